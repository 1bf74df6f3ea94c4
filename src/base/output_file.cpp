#include "base/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>

namespace base {

namespace {

/// Links followed before giving up (Linux's own limit for a path).
constexpr int kMaxLinks = 40;
/// Temporary names tried before giving up (each is `<FILE>.tmp.<pid>.<n>`; a clash needs a
/// stale file from an earlier process with the same id).
constexpr int kMaxTemporaryNames = 100;
/// Permissions of a new file before the umask, as for any file a shell redirection creates.
constexpr mode_t kNewFileMode = 0666;
/// How often open() looks again for a FIFO's reader.
constexpr auto kFifoPollInterval = std::chrono::milliseconds(10);

std::string quoted(const std::string& path) { return "'" + path + "'"; }

/// What the messages call the file: the path given, and where a link led.
std::string where(const std::string& path, const std::string& target) {
  return target == path ? quoted(path) : quoted(path) + " (a link to " + quoted(target) + ")";
}

std::string folder_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

/// The path `path` leads to once every symbolic link at its end is followed, or why not (a
/// loop, an unreadable link). Links in the folders above are the kernel's.
Result<std::string> follow_links(const std::string& path) {
  using R = Result<std::string>;
  std::string at = path;
  for (int hop = 0; hop <= kMaxLinks; ++hop) {
    struct stat info {};
    if (::lstat(at.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return R::ok(std::move(at));
    std::string link(static_cast<std::size_t>(info.st_size > 0 ? info.st_size : 4096) + 1, '\0');
    const ssize_t n = ::readlink(at.c_str(), link.data(), link.size());
    if (n < 0) return R::fail(std::strerror(errno));
    link.resize(static_cast<std::size_t>(n));
    at = (link.empty() || link[0] == '/') ? link : folder_of(at) + "/" + link;
  }
  return R::fail(std::strerror(ELOOP));
}

/// Why a file of this kind is not written, or "" when it is one the rule writes.
std::string refusal(mode_t mode) {
  if (S_ISREG(mode) || S_ISCHR(mode) || S_ISFIFO(mode)) return "";
  if (S_ISDIR(mode)) return "it is a directory";
  if (S_ISBLK(mode)) return "it is a block device";
  if (S_ISSOCK(mode)) return "it is a socket";
  return "it is not a file that can be written";
}

bool write_all(int fd, const char* data, std::size_t size) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

/// A new file beside `target`, named `<target>.tmp.<pid>.<n>`; -1 (errno set) when none could
/// be made.
int create_temporary(const std::string& target, std::string& name) {
  for (int n = 0; n < kMaxTemporaryNames; ++n) {
    name = target + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(n);
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, kNewFileMode);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  return -1;
}

/// Opens a device or FIFO for writing, never creating or truncating it. Non-blocking, so that a
/// FIFO without a reader fails (ENXIO) instead of hanging: retried until kFifoReaderWait_s has
/// passed, since a reader started beside the program may open it a moment late.
int open_through(const std::string& target, bool fifo) {
  const auto give_up = std::chrono::steady_clock::now() +
                       std::chrono::duration<double>(fifo ? kFifoReaderWait_s : 0.0);
  while (true) {
    const int fd = ::open(target.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_NOFOLLOW | O_CLOEXEC);
    if (fd >= 0 || errno != ENXIO || !fifo || std::chrono::steady_clock::now() >= give_up) return fd;
    std::this_thread::sleep_for(kFifoPollInterval);
  }
}

std::string no_reader() {
  return "no process is reading the FIFO (waited " +
         std::to_string(static_cast<int>(kFifoReaderWait_s)) + " s)";
}

}  // namespace

Result<void> OutputFile::fail(const std::string& reason) {
  if (error_.empty()) error_ = "cannot write " + where(path_, target_) + ": " + reason;
  return Result<void>::fail(error_);
}

Result<OutputFile> OutputFile::open(const std::string& path, OutputMode mode) {
  OutputFile out;
  out.path_ = path;
  out.target_ = path;
  Result<std::string> target = follow_links(path);
  if (!target) return Result<OutputFile>::fail(out.fail(target.error).error);
  out.target_ = std::move(*target.value);
  // (on failure, out's destructor closes and removes what was made)
  if (auto opened = out.open_target(mode); !opened)
    return Result<OutputFile>::fail(out.fail(opened.error).error);
  return Result<OutputFile>::ok(std::move(out));
}

Result<void> OutputFile::open_target(OutputMode mode) {
  using R = Result<void>;
  struct stat info {};
  const bool exists = ::stat(target_.c_str(), &info) == 0;
  if (!exists && errno != ENOENT) return R::fail(std::strerror(errno));
  if (exists && !refusal(info.st_mode).empty()) return R::fail(refusal(info.st_mode));
  through_ = exists && !S_ISREG(info.st_mode);
  if (through_) {
    const bool fifo = S_ISFIFO(info.st_mode);
    fd_ = open_through(target_, fifo);
    if (fd_ < 0) return R::fail(fifo && errno == ENXIO ? no_reader() : std::strerror(errno));
  } else if (mode == OutputMode::kReplace) {
    fd_ = create_temporary(target_, temporary_);
    if (fd_ < 0) return R::fail(std::strerror(errno));
    // Replacing a file keeps its permissions (the umask applies only to a new one). Best
    // effort: a file of another owner may refuse it, and the new file is still whole.
    if (exists) ::fchmod(fd_, info.st_mode & 07777);
  } else {
    // O_NONBLOCK: should the path have become a FIFO since stat(), this cannot hang.
    fd_ = ::open(target_.c_str(), O_WRONLY | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC,
                 kNewFileMode);
    if (fd_ < 0) return R::fail(std::strerror(errno));
  }
  return check_opened(mode);
}

Result<void> OutputFile::check_opened(OutputMode mode) {
  // What was opened is checked on the descriptor: the path may have changed since stat().
  struct stat opened {};
  if (::fstat(fd_, &opened) != 0 || !refusal(opened.st_mode).empty() ||
      S_ISREG(opened.st_mode) == through_) {
    return Result<void>::fail("it changed while it was opened");
  }
  if (!through_ && mode == OutputMode::kInPlace && ::ftruncate(fd_, 0) != 0)
    return Result<void>::fail(std::strerror(errno));
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);  // from now on, writes wait for room
  return Result<void>::ok();
}

OutputFile::OutputFile(OutputFile&& other) noexcept { *this = std::move(other); }

OutputFile& OutputFile::operator=(OutputFile&& other) noexcept {
  if (this != &other) {
    discard();
    fd_ = other.fd_;
    path_ = std::move(other.path_);
    target_ = std::move(other.target_);
    temporary_ = std::move(other.temporary_);
    buffer_ = std::move(other.buffer_);
    error_ = std::move(other.error_);
    through_ = other.through_;
    other.fd_ = -1;
    other.temporary_.clear();
  }
  return *this;
}

OutputFile::~OutputFile() { discard(); }

void OutputFile::discard() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
  temporary_.clear();
}

Result<void> OutputFile::write(std::string_view bytes) {
  if (!error_.empty() || fd_ < 0) return fail("it is closed");
  if (buffer_.size() + bytes.size() > kBufferBytes) {
    if (auto flushed = flush(); !flushed) return flushed;
  }
  if (bytes.size() >= kBufferBytes) {
    if (!write_all(fd_, bytes.data(), bytes.size())) return fail(std::strerror(errno));
    return Result<void>::ok();
  }
  buffer_.append(bytes);
  return Result<void>::ok();
}

Result<void> OutputFile::flush() {
  if (!error_.empty() || fd_ < 0) return fail("it is closed");
  const bool written = write_all(fd_, buffer_.data(), buffer_.size());
  buffer_.clear();
  return written ? Result<void>::ok() : fail(std::strerror(errno));
}

Result<void> OutputFile::commit() {
  if (auto flushed = flush(); !flushed) {
    discard();
    return flushed;
  }
  // A device or FIFO has nothing to sync (fsync fails with EINVAL there).
  if (!through_ && ::fsync(fd_) != 0) fail(std::strerror(errno));
  if (::close(fd_) != 0 && error_.empty()) fail(std::strerror(errno));
  fd_ = -1;
  if (error_.empty() && !temporary_.empty() &&
      std::rename(temporary_.c_str(), target_.c_str()) != 0) {
    fail(std::strerror(errno));
  }
  if (error_.empty()) temporary_.clear();  // renamed: nothing left to remove
  discard();
  return error_.empty() ? Result<void>::ok() : Result<void>::fail(error_);
}

OutputFileBuffer::int_type OutputFileBuffer::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  const char byte = traits_type::to_char_type(c);
  return file_.write(std::string_view(&byte, 1)) ? c : traits_type::eof();
}

std::streamsize OutputFileBuffer::xsputn(const char* bytes, std::streamsize count) {
  return file_.write(std::string_view(bytes, static_cast<std::size_t>(count))) ? count : 0;
}

int OutputFileBuffer::sync() { return file_.flush() ? 0 : -1; }

Result<void> write_output_file(const std::string& path, std::string_view text) {
  auto file = OutputFile::open(path, OutputMode::kReplace);
  if (!file) return Result<void>::fail(std::move(file.error));
  if (auto written = file.value->write(text); !written) return written;
  return file.value->commit();
}

}  // namespace base
