// Descriptors a program owns. Contract in base/descriptors.hpp.
#include "base/descriptors.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>

namespace base {
namespace {

constexpr int kFirstFreeDescriptor = STDERR_FILENO + 1;

/// `fd` itself when it is above 2, else a close-on-exec copy above 2 (the original closed).
int above_standard(int fd) {
  if (fd < 0 || fd >= kFirstFreeDescriptor) return fd;
  const int moved = ::fcntl(fd, F_DUPFD_CLOEXEC, kFirstFreeDescriptor);
  const int saved = errno;
  ::close(fd);
  errno = saved;
  return moved;
}

}  // namespace

void ensure_standard_descriptors() {
  for (int fd = STDIN_FILENO; fd <= STDERR_FILENO; ++fd) {
    if (::fcntl(fd, F_GETFD) >= 0 || errno != EBADF) continue;
    const int null_fd = ::open("/dev/null", fd == STDIN_FILENO ? O_RDONLY : O_WRONLY);
    // open() returns the lowest free descriptor: `fd` itself, as the lower ones are open.
    if (null_fd >= 0 && null_fd != fd) {
      ::dup2(null_fd, fd);
      ::close(null_fd);
    }
  }
}

bool open_internal_pipe(int fds[2]) {
  int raw[2];
  if (::pipe2(raw, O_NONBLOCK | O_CLOEXEC) != 0) return false;
  fds[0] = above_standard(raw[0]);
  fds[1] = above_standard(raw[1]);
  if (fds[0] >= 0 && fds[1] >= 0) return true;
  const int saved = errno;
  if (fds[0] >= 0) ::close(fds[0]);
  if (fds[1] >= 0) ::close(fds[1]);
  errno = saved;
  return false;
}

}  // namespace base
