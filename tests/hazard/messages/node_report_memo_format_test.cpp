// NodeReportMemo::format keeps the parse of the text it writes, built from the writing instead
// of read back: the text must be format_node_report's, and the kept parse must be what
// parse_node_report gives for that text, bit for bit, on reports near and off the usual ones.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <string>

#include "hazard/messages/node_report.hpp"

namespace hazard {
namespace {

std::uint64_t bits(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

std::optional<std::uint64_t> bits(std::optional<double> v) {
  if (!v) return std::nullopt;
  return bits(*v);
}

void expect_same_parse(const Parsed<NodeReport>& got, const Parsed<NodeReport>& want,
                       const std::string& text) {
  ASSERT_EQ(got.error, want.error) << text;
  ASSERT_EQ(got.value.has_value(), want.value.has_value()) << text;
  if (!want.value) return;
  const NodeReport& g = *got.value;
  const NodeReport& w = *want.value;
  EXPECT_EQ(g.name, w.name) << text;
  EXPECT_EQ(bits(g.x_m), bits(w.x_m)) << text;
  EXPECT_EQ(bits(g.y_m), bits(w.y_m)) << text;
  EXPECT_EQ(bits(g.speed_mps), bits(w.speed_mps)) << text;
  EXPECT_EQ(bits(g.heading_deg), bits(w.heading_deg)) << text;
  EXPECT_EQ(bits(g.lat_deg), bits(w.lat_deg)) << text;
  EXPECT_EQ(bits(g.lon_deg), bits(w.lon_deg)) << text;
  EXPECT_EQ(bits(g.time_s), bits(w.time_s)) << text;
  EXPECT_EQ(g.type, w.type) << text;
  EXPECT_EQ(g.placed_from_lat_lon, w.placed_from_lat_lon) << text;
}

double number(std::mt19937_64& rng) {
  switch (rng() % 10) {
    case 0:
      return std::ldexp(static_cast<double>(rng() % 1000) - 500, static_cast<int>(rng() % 120) - 60);
    case 1: {  // on and near the 2 and 8 decimals the text has, ties included
      const double steps[] = {0.005, 0.125, 0.5, 0.00000001, 0.000000005};
      return static_cast<double>(static_cast<std::int64_t>(rng() % 200001) - 100000) *
             steps[rng() % 5];
    }
    case 2: {
      const double odd[] = {0.0, -0.0, 1e15, -9e15, 1e300, 5e-324, -1e-3,
                            std::numeric_limits<double>::infinity(),
                            std::numeric_limits<double>::quiet_NaN(), 1e8, 100000000.5};
      return odd[rng() % 11];
    }
    default: {
      std::uniform_real_distribution<double> d(-20000.0, 20000.0);
      return d(rng);
    }
  }
}

// Names and types on and off the rules the writing checks itself: blanks the trim takes at
// either end, control bytes, the bytes that end or hold open a piece, names at and past
// kMaxVehicleNameBytes (128).
std::string text_value(std::mt19937_64& rng) {
  const char* values[] = {"archie", "betty", "", " b", "b ", "a,b", "{a}", "a}", "a=b",
                          "x\ty", "UUV", "kayak", "\x7f", "X=1", "1.5", "long-name_2",
                          "\tb", "b\r", "\nb", "b\x1f"};
  const std::size_t pick = rng() % 22;
  if (pick == 20) return std::string(128, 'n');
  if (pick == 21) return std::string(129, 'n');
  return values[pick];
}

NodeReport generated_report(std::mt19937_64& rng) {
  NodeReport r;
  r.name = rng() % 4 == 0 ? text_value(rng) : "archie";
  r.x_m = number(rng);
  r.y_m = number(rng);
  r.speed_mps = rng() % 3 == 0 ? number(rng) : std::fabs(number(rng)) / 1000.0;
  r.heading_deg = number(rng);
  if (rng() % 4 != 0) r.lat_deg = number(rng) / 1000.0;
  if (rng() % 4 != 0) r.lon_deg = number(rng) / 1000.0;
  if (rng() % 4 != 0) r.time_s = rng() % 2 ? 1700000000.0 + number(rng) : number(rng);
  if (rng() % 3 != 0) r.type = text_value(rng);
  return r;
}

TEST(NodeReportMemoFormat, KeepsWhatTheParseOfItsTextGives) {
  std::mt19937_64 rng(20261128);
  NodeReportMemo memo;
  int kept = 0;
  for (int i = 0; i < 100000; ++i) {
    const NodeReport r = generated_report(rng);
    const std::string text = memo.format(r);
    ASSERT_EQ(text, format_node_report(r));
    const std::size_t read_before = memo.texts_read();
    expect_same_parse(memo.parse(text, nullptr), parse_node_report(text), text);
    if (HasFailure()) return;
    kept += memo.texts_read() == read_before ? 1 : 0;
  }
  EXPECT_GT(kept, 10000);  // most reports are kept from the writing, not read back
}

// TIME's whole seconds are kept from one report to the next (the digits of a ten-digit time
// stamp): reports a tenth of a second apart, across whole seconds, from two vehicles, and
// times that leave the kept digits (short, negative, past 2^53 units) and come back.
TEST(NodeReportMemoFormat, TimeStampsThatShareTheirWholeSecondsAreWrittenAsAlone) {
  NodeReportMemo memo;
  NodeReport r;
  r.x_m = 10.0;
  r.y_m = -5.0;
  r.speed_mps = 1.5;
  r.heading_deg = 90.0;
  r.type = "UUV";
  const double odd[] = {12.5, -1700000001.25, 99999.999, 1e13, 1700000000.0};
  for (int i = 0; i < 400; ++i) {
    r.name = i % 2 == 0 ? "archie" : "betty";
    r.time_s = i % 37 == 0 ? odd[(i / 37) % 5] : 1699999998.0 + 0.1 * i;
    const std::string text = memo.format(r);
    ASSERT_EQ(text, format_node_report(r));
    expect_same_parse(memo.parse(text, nullptr), parse_node_report(text), text);
    if (HasFailure()) return;
  }
}

TEST(NodeReportMemoFormat, AUsualReportIsKeptFromTheWritingAndAnOddOneIsRead) {
  NodeReportMemo memo;
  NodeReport r;
  r.name = "archie";
  r.x_m = -145.0;
  r.y_m = -388.53;
  r.speed_mps = 1.5;
  r.heading_deg = 180.0;
  r.lat_deg = 43.82180313;
  r.lon_deg = -70.33220245;
  r.time_s = 1700000250.0;
  r.type = "UUV";
  const std::string text = memo.format(r);
  EXPECT_EQ(text,
            "NAME=archie,X=-145,Y=-388.53,SPD=1.5,HDG=180,LAT=43.82180313,LON=-70.33220245,"
            "TIME=1700000250,TYPE=UUV");
  const Parsed<NodeReport>& kept = memo.parse(text, nullptr);
  EXPECT_EQ(memo.texts_read(), 0U);
  expect_same_parse(kept, parse_node_report(text), text);
  // A name the scan would cut at its ',' is read back as it arrives.
  r.name = "a,b";
  const std::string odd = memo.format(r);
  expect_same_parse(memo.parse(odd, nullptr), parse_node_report(odd), odd);
  EXPECT_EQ(memo.texts_read(), 1U);
}

// The reports the direct writing leaves to the general one (a TYPE over 64 bytes, a number
// past 2^53 units) and one it writes but must not keep (X beyond kMaxNodeCoordinate_m): the
// text is format_node_report's, and the parse is what reading it gives.
TEST(NodeReportMemoFormat, ReportsOffTheDirectWritingKeepTheSameTextAndParse) {
  NodeReportMemo memo;
  NodeReport r;
  r.name = "betty";
  r.x_m = 12.345;
  r.y_m = -0.004;
  r.speed_mps = 2.0;
  r.heading_deg = 359.999;
  r.time_s = 1700000024.75;
  r.type = std::string(65, 't');
  std::string text = memo.format(r);
  EXPECT_EQ(text, "NAME=betty,X=12.35,Y=0,SPD=2,HDG=360,TIME=1700000024.75,TYPE=" +
                      std::string(65, 't'));
  expect_same_parse(memo.parse(text, nullptr), parse_node_report(text), text);
  EXPECT_EQ(memo.texts_read(), 0U);  // kept through the general writing
  r.type = "";
  text = memo.format(r);
  EXPECT_EQ(text, "NAME=betty,X=12.35,Y=0,SPD=2,HDG=360,TIME=1700000024.75,TYPE=");
  expect_same_parse(memo.parse(text, nullptr), parse_node_report(text), text);
  EXPECT_EQ(memo.texts_read(), 0U);  // kept from the direct writing, no type
  r.time_s = 1e16;  // past the fast path: written by append_fmt
  text = memo.format(r);
  EXPECT_EQ(text, format_node_report(r));
  expect_same_parse(memo.parse(text, nullptr), parse_node_report(text), text);
  EXPECT_EQ(memo.texts_read(), 1U);
  r.time_s.reset();
  r.x_m = 2e8;  // beyond kMaxNodeCoordinate_m: written, not kept, refused when read
  text = memo.format(r);
  EXPECT_EQ(text, "NAME=betty,X=200000000,Y=0,SPD=2,HDG=360,TYPE=");
  const Parsed<NodeReport>& refused = memo.parse(text, nullptr);
  EXPECT_FALSE(refused.value.has_value());
  expect_same_parse(refused, parse_node_report(text), text);
  EXPECT_EQ(memo.texts_read(), 2U);
}

// An entry kept from a parse (not from the direct writing) vouches for nothing: a report with
// its name, which the direct writing refuses ('{'), is written the general way and read back.
TEST(NodeReportMemoFormat, AnEntryKeptFromAParseDoesNotVouchForTheNameItHolds) {
  NodeReportMemo memo;
  NodeReport r;
  r.name = "archie";
  for (int i = 0; i < 4; ++i) {  // every entry kept by the direct writing
    r.x_m = i;
    memo.format(r);
  }
  // The next four entries kept from parses; the first has the name "{x}".
  for (int i = 0; i < 4; ++i) {
    const std::string name = i == 0 ? "{x}" : "p" + std::to_string(i);
    ASSERT_TRUE(memo.parse("NAME=" + name + ",X=1,Y=2,SPD=1,HDG=0", nullptr).value);
  }
  EXPECT_EQ(memo.texts_read(), 4U);
  r.name = "{x}";
  r.x_m = 3.0;  // (not the parsed text, which the memo would find)
  r.y_m = 2.0;
  r.speed_mps = 1.0;
  r.heading_deg = 0.0;
  const std::string text = memo.format(r);  // replaces the "{x}" entry's place
  EXPECT_EQ(text, "NAME={x},X=3,Y=2,SPD=1,HDG=0");
  expect_same_parse(memo.parse(text, nullptr), parse_node_report(text), text);
  EXPECT_EQ(memo.texts_read(), 5U);  // not kept from the writing: read when it arrives
}

}  // namespace
}  // namespace hazard
