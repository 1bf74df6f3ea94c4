// The --log writer: pLogger's .alog header and one line per accepted NOTIFY.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "alog_writer.hpp"
#include "moos/alog.hpp"
#include "scratch_files.hpp"
#include "wire_messages.hpp"

namespace moosdb_lite {
namespace {

using namespace moos::test;

std::vector<std::string> read_lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(AlogValue, DoublesUseTheShortestExactText) {
  EXPECT_EQ(moos::alog_value(notify_double("X", 12.5, "p")), "12.5");
  EXPECT_EQ(moos::alog_value(notify_double("X", 0.1, "p")), "0.1");
  EXPECT_EQ(moos::alog_value(notify_double("X", -3, "p")), "-3");
  EXPECT_EQ(moos::alog_value(notify_double("X", 1700000000.125, "p")), "1700000000.125");
  const double third = 1.0 / 3.0;
  EXPECT_EQ(std::stod(moos::alog_value(notify_double("X", third, "p"))), third);
}

TEST(AlogValue, StringsAsTheyAreAndBinaryAsHex) {
  EXPECT_EQ(moos::alog_value(notify_string("X", "a b,c=d", "p")), "a b,c=d");
  EXPECT_EQ(moos::alog_value(moos::make_binary_notify("B", std::string("\0\xff\x10\x7f", 4), "p", kT0)),
            "<binary:4:00ff107f>");
}

TEST(AlogWriter, WritesHeaderAndOneLinePerMessageRelativeToLogstart) {
  const test_support::ScratchDir dir;
  const std::string path = (dir / "writer.alog").string();
  {
    AlogWriter writer;
    std::string error;
    ASSERT_TRUE(writer.open(path, kT0, nullptr, &error, [] { return kT0; })) << error;
    writer.write(notify_double("NAV_X", 12.5, "pSim", kT0 + 1.25));
    writer.write(notify_string("MODE", "SURVEY now", "pHelm", kT0 + 2.5));
    writer.flush();
  }
  const auto lines = read_lines(path);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(moos::alog_logstart(lines[1]), kT0);
  const auto first = moos::parse_alog_line(lines[3]);
  ASSERT_EQ(first.kind, moos::AlogLineKind::kEntry);
  EXPECT_EQ(first.entry.time_s, 1.25);
  EXPECT_EQ(first.entry.variable, "NAV_X");
  EXPECT_EQ(first.entry.source, "pSim");
  EXPECT_EQ(first.entry.value, "12.5");
  const auto second = moos::parse_alog_line(lines[4]);
  EXPECT_EQ(second.entry.value, "SURVEY now");
}

TEST(AlogWriter, UnwritableFileIsAnErrorNamingIt) {
  AlogWriter writer;
  std::string error;
  EXPECT_FALSE(writer.open("/nonexistent-dir/x.alog", kT0, nullptr, &error));
  EXPECT_NE(error.find("/nonexistent-dir/x.alog"), std::string::npos);
}

}  // namespace
}  // namespace moosdb_lite
