#include "base/file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace base {

namespace {

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISFIFO(mode)) return "is a FIFO, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
  return "is not a regular file";
}

std::string too_large(std::size_t max_bytes) {
  return "is larger than " + std::to_string(max_bytes) + " bytes";
}

/// Closes the descriptor on every path out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

FileText read_regular_file(const std::string& path, std::size_t max_bytes) {
  // O_NONBLOCK: opening a FIFO without a writer returns at once instead of waiting for one.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) return {std::nullopt, std::string("cannot be opened: ") + std::strerror(errno)};
  struct stat info {};
  if (::fstat(file.fd, &info) != 0)
    return {std::nullopt, std::string("cannot be examined: ") + std::strerror(errno)};
  if (!S_ISREG(info.st_mode)) return {std::nullopt, kind_of(info.st_mode)};
  if (static_cast<unsigned long long>(info.st_size) > max_bytes) return {std::nullopt, too_large(max_bytes)};

  std::string text(static_cast<std::size_t>(info.st_size), '\0');
  std::size_t used = 0;
  char spare[4096];
  while (true) {
    // Read into the string while it has room, then into a spare buffer to notice growth.
    const bool room = used < text.size();
    char* into = room ? text.data() + used : spare;
    const std::size_t want = room ? text.size() - used : sizeof spare;
    const ssize_t got = ::read(file.fd, into, want);
    if (got < 0) {
      if (errno == EINTR) continue;
      return {std::nullopt, std::string("cannot be read: ") + std::strerror(errno)};
    }
    if (got == 0) break;
    if (!room) {
      if (used + static_cast<std::size_t>(got) > max_bytes) return {std::nullopt, too_large(max_bytes)};
      text.append(spare, static_cast<std::size_t>(got));
    }
    used += static_cast<std::size_t>(got);
  }
  text.resize(used);
  return {std::move(text), {}};
}

}  // namespace base
