// Bounded reading of input files (issue 12, "Special files"): only regular files, never more
// than the bound, never blocking on a FIFO.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "base/file.hpp"

namespace base {
namespace {

class ReadRegularFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("base_file_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& bytes) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  std::filesystem::path dir_;
};

TEST_F(ReadRegularFile, ReadsTheWholeFileByteForByte) {
  const std::string bytes = std::string("a\0b\r\nc", 6) + std::string(100000, 'x');
  const FileText read = read_regular_file(write("f.txt", bytes));
  ASSERT_TRUE(read.text.has_value()) << read.problem;
  EXPECT_EQ(*read.text, bytes);
  EXPECT_EQ(read.problem, "");
}

TEST_F(ReadRegularFile, AnEmptyFileIsEmptyText) {
  const FileText read = read_regular_file(write("empty.txt", ""));
  ASSERT_TRUE(read.text.has_value());
  EXPECT_EQ(*read.text, "");
}

TEST_F(ReadRegularFile, AMissingFileSaysWhy) {
  const FileText read = read_regular_file((dir_ / "nope").string());
  EXPECT_FALSE(read.text.has_value());
  EXPECT_EQ(read.problem, "cannot be opened: No such file or directory");
}

TEST_F(ReadRegularFile, ADirectoryIsRefused_Issue12) {
  const FileText read = read_regular_file(dir_.string());
  EXPECT_FALSE(read.text.has_value());
  EXPECT_EQ(read.problem, "is a directory");
}

TEST_F(ReadRegularFile, AFifoWithoutWriterIsRefusedAtOnce_Issue12) {
  const std::string fifo = (dir_ / "fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const FileText read = read_regular_file(fifo);  // would block forever without O_NONBLOCK
  EXPECT_FALSE(read.text.has_value());
  EXPECT_EQ(read.problem, "is a FIFO, not a regular file");
}

TEST_F(ReadRegularFile, ADeviceIsRefusedNotReadUntilMemoryRunsOut_Issue12) {
  const FileText read = read_regular_file("/dev/zero");
  EXPECT_FALSE(read.text.has_value());
  EXPECT_EQ(read.problem, "is a device, not a regular file");
}

TEST_F(ReadRegularFile, AFileOverTheBoundIsRefusedWithTheBound) {
  const std::string path = write("big.txt", std::string(1001, 'x'));
  const FileText read = read_regular_file(path, 1000);
  EXPECT_FALSE(read.text.has_value());
  EXPECT_EQ(read.problem, "is larger than 1000 bytes");
  EXPECT_TRUE(read_regular_file(path, 1001).text.has_value());
}

}  // namespace
}  // namespace base
