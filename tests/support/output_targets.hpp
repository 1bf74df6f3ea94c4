#pragma once
// Outputs a user may name that are not regular files, and the checks that a program (or a
// writer function) treats each by the rule of include/base/output_file.hpp.
//
// Contract:
// - make_device makes a character device like /dev/null or /dev/full inside the test's scratch
//   folder (mknod, allowed to root), so that a program that wrongly renames over its output
//   replaces the test's node and never the machine's /dev/null (the tests run as root in CI).
//   Without the right to mknod (or on a nodev file system) it gives the machine's device when
//   the test is not root (who cannot replace it), else nullopt: the test is then skipped.
// - read_fifo reads a FIFO from a thread of the test until its writer has come and gone, or
//   until `wait_s` has passed: never a hang.
// - check_output_targets runs `write` once per kind of output (a character device, a full
//   device, a FIFO with and without a reader, a symlink, a regular file, a directory) and
//   expects the rule's outcome; `write` runs the program (or function) so that it writes to the
//   path given and says how it ended. Header-only, so that base's tests need no library of ours.

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <optional>
#include <sstream>
#include <string>

namespace test_support {

/// Two character devices of Linux (major 1): the sink and the always-full device.
enum class Device { kNull = 3, kFull = 7 };

inline std::optional<std::string> make_device(const std::filesystem::path& path, Device which) {
  const dev_t number = makedev(1, static_cast<unsigned>(which));
  if (::mknod(path.c_str(), S_IFCHR | 0666, number) == 0) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd >= 0) {
      ::close(fd);
      return path.string();
    }
    ::unlink(path.c_str());
  }
  if (::geteuid() == 0) return std::nullopt;
  return which == Device::kNull ? "/dev/null" : "/dev/full";
}

inline bool make_fifo(const std::filesystem::path& path) { return ::mkfifo(path.c_str(), 0600) == 0; }

/// The file type bits of `path` itself (not of what a link leads to); 0 when it is missing.
inline mode_t kind_at(const std::filesystem::path& path) {
  struct stat info {};
  return ::lstat(path.c_str(), &info) == 0 ? (info.st_mode & S_IFMT) : 0;
}

inline ino_t inode_at(const std::filesystem::path& path) {
  struct stat info {};
  return ::lstat(path.c_str(), &info) == 0 ? info.st_ino : 0;
}

/// Everything written into the FIFO at `path` by its writers, once one has come and gone (or
/// what arrived within `wait_s`). Opened non-blocking: it never waits for a writer to open.
inline std::string read_fifo(const std::string& path, double wait_s) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return "<cannot open the FIFO>";
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_s);
  std::string got;
  char block[65536];
  while (std::chrono::steady_clock::now() < give_up) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 50) <= 0) continue;
    const ssize_t n = ::read(fd, block, sizeof block);
    if (n > 0) {
      got.append(block, static_cast<std::size_t>(n));
    } else if (n == 0 && (p.revents & POLLHUP)) {
      break;  // (Linux: POLLHUP only once a writer has come and gone)
    }
  }
  ::close(fd);
  return got;
}

/// How a write to an output ended: the program's exit code (nullopt: killed or timed out) and
/// its standard error (or the writer function's problem).
struct WriteEnd {
  std::optional<int> exit_code;
  std::string err;
};
using WriteTo = std::function<WriteEnd(const std::string& path)>;
/// Checks what arrived at an output (a regular file's content, or what a FIFO's reader read).
using CheckBytes = std::function<void(const std::string& bytes)>;

inline std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void check_null_device(const std::filesystem::path& dir, const std::string& name,
                              const WriteTo& write) {
  const auto device = make_device(dir / name, Device::kNull);
  if (!device) GTEST_SKIP() << "no device node can be made here (mknod)";
  const WriteEnd end = write(*device);
  EXPECT_EQ(end.exit_code, 0) << end.err;
  EXPECT_EQ(kind_at(*device), S_IFCHR) << *device << " is no longer a character device";
}

inline void check_full_device(const std::filesystem::path& dir, const std::string& name,
                              const WriteTo& write) {
  const auto device = make_device(dir / name, Device::kFull);
  if (!device) GTEST_SKIP() << "no device node can be made here (mknod)";
  const WriteEnd end = write(*device);
  EXPECT_NE(end.exit_code, 0) << "a write to a full device must fail";
  EXPECT_NE(end.exit_code, std::nullopt) << "killed or timed out";
  EXPECT_NE(end.err.find(*device), std::string::npos) << end.err;
  EXPECT_NE(end.err.find("No space left on device"), std::string::npos) << end.err;
  EXPECT_EQ(kind_at(*device), S_IFCHR);
}

inline void check_fifo_with_reader(const std::filesystem::path& dir, const std::string& name,
                                   const WriteTo& write, const CheckBytes& check) {
  const std::string fifo = (dir / name).string();
  ASSERT_TRUE(make_fifo(fifo));
  auto reader = std::async(std::launch::async, [&fifo] { return read_fifo(fifo, 60.0); });
  const WriteEnd end = write(fifo);
  const std::string bytes = reader.get();
  EXPECT_EQ(end.exit_code, 0) << end.err;
  check(bytes);
  EXPECT_EQ(kind_at(fifo), S_IFIFO);
}

/// No reader: a clear error after the bounded wait (kFifoReaderWait_s, 5 s), never a hang.
inline void check_fifo_without_reader(const std::filesystem::path& dir, const std::string& name,
                                      const WriteTo& write) {
  const std::string fifo = (dir / name).string();
  ASSERT_TRUE(make_fifo(fifo));
  const auto start = std::chrono::steady_clock::now();
  const WriteEnd end = write(fifo);
  const double took_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_NE(end.exit_code, 0);
  EXPECT_NE(end.exit_code, std::nullopt) << "killed or timed out: it waited for a reader";
  EXPECT_NE(end.err.find("no process is reading the FIFO"), std::string::npos) << end.err;
  EXPECT_NE(end.err.find(fifo), std::string::npos) << end.err;
  EXPECT_LT(took_s, 30.0);
  EXPECT_EQ(kind_at(fifo), S_IFIFO);
}

inline void check_symlink(const std::filesystem::path& dir, const std::string& name,
                          const WriteTo& write, const CheckBytes& check) {
  std::filesystem::create_directories(dir / "real");
  const auto target = dir / "real" / name;
  std::ofstream(target) << "old content\n";
  const auto link = dir / name;
  std::filesystem::create_symlink(std::filesystem::path("real") / name, link);  // relative
  const WriteEnd end = write(link.string());
  EXPECT_EQ(end.exit_code, 0) << end.err;
  EXPECT_EQ(kind_at(link), S_IFLNK) << "the link was replaced";
  EXPECT_EQ(kind_at(target), S_IFREG);
  check(read_all(target));
}

/// How a writer treats a regular file: replaced by a rename (OutputMode::kReplace, a new inode)
/// or truncated and written in place (kInPlace, a log that grows: the same inode).
enum class Regular { kReplaced, kInPlace };

/// The old content gone, no temporary file left beside it.
inline void check_regular_file(const std::filesystem::path& dir, const std::string& name,
                               const WriteTo& write, const CheckBytes& check,
                               Regular how = Regular::kReplaced) {
  const auto file = dir / name;
  std::ofstream(file) << "old content\n";
  const ino_t before = inode_at(file);
  const WriteEnd end = write(file.string());
  EXPECT_EQ(end.exit_code, 0) << end.err;
  EXPECT_EQ(kind_at(file), S_IFREG);
  if (how == Regular::kReplaced)
    EXPECT_NE(inode_at(file), before) << "written in place, not replaced atomically";
  else
    EXPECT_EQ(inode_at(file), before) << "a log is written in place";
  check(read_all(file));
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << entry.path();
}

inline void check_directory(const std::filesystem::path& dir, const std::string& name,
                            const WriteTo& write) {
  const auto folder = dir / name;
  std::filesystem::create_directories(folder);
  const WriteEnd end = write(folder.string());
  EXPECT_NE(end.exit_code, 0);
  EXPECT_NE(end.exit_code, std::nullopt) << "killed or timed out";
  EXPECT_NE(end.err.find(folder.string()), std::string::npos) << end.err;
  EXPECT_NE(end.err.find("is a directory"), std::string::npos) << end.err;
  EXPECT_EQ(kind_at(folder), S_IFDIR);
  EXPECT_TRUE(std::filesystem::is_empty(folder));
}

}  // namespace test_support
