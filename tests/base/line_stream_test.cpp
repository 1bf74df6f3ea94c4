// base::LineStream: lines as std::getline splits them, a line over the bound read past and
// counted (also one that spans many reads), a FIFO read as a file is, a device refused.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "base/line_stream.hpp"
#include "fifo_writer.hpp"

namespace base {
namespace {

class LineStreamTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("base_line_stream_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string write(const std::string& bytes) {
    const std::string path = (dir_ / "f.txt").string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  // Every line of the file at `path` with its number, read with `max` as the bound.
  static std::vector<std::pair<std::size_t, std::string>> lines_of(const std::string& path,
                                                                   std::size_t max,
                                                                   std::size_t* long_lines) {
    Result<LineStream> opened = LineStream::open(path, max);
    EXPECT_TRUE(opened) << opened.error;
    std::vector<std::pair<std::size_t, std::string>> out;
    if (!opened) return out;
    LineStream& stream = *opened.value;
    while (const auto line = stream.next()) out.emplace_back(stream.line_number(), *line);
    if (long_lines) *long_lines = stream.long_lines();
    return out;
  }

  std::filesystem::path dir_;
};

using Lines = std::vector<std::pair<std::size_t, std::string>>;

TEST_F(LineStreamTest, SplitsAtNewlinesAndKeepsALastLineWithoutOne) {
  std::size_t long_lines = 9;
  EXPECT_EQ(lines_of(write("a\n\nb c\r\nlast"), 100, &long_lines),
            (Lines{{1, "a"}, {2, ""}, {3, "b c\r"}, {4, "last"}}));
  EXPECT_EQ(long_lines, 0u);
  EXPECT_EQ(lines_of(write(""), 100, nullptr), Lines{});
}

// Lines over the bound, in one read and across many (a 256 KB block), are skipped and counted;
// the numbers of the lines after them stay right.
TEST_F(LineStreamTest, ALineOverTheBoundIsReadPastAndCounted) {
  const std::string huge(3 * 1024 * 1024, 'k');
  const std::string spanning(600 * 1024, 's');  // within a bound of 1 MiB, across reads
  std::size_t long_lines = 0;
  const Lines got =
      lines_of(write("a\n" + std::string(20, 'x') + "\n" + huge + "\n" + spanning + "\nb\n" + huge),
               1024 * 1024, &long_lines);
  EXPECT_EQ(long_lines, 2u);
  ASSERT_EQ(got.size(), 4u);
  EXPECT_EQ(got[0], (std::pair<std::size_t, std::string>{1, "a"}));
  EXPECT_EQ(got[2].first, 4u);
  EXPECT_EQ(got[2].second, spanning);
  EXPECT_EQ(got[3], (std::pair<std::size_t, std::string>{5, "b"}));
  EXPECT_EQ(lines_of(write("12345\n123456\n1234567"), 6, &long_lines),
            (Lines{{1, "12345"}, {2, "123456"}}));
  EXPECT_EQ(long_lines, 1u);
}

TEST_F(LineStreamTest, AFifoIsReadAsAFileIs) {
  const std::string fifo = (dir_ / "pipe").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  bool fed = false;
  std::thread writer([&] { fed = test_support::write_fifo(fifo, "one\ntwo\n"); });
  const Lines got = lines_of(fifo, 100, nullptr);
  writer.join();
  EXPECT_TRUE(fed);
  EXPECT_EQ(got, (Lines{{1, "one"}, {2, "two"}}));
}

TEST_F(LineStreamTest, ADeviceOrFolderIsRefusedWithTheReason) {
  EXPECT_EQ(LineStream::open("/dev/zero", 100).error, "is a device, not a regular file");
  EXPECT_EQ(LineStream::open(dir_.string(), 100).error, "is a directory");
  const Result<LineStream> missing = LineStream::open((dir_ / "missing").string(), 100);
  EXPECT_FALSE(missing);
  EXPECT_NE(missing.error.find("cannot be opened"), std::string::npos);
}

}  // namespace
}  // namespace base
