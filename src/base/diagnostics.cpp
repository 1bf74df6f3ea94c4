// Diagnostics that never block. Contract in base/diagnostics.hpp.
#include "base/diagnostics.hpp"

#include "base/descriptors.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <streambuf>
#include <string>

namespace base {
namespace {

std::uint64_t lines_in(std::string_view text) {
  const auto newlines = static_cast<std::uint64_t>(std::count(text.begin(), text.end(), '\n'));
  return text.empty() || text.back() == '\n' ? newlines : newlines + 1;
}

enum class Put { kWritten, kWouldWait, kFailed };

/// Whether `fd` takes a write now: a socket answers through send's MSG_DONTWAIT, anything else
/// through a poll that does not wait (a pipe without a reader reports an error: not ready).
bool ready_now(int fd) {
  pollfd p{fd, POLLOUT, 0};
  for (;;) {
    const int ready = ::poll(&p, 1, 0);
    if (ready < 0 && errno == EINTR) continue;
    return ready == 1 && (p.revents & POLLOUT) && !(p.revents & (POLLERR | POLLHUP | POLLNVAL));
  }
}

/// One piece (at most PIPE_BUF bytes, so a pipe takes it whole or not at all), now or never.
Put put_now(int fd, std::string_view piece, bool& line_open) {
  while (!piece.empty()) {
    ssize_t n = ::send(fd, piece.data(), piece.size(), MSG_DONTWAIT | MSG_NOSIGNAL);
    if (n < 0 && errno == ENOTSOCK) {
      if (!ready_now(fd)) return Put::kWouldWait;
      n = ::write(fd, piece.data(), piece.size());
    }
    if (n > 0) {
      line_open = piece[static_cast<std::size_t>(n) - 1] != '\n';
      piece.remove_prefix(static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    return n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK) ? Put::kWouldWait : Put::kFailed;
  }
  return Put::kWritten;
}

/// The longest prefix of `text` to write as one piece: whole lines when they fit in PIPE_BUF.
std::size_t piece_length(std::string_view text) {
  if (text.size() <= PIPE_BUF) return text.size();
  const std::size_t last_newline = text.substr(0, PIPE_BUF).rfind('\n');
  return last_newline == std::string_view::npos ? PIPE_BUF : last_newline + 1;
}

/// A stream buffer that hands whole lines to standard_writer(fd) (a line longer than the limit
/// goes in parts) when the stream is flushed (std::cerr flushes after every output, unless a
/// program turns unitbuf off to gather its lines, as hazard_replay does) or once kGatherBytes
/// are pending. Never destroyed: the streams flush it at exit.
class DiagnosticBuffer : public std::streambuf {
 public:
  explicit DiagnosticBuffer(int fd) : fd_(fd) {}

 protected:
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    const char ch = traits_type::to_char_type(c);
    xsputn(&ch, 1);
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_.append(s, static_cast<std::size_t>(n));
    if (pending_.size() >= kGatherBytes) write_lines();
    return n;
  }
  int sync() override {
    std::lock_guard<std::mutex> lock(mutex_);
    write_lines();
    return 0;
  }

 private:
  static constexpr std::size_t kGatherBytes = 16 * 1024;
  static constexpr std::size_t kLongLine = 64 * 1024;

  /// The complete lines pending, or everything once a line is too long to wait for its end.
  void write_lines() {
    const std::size_t end = pending_.size() >= kLongLine ? pending_.size()
                                                         : pending_.rfind('\n') + 1;  // npos: 0
    if (end == 0) return;
    standard_writer(fd_).write(std::string_view(pending_).substr(0, end));
    pending_.erase(0, end);
  }

  int fd_;
  std::mutex mutex_;
  std::string pending_;
};

ssize_t cookie_write(void* cookie, const char* data, std::size_t size) {
  standard_writer(static_cast<int>(reinterpret_cast<std::intptr_t>(cookie))).write({data, size});
  return static_cast<ssize_t>(size);  // dropped text is counted, never an error of the stream
}

/// A C stream over standard_writer(fd), line-buffered as stderr is expected to be.
FILE* diagnostic_file(int fd) {
  cookie_io_functions_t functions{};
  functions.write = cookie_write;
  void* cookie = reinterpret_cast<void*>(static_cast<std::intptr_t>(fd));
  FILE* file = ::fopencookie(cookie, "w", functions);
  if (file) std::setvbuf(file, nullptr, _IOLBF, BUFSIZ);
  return file;
}

void route(int fd, std::ostream& stream, FILE*& c_stream) {
  std::fflush(c_stream);
  stream.flush();
  stream.rdbuf(new DiagnosticBuffer(fd));  // lives as long as the process
  if (FILE* file = diagnostic_file(fd)) c_stream = file;
}

}  // namespace

DiagnosticWriter::DiagnosticWriter(int fd, std::string stream_name)
    : fd_(fd), stream_name_(std::move(stream_name)) {}

// Writes `text` in pieces of whole lines until one cannot go now; what is left of it.
std::string_view DiagnosticWriter::write_now(std::string_view text, bool& line_open) {
  while (!text.empty()) {
    const std::size_t length = piece_length(text);
    if (put_now(fd_, text.substr(0, length), line_open) != Put::kWritten) return text;
    text.remove_prefix(length);
  }
  return text;
}

bool DiagnosticWriter::write(std::string_view text) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (unreported_lines_ > 0) {
    const std::string note = std::string(line_open_ ? "\n" : "") + "[" +
                             std::to_string(unreported_lines_) + " line" +
                             (unreported_lines_ == 1 ? "" : "s") + " of diagnostics dropped: " +
                             stream_name_ + " was not taking them]\n";
    bool note_open = false;
    if (!write_now(note, note_open).empty()) return drop(text);
    line_open_ = false;
    unreported_lines_ = 0;
  }
  const std::string_view left = write_now(text, line_open_);
  return left.empty() || drop(left);
}

bool DiagnosticWriter::drop(std::string_view text) {
  dropped_lines_ += lines_in(text);
  unreported_lines_ += lines_in(text);
  return false;
}

std::uint64_t DiagnosticWriter::dropped_lines() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return dropped_lines_;
}

DiagnosticWriter& standard_writer(int fd) {
  static DiagnosticWriter output(STDOUT_FILENO, "standard output");
  static DiagnosticWriter error(STDERR_FILENO, "standard error");
  return fd == STDOUT_FILENO ? output : error;
}

void install_nonblocking_diagnostics(DiagnosticStreams streams) {
  ensure_standard_descriptors();
  route(STDERR_FILENO, std::cerr, stderr);
  std::clog.rdbuf(std::cerr.rdbuf());
  if (streams == DiagnosticStreams::kStdoutAndStderr) route(STDOUT_FILENO, std::cout, stdout);
}

}  // namespace base
