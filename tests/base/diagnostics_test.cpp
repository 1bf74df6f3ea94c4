// Diagnostics that never block (base/diagnostics.hpp): a stalled pipe, a stalled socket and a
// pipe without a reader are written without waiting, whole lines or nothing, the loss counted
// and said once writing resumes; closed standard descriptors are reopened on /dev/null; a
// program whose standard error nobody reads runs to its end.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <string>
#include <thread>

#include "base/descriptors.hpp"
#include "base/diagnostics.hpp"

namespace base {
namespace {

/// Both ends of a pipe (or a socket pair), closed at the end of the test.
struct Ends {
  int read = -1;
  int write = -1;
  ~Ends() {
    if (read >= 0) ::close(read);
    if (write >= 0) ::close(write);
  }
};

void make_pipe(Ends& ends) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  ends.read = fds[0];
  ends.write = fds[1];
}

void make_socket_pair(Ends& ends) {
  int fds[2];
  ASSERT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, fds), 0);
  ends.read = fds[0];
  ends.write = fds[1];
}

/// Everything readable now from a descriptor (made non-blocking for the purpose).
std::string drain(int fd) {
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
  std::string out;
  char buffer[65536];
  for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) out.append(buffer, n);
  return out;
}

const std::string kLine = std::string(99, 'x') + "\n";

/// Writes `count` lines to a descriptor nobody reads; the number that was dropped.
int write_until_stalled(DiagnosticWriter& writer, int count) {
  int dropped = 0;
  for (int i = 0; i < count; ++i) {
    if (!writer.write(kLine)) ++dropped;
  }
  return dropped;
}

void expect_whole_lines(const std::string& text) {
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.size() % kLine.size(), 0u);
  for (std::size_t at = 0; at + kLine.size() <= text.size(); at += kLine.size()) {
    ASSERT_EQ(text.compare(at, kLine.size(), kLine), 0) << "a torn line at byte " << at;
  }
}

TEST(Diagnostics, AStalledPipeIsWrittenWithoutWaitingWholeLinesOrNothing) {
  Ends pipe;
  make_pipe(pipe);
  DiagnosticWriter writer(pipe.write, "standard error");
  const int dropped = write_until_stalled(writer, 5000);  // 500 KB into a 64 KB pipe
  EXPECT_GT(dropped, 4000);
  EXPECT_EQ(writer.dropped_lines(), static_cast<std::uint64_t>(dropped));
  expect_whole_lines(drain(pipe.read));

  // Once the reader catches up, the next write first says how much was lost.
  ASSERT_TRUE(writer.write("resumed\n"));
  EXPECT_EQ(drain(pipe.read), "[" + std::to_string(dropped) +
                                  " lines of diagnostics dropped: standard error was not taking "
                                  "them]\nresumed\n");
  ASSERT_TRUE(writer.write("again\n"));
  EXPECT_EQ(drain(pipe.read), "again\n");  // said once
}

TEST(Diagnostics, AStalledSocketIsWrittenWithoutWaiting) {
  Ends pair;
  make_socket_pair(pair);
  DiagnosticWriter writer(pair.write, "standard error");
  const int dropped = write_until_stalled(writer, 20000);  // 2 MB, past any socket buffer
  EXPECT_GT(dropped, 0);
  expect_whole_lines(drain(pair.read));
  ASSERT_TRUE(writer.write("resumed\n"));
  const std::string after = drain(pair.read);
  EXPECT_EQ(after.rfind("[" + std::to_string(dropped) + " lines of diagnostics dropped", 0), 0u)
      << after;
}

TEST(Diagnostics, APipeWithoutAReaderDropsWithoutASignal) {
  Ends pipe;
  make_pipe(pipe);
  ::close(pipe.read);
  pipe.read = -1;
  // SIGPIPE at its default would end the test program here.
  DiagnosticWriter writer(pipe.write, "standard error");
  EXPECT_FALSE(writer.write("nobody reads this\n"));
  EXPECT_EQ(writer.dropped_lines(), 1u);
}

/// Runs `body` in a child process; its exit status, or -1 when it ran for more than 20 s.
template <typename Body>
int in_child(Body body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    body();
    std::_Exit(0);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(Diagnostics, ClosedStandardDescriptorsAreReopenedOnDevNull) {
  const int status = in_child([] {
    ::close(STDIN_FILENO);
    ::close(STDERR_FILENO);
    ensure_standard_descriptors();
    char target[64] = {};
    for (int fd : {STDIN_FILENO, STDERR_FILENO}) {
      const std::string link = "/proc/self/fd/" + std::to_string(fd);
      const ssize_t n = ::readlink(link.c_str(), target, sizeof target - 1);
      if (n <= 0 || std::string(target, static_cast<std::size_t>(n)) != "/dev/null") std::_Exit(3);
    }
    // A pipe opened now can no longer land on descriptor 2.
    int fds[2];
    if (::pipe(fds) != 0 || fds[0] <= STDERR_FILENO || fds[1] <= STDERR_FILENO) std::_Exit(4);
  });
  EXPECT_EQ(status, 0);
}

TEST(Diagnostics, AnInternalPipeIsNonBlockingAndAboveTheStandardDescriptors) {
  const int status = in_child([] {
    ::close(STDOUT_FILENO);
    ::close(STDERR_FILENO);
    int fds[2];
    if (!open_internal_pipe(fds)) std::_Exit(3);
    for (int fd : fds) {
      if (fd <= STDERR_FILENO) std::_Exit(4);
      if (!(::fcntl(fd, F_GETFL) & O_NONBLOCK) || !(::fcntl(fd, F_GETFD) & FD_CLOEXEC)) std::_Exit(5);
    }
    // Full, it refuses instead of waiting.
    const std::string block(65536, 'x');
    while (::write(fds[1], block.data(), block.size()) > 0) {
    }
    if (errno != EAGAIN) std::_Exit(6);
  });
  EXPECT_EQ(status, 0);
}

TEST(Diagnostics, AProgramWhoseStandardErrorNobodyReadsRunsToItsEnd) {
  Ends pipe;
  make_pipe(pipe);
  const int write_end = pipe.write;
  const int status = in_child([write_end] {
    ::dup2(write_end, STDERR_FILENO);
    install_nonblocking_diagnostics();
    for (int i = 0; i < 20000; ++i) {  // 2 MB each way, into a 64 KB pipe nobody reads
      std::cerr << kLine;
      std::fprintf(stderr, "%s", kLine.c_str());
    }
    std::cerr.flush();
    std::fflush(stderr);
    if (standard_writer(STDERR_FILENO).dropped_lines() < 30000) std::_Exit(5);
  });
  EXPECT_EQ(status, 0) << "-1: the child was stopped by its standard error";
  expect_whole_lines(drain(pipe.read));
}

// A program that turns unitbuf off (hazard_replay, with an event per detection) gathers its
// lines: nothing is written until the stream is flushed, then every line at once.
TEST(Diagnostics, AStreamWithoutUnitbufWritesItsLinesWhenFlushed) {
  Ends pipe;
  make_pipe(pipe);
  const int write_end = pipe.write;
  const int read_end = pipe.read;
  const int status = in_child([write_end, read_end] {
    ::dup2(write_end, STDERR_FILENO);
    install_nonblocking_diagnostics();
    std::cerr.unsetf(std::ios::unitbuf);
    for (int i = 0; i < 10; ++i) std::cerr << kLine;
    if (!drain(read_end).empty()) std::_Exit(3);
    std::cerr.flush();
    if (drain(read_end) != [] {
          std::string ten;
          for (int i = 0; i < 10; ++i) ten += kLine;
          return ten;
        }())
      std::_Exit(4);
  });
  EXPECT_EQ(status, 0);
}

}  // namespace
}  // namespace base
