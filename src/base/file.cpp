#include "base/file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
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

/// `what` followed by the reason errno gives.
std::string cannot(const char* what) { return std::string(what) + std::strerror(errno); }

// Reads `fd` to its end into `bytes`, a block at a time; false with `problem` set on an error
// or past `max_bytes`.
bool read_to_end(int fd, std::size_t max_bytes, std::vector<char>& bytes, std::string& problem) {
  constexpr std::size_t kBlockBytes = std::size_t{1} << 20;
  std::size_t used = 0;
  while (true) {
    if (bytes.size() - used < kBlockBytes) bytes.resize(used + kBlockBytes);
    const ssize_t got = ::read(fd, bytes.data() + used, bytes.size() - used);
    if (got < 0) {
      if (errno == EINTR) continue;
      problem = cannot("cannot be read: ");
      return false;
    }
    if (got == 0) break;
    used += static_cast<std::size_t>(got);
    if (used > max_bytes) {
      problem = too_large(max_bytes);
      return false;
    }
  }
  bytes.resize(used);  // (the capacity past it was never written: no resident memory)
  return true;
}

}  // namespace

Result<std::string> read_file_text(const std::string& path, std::size_t max_bytes) {
  using R = Result<std::string>;
  // O_NONBLOCK: opening a FIFO without a writer returns at once instead of waiting for one.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) return R::fail(cannot("cannot be opened: "));
  struct stat info {};
  if (::fstat(file.fd, &info) != 0)
    return R::fail(cannot("cannot be examined: "));
  if (!S_ISREG(info.st_mode)) return R::fail(kind_of(info.st_mode));
  if (static_cast<unsigned long long>(info.st_size) > max_bytes) return R::fail(too_large(max_bytes));

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
      return R::fail(cannot("cannot be read: "));
    }
    if (got == 0) break;
    if (!room) {
      if (used + static_cast<std::size_t>(got) > max_bytes) return R::fail(too_large(max_bytes));
      text.append(spare, static_cast<std::size_t>(got));
    }
    used += static_cast<std::size_t>(got);
  }
  text.resize(used);
  return R::ok(std::move(text));
}

Result<WholeFile> WholeFile::open(const std::string& path, std::size_t max_bytes) {
  using R = Result<WholeFile>;
  // Blocking: a FIFO waits for its writer, as a reader of a pipe should.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) return R::fail(cannot("cannot be opened: "));
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) return R::fail(cannot("cannot be examined: "));
  if (!S_ISREG(info.st_mode) && !S_ISFIFO(info.st_mode)) return R::fail(kind_of(info.st_mode));
  WholeFile whole;
  if (S_ISREG(info.st_mode) && info.st_size > 0) {
    const auto size = static_cast<unsigned long long>(info.st_size);
    if (size > max_bytes) return R::fail(too_large(max_bytes));
    int flags = MAP_PRIVATE;
#ifdef MAP_POPULATE
    flags |= MAP_POPULATE;  // the page tables filled in one call, not one fault per page
#endif
    void* const mapped = ::mmap(nullptr, static_cast<std::size_t>(size), PROT_READ, flags,
                                file.fd, 0);
    if (mapped != MAP_FAILED) {
      whole.mapped_ = mapped;
      whole.mapped_bytes_ = static_cast<std::size_t>(size);
      return R::ok(std::move(whole));
    }
  }
  std::string problem;
  if (!read_to_end(file.fd, max_bytes, whole.read_, problem)) return R::fail(std::move(problem));
  return R::ok(std::move(whole));
}

WholeFile::WholeFile(WholeFile&& other) noexcept
    : mapped_(other.mapped_), mapped_bytes_(other.mapped_bytes_), read_(std::move(other.read_)) {
  other.mapped_ = nullptr;
  other.mapped_bytes_ = 0;
}

WholeFile& WholeFile::operator=(WholeFile&& other) noexcept {
  if (this != &other) {
    unmap();
    mapped_ = other.mapped_;
    mapped_bytes_ = other.mapped_bytes_;
    read_ = std::move(other.read_);
    other.mapped_ = nullptr;
    other.mapped_bytes_ = 0;
  }
  return *this;
}

WholeFile::~WholeFile() { unmap(); }

void WholeFile::unmap() {
  if (mapped_) ::munmap(mapped_, mapped_bytes_);
  mapped_ = nullptr;
  mapped_bytes_ = 0;
}

}  // namespace base
