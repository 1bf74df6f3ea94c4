// Bounded reading of input files ("Special files"): only regular files, never more
// than the bound, never blocking on a FIFO. WholeFile: a regular file mapped, a pipe
// read to its end, the rest refused.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "base/file.hpp"
#include "fifo_writer.hpp"

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
  const Result<std::string> read = read_file_text(write("f.txt", bytes));
  ASSERT_TRUE(read.value.has_value()) << read.error;
  EXPECT_EQ(*read.value, bytes);
  EXPECT_EQ(read.error, "");
}

TEST_F(ReadRegularFile, AnEmptyFileIsEmptyText) {
  const Result<std::string> read = read_file_text(write("empty.txt", ""));
  ASSERT_TRUE(read.value.has_value());
  EXPECT_EQ(*read.value, "");
}

TEST_F(ReadRegularFile, AMissingFileSaysWhy) {
  const Result<std::string> read = read_file_text((dir_ / "nope").string());
  EXPECT_FALSE(read.value.has_value());
  EXPECT_EQ(read.error, "cannot be opened: No such file or directory");
}

TEST_F(ReadRegularFile, ADirectoryIsRefused_Hardening) {
  const Result<std::string> read = read_file_text(dir_.string());
  EXPECT_FALSE(read.value.has_value());
  EXPECT_EQ(read.error, "is a directory");
}

TEST_F(ReadRegularFile, AFifoWithoutWriterIsRefusedAtOnce_Hardening) {
  const std::string fifo = (dir_ / "fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const Result<std::string> read = read_file_text(fifo);  // would block forever without O_NONBLOCK
  EXPECT_FALSE(read.value.has_value());
  EXPECT_EQ(read.error, "is a FIFO, not a regular file");
}

TEST_F(ReadRegularFile, ADeviceIsRefusedNotReadUntilMemoryRunsOut_Hardening) {
  const Result<std::string> read = read_file_text("/dev/zero");
  EXPECT_FALSE(read.value.has_value());
  EXPECT_EQ(read.error, "is a device, not a regular file");
}

TEST_F(ReadRegularFile, AFileOverTheBoundIsRefusedWithTheBound) {
  const std::string path = write("big.txt", std::string(1001, 'x'));
  const Result<std::string> read = read_file_text(path, 1000);
  EXPECT_FALSE(read.value.has_value());
  EXPECT_EQ(read.error, "is larger than 1000 bytes");
  EXPECT_TRUE(read_file_text(path, 1001).value.has_value());
}

using WholeFileTest = ReadRegularFile;  // the same scratch folder

std::optional<WholeFile> open_whole(const std::string& path, std::size_t max_bytes,
                                    std::string& problem) {
  Result<WholeFile> whole = WholeFile::open(path, max_bytes);
  problem = whole.error;
  return std::move(whole.value);
}

TEST_F(WholeFileTest, MapsARegularFileByteForByte) {
  const std::string bytes = std::string("a\0b\r\nc", 6) + std::string(300000, 'x') + "end";
  std::string problem;
  const auto file = open_whole(write("f.alog", bytes), bytes.size(), problem);
  ASSERT_TRUE(file.has_value()) << problem;
  EXPECT_TRUE(file->mapped());
  EXPECT_EQ(file->text(), bytes);
}

TEST_F(WholeFileTest, ItsBytesStayPutWhenItIsMoved) {
  for (const std::string& bytes : {std::string("short"), std::string(5000, 'y')}) {
    const std::string fifo = (dir_ / "moved").string();
    std::string problem;
    auto mapped = open_whole(write("m.alog", bytes), 1 << 20, problem);
    ASSERT_TRUE(mapped.has_value()) << problem;
    const char* const at = mapped->text().data();
    const WholeFile moved(std::move(*mapped));
    EXPECT_EQ(moved.text().data(), at);
    EXPECT_EQ(moved.text(), bytes);
    EXPECT_TRUE(mapped->text().empty());  // the moved-from object no longer owns the bytes

    // Read (not mapped) bytes too: a short text must not move with a small-string buffer.
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    bool fed = false;
    std::thread writer([&] { fed = test_support::write_fifo(fifo, bytes); });
    auto piped = open_whole(fifo, 1 << 20, problem);
    writer.join();
    EXPECT_TRUE(fed);
    std::filesystem::remove(fifo);
    ASSERT_TRUE(piped.has_value()) << problem;
    const char* const read_at = piped->text().data();
    WholeFile assigned = std::move(*mapped);  // an empty one, then given the read bytes
    assigned = std::move(*piped);
    EXPECT_FALSE(assigned.mapped());
    EXPECT_EQ(assigned.text().data(), read_at);
    EXPECT_EQ(assigned.text(), bytes);
  }
}

TEST_F(WholeFileTest, AnEmptyFileIsEmptyText) {
  std::string problem;
  const auto file = open_whole(write("empty.alog", ""), 100, problem);
  ASSERT_TRUE(file.has_value()) << problem;
  EXPECT_EQ(file->text(), "");
}

TEST_F(WholeFileTest, AFileThatSaysItIsEmptyIsStillRead) {
  std::string problem;
  const auto file = open_whole("/proc/self/status", 1 << 20, problem);  // st_size is 0
  ASSERT_TRUE(file.has_value()) << problem;
  EXPECT_FALSE(file->mapped());
  EXPECT_NE(file->text().find("Name:"), std::string_view::npos) << file->text();
}

TEST_F(WholeFileTest, APipeIsReadToItsEnd) {
  const std::string fifo = (dir_ / "pipe").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string bytes(3 * 1024 * 1024 + 7, 'p');  // more than one block
  bool fed = false;
  std::thread writer([&] { fed = test_support::write_fifo(fifo, bytes); });
  std::string problem;
  const auto file = open_whole(fifo, bytes.size(), problem);
  writer.join();
  EXPECT_TRUE(fed);
  ASSERT_TRUE(file.has_value()) << problem;
  EXPECT_FALSE(file->mapped());
  EXPECT_EQ(file->text(), bytes);
}

TEST_F(WholeFileTest, MoreThanTheBoundIsRefusedWithTheBound) {
  std::string problem;
  const std::string path = write("big.alog", std::string(1001, 'x'));
  EXPECT_FALSE(open_whole(path, 1000, problem).has_value());
  EXPECT_EQ(problem, "is larger than 1000 bytes");
  EXPECT_TRUE(open_whole(path, 1001, problem).has_value());

  const std::string fifo = (dir_ / "big_pipe").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // (Whether the writer gets every byte in before the reader gives up is not fixed.)
  std::thread writer([&] { test_support::write_fifo(fifo, std::string(1001, 'x')); });
  problem.clear();
  EXPECT_FALSE(open_whole(fifo, 1000, problem).has_value());
  writer.join();
  EXPECT_EQ(problem, "is larger than 1000 bytes");
}

TEST_F(WholeFileTest, DirectoriesDevicesAndMissingFilesAreRefusedWithAReason) {
  std::string problem;
  EXPECT_FALSE(open_whole(dir_.string(), 100, problem).has_value());
  EXPECT_EQ(problem, "is a directory");
  EXPECT_FALSE(open_whole("/dev/zero", 100, problem).has_value());
  EXPECT_EQ(problem, "is a device, not a regular file");
  EXPECT_FALSE(open_whole((dir_ / "nope").string(), 100, problem).has_value());
  EXPECT_EQ(problem, "cannot be opened: No such file or directory");
}

}  // namespace
}  // namespace base
