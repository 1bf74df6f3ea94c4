#pragma once
// A writer for a FIFO that a test's reader (a function or a child process) is meant to read:
// it waits for the reader to open the FIFO, writes the bytes, and gives up rather than hang
// the test when no reader comes or the reader goes away.

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <string>
#include <thread>

namespace test_support {

/// Writes `bytes` into the FIFO at `path` once a reader has opened it, then closes it. Gives up
/// when no reader opened it within `wait_s`. Meant for a thread of its own; false when the bytes
/// were not all written.
inline bool write_fifo(const std::string& path, const std::string& bytes, double wait_s = 60.0) {
  // A reader that goes away makes write() fail with EPIPE here, not kill the test process.
  sigset_t pipe_signal;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_signal, nullptr);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_s);
  int fd = -1;
  // Non-blocking, an open for writing fails (ENXIO) while there is no reader: poll for one.
  while ((fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC)) < 0 && errno == ENXIO &&
         std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (fd < 0) return false;
  ::fcntl(fd, F_SETFL, 0);  // blocking writes: wait for the reader to make room
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    written += static_cast<std::size_t>(n);
  }
  ::close(fd);
  return written == bytes.size();
}

}  // namespace test_support
