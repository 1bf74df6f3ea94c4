// Writing a user-named output (base/output_file.hpp): a regular file replaced atomically, a
// device or FIFO written through, a link followed and kept, a directory refused.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "base/file.hpp"
#include "base/output_file.hpp"
#include "output_targets.hpp"

namespace base {
namespace {

namespace fs = std::filesystem;
using test_support::kind_at;
using test_support::read_all;
using test_support::WriteEnd;

const std::string kText = std::string(200000, 'x') + "\n";  // more than one buffer or write()

class OutputFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string name = (fs::temp_directory_path() / "output_file_XXXXXX").string();
    ASSERT_NE(::mkdtemp(name.data()), nullptr);
    dir_ = name;
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// write_output_file as a program would use it: 0, or 1 with the problem.
  static WriteEnd replace(const std::string& path) {
    const Result<void> written = write_output_file(path, kText);
    return {written ? 0 : 1, written.error};
  }
  /// A log's way: opened in place, written a line at a time, committed.
  static WriteEnd in_place(const std::string& path) {
    auto file = OutputFile::open(path, OutputMode::kInPlace);
    if (!file) return {1, file.error};
    Result<void> done = Result<void>::ok();
    for (std::size_t at = 0; done && at < kText.size(); at += 1000)
      done = file.value->write(std::string_view(kText).substr(at, 1000));
    if (done) done = file.value->commit();
    return {done ? 0 : 1, done.error};
  }
  static void is_the_text(const std::string& bytes) { EXPECT_EQ(bytes, kText); }

  fs::path dir_;
};

TEST_F(OutputFileTest, ANullDeviceStaysACharacterDevice) {
  test_support::check_null_device(dir_, "null", replace);
  test_support::check_null_device(dir_, "null_log", in_place);
}

TEST_F(OutputFileTest, AFullDeviceIsAnErrorNamingThePath) {
  test_support::check_full_device(dir_, "full", replace);
  test_support::check_full_device(dir_, "full_log", in_place);
}

TEST_F(OutputFileTest, AFifoWithAReaderGetsTheBytes) {
  test_support::check_fifo_with_reader(dir_, "fifo", replace, is_the_text);
  test_support::check_fifo_with_reader(dir_, "fifo_log", in_place, is_the_text);
}

TEST_F(OutputFileTest, AFifoWithoutAReaderIsAnErrorAfterTheWait) {
  test_support::check_fifo_without_reader(dir_, "fifo", replace);
}

TEST_F(OutputFileTest, ASymlinkStaysALinkAndTheFileItNamesGetsTheBytes) {
  test_support::check_symlink(dir_, "out", replace, is_the_text);
  test_support::check_symlink(dir_, "log", in_place, is_the_text);
}

TEST_F(OutputFileTest, ARegularFileIsReplacedByARename) {
  test_support::check_regular_file(dir_, "out", replace, is_the_text);
  test_support::check_regular_file(dir_, "log", in_place, is_the_text,
                                   test_support::Regular::kInPlace);
}

TEST_F(OutputFileTest, ADirectoryIsRefusedNamingIt) {
  test_support::check_directory(dir_, "folder", replace);
  test_support::check_directory(dir_, "folder_log", in_place);
}

TEST_F(OutputFileTest, AReaderNeverSeesAHalfFile) {
  const std::string path = (dir_ / "out").string();
  const std::string a(300000, 'a');
  const std::string b(100000, 'b');
  ASSERT_EQ(write_output_file(path, a).error, "");
  std::atomic<bool> done{false};
  std::thread writer([&] {
    for (int i = 0; i < 100; ++i) EXPECT_EQ(write_output_file(path, i % 2 ? a : b).error, "");
    done = true;
  });
  int reads = 0;
  while (!done) {
    const Result<std::string> read = read_file_text(path);
    ASSERT_TRUE(read) << read.error;
    ASSERT_TRUE(*read.value == a || *read.value == b) << "a read of " << read.value->size() << " bytes";
    ++reads;
  }
  writer.join();
  EXPECT_GT(reads, 0);
}

TEST_F(OutputFileTest, WithoutCommitTheTargetStaysAsItWasAndNoTemporaryIsLeft) {
  const fs::path path = dir_ / "out";
  std::ofstream(path) << "old\n";
  {
    auto file = OutputFile::open(path.string(), OutputMode::kReplace);
    ASSERT_TRUE(file) << file.error;
    ASSERT_TRUE(file.value->write(kText));
  }
  EXPECT_EQ(read_all(path), "old\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(OutputFileTest, AReplacedFileKeepsItsPermissionsAndANewOneGetsTheUsualOnes) {
  const fs::path kept = dir_ / "kept";
  std::ofstream(kept) << "old\n";
  ASSERT_EQ(::chmod(kept.c_str(), 0640), 0);
  ASSERT_EQ(write_output_file(kept.string(), "new\n").error, "");
  struct stat info {};
  ASSERT_EQ(::stat(kept.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0640u);

  const mode_t old_mask = ::umask(022);
  const fs::path fresh = dir_ / "fresh";
  EXPECT_EQ(write_output_file(fresh.string(), "x\n").error, "");
  ::umask(old_mask);
  ASSERT_EQ(::stat(fresh.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0644u);
}

TEST_F(OutputFileTest, ALinkToNothingYetCreatesItsTargetAndALinkChainIsFollowed) {
  fs::create_symlink(dir_ / "made", dir_ / "dangling");
  fs::create_symlink("dangling", dir_ / "chain");
  ASSERT_EQ(write_output_file((dir_ / "chain").string(), "x\n").error, "");
  EXPECT_EQ(kind_at(dir_ / "chain"), S_IFLNK);
  EXPECT_EQ(kind_at(dir_ / "dangling"), S_IFLNK);
  EXPECT_EQ(read_all(dir_ / "made"), "x\n");
}

TEST_F(OutputFileTest, ALinkLoopAndAMissingFolderAreErrorsNamingThePath) {
  fs::create_symlink("loop_b", dir_ / "loop_a");
  fs::create_symlink("loop_a", dir_ / "loop_b");
  const std::string loop = (dir_ / "loop_a").string();
  const std::string problem = write_output_file(loop, "x\n").error;
  ASSERT_FALSE(problem.empty());
  EXPECT_NE(problem.find("'" + loop + "'"), std::string::npos) << problem;
  EXPECT_NE(problem.find("Too many levels of symbolic links"), std::string::npos) << problem;

  const std::string missing = (dir_ / "no_such_folder" / "out").string();
  EXPECT_EQ(write_output_file(missing, "x\n").error,
            "cannot write '" + missing + "': No such file or directory");
}

TEST_F(OutputFileTest, ASocketIsRefused) {
  const std::string socket_path = (dir_ / "sock").string();
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  ASSERT_LT(socket_path.size(), sizeof address.sun_path);
  socket_path.copy(address.sun_path, socket_path.size());
  const bool bound = ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
  ::close(fd);  // (the socket file stays)
  if (!bound) GTEST_SKIP() << "no socket file can be made here";
  const std::string problem = write_output_file(socket_path, "x\n").error;
  ASSERT_FALSE(problem.empty());
  EXPECT_NE(problem.find("it is a socket"), std::string::npos) << problem;
  EXPECT_EQ(kind_at(socket_path), S_IFSOCK);
}

}  // namespace
}  // namespace base
