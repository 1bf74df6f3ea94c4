#include "base/line_stream.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace base {

namespace {

// Bytes asked of the kernel at a time: large enough that a pipe's reads stay few.
constexpr std::size_t kBlockBytes = std::size_t{256} * 1024;

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is a device, not a regular file";
}

}  // namespace

Result<LineStream> LineStream::open(const std::string& path, std::size_t max_line_bytes) {
  // Blocking: a FIFO waits for its writer, as a reader of a pipe should.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return Result<LineStream>::fail(std::string("cannot be opened: ") + std::strerror(errno));
  LineStream stream(fd, max_line_bytes);  // closes fd from here on
  struct stat info {};
  if (::fstat(fd, &info) != 0)
    return Result<LineStream>::fail(std::string("cannot be examined: ") + std::strerror(errno));
  if (!S_ISREG(info.st_mode) && !S_ISFIFO(info.st_mode))
    return Result<LineStream>::fail(kind_of(info.st_mode));
  return Result<LineStream>::ok(std::move(stream));
}

LineStream::LineStream(int fd, std::size_t max_line_bytes)
    : fd_(fd), max_line_bytes_(max_line_bytes), block_(kBlockBytes) {}

LineStream::LineStream(LineStream&& other) noexcept
    : fd_(other.fd_),
      max_line_bytes_(other.max_line_bytes_),
      block_(std::move(other.block_)),
      begin_(other.begin_),
      end_(other.end_),
      line_(std::move(other.line_)),
      holding_(other.holding_),
      skipping_(other.skipping_),
      at_end_(other.at_end_),
      line_number_(other.line_number_),
      long_lines_(other.long_lines_),
      error_(std::move(other.error_)) {
  other.fd_ = -1;
}

LineStream::~LineStream() {
  if (fd_ >= 0) ::close(fd_);
}

bool LineStream::refill() {
  for (;;) {
    const ssize_t n = ::read(fd_, block_.data(), block_.size());
    if (n > 0) {
      begin_ = 0;
      end_ = static_cast<std::size_t>(n);
      return true;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) error_ = std::string("read failed: ") + std::strerror(errno);
    return false;
  }
}

std::optional<std::string_view> LineStream::end_of_held_line() {
  ++line_number_;
  const bool too_long = skipping_;
  skipping_ = false;
  holding_ = false;
  if (too_long) {
    ++long_lines_;
    return std::nullopt;
  }
  return std::string_view(line_);
}

std::optional<std::string_view> LineStream::next() {
  if (!holding_) line_.clear();  // the line returned last
  while (!at_end_) {
    if (begin_ == end_ && !refill()) {
      at_end_ = true;
      if (holding_ || skipping_) {
        if (auto line = end_of_held_line()) return line;
      }
      break;
    }
    const char* const from = block_.data() + begin_;
    const std::size_t available = end_ - begin_;
    const void* const newline = std::memchr(from, '\n', available);
    const std::size_t length =
        newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - from) : available;
    begin_ += newline ? length + 1 : length;
    if (!holding_ && !skipping_ && newline) {  // the common case: the line is in the block
      ++line_number_;
      if (length <= max_line_bytes_) return std::string_view(from, length);
      ++long_lines_;
      continue;
    }
    if (!skipping_) {
      line_.append(from, length);
      holding_ = true;
      if (line_.size() > max_line_bytes_) {
        skipping_ = true;  // read past the rest, holding none of it
        line_.clear();
        line_.shrink_to_fit();
      }
    }
    if (newline) {
      if (auto line = end_of_held_line()) return line;
    }
  }
  return std::nullopt;
}

std::string long_lines_warning(std::size_t count, std::size_t max_line_bytes) {
  return std::to_string(count) + " lines over " + std::to_string(max_line_bytes) +
         " bytes skipped";
}

}  // namespace base
