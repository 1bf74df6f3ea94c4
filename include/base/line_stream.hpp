#pragma once
// A file read a line at a time, with memory bounded independently of its size: for readers of
// logs that may be piped in (`hazard_replay run.moos <(zcat run.alog.gz)`) and may hold a line
// of hundreds of megabytes.
//
// Contract:
// - Only a regular file or a FIFO (a pipe, /dev/stdin when it is one) is read; a directory,
//   socket or device is refused with a reason, as base::WholeFile refuses it. Opening a FIFO
//   waits for its writer.
// - Lines are split at '\n' (a last line without one still counts) and returned without it.
// - A line over `max_line_bytes` is read past and never held: it is counted (long_lines())
//   and the next line is returned. Memory: one read block plus at most `max_line_bytes`.
// - A read error ends the lines, with the reason in error().

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"

namespace base {

class LineStream {
 public:
  /// The lines of `path`, or why it cannot be read ("is a directory").
  static Result<LineStream> open(const std::string& path, std::size_t max_line_bytes);
  LineStream(LineStream&& other) noexcept;
  LineStream& operator=(LineStream&&) = delete;
  LineStream(const LineStream&) = delete;
  LineStream& operator=(const LineStream&) = delete;
  ~LineStream();

  /// The next line, valid until the next call; nullopt at the end (or after a read error).
  std::optional<std::string_view> next();
  /// The number of the line next() returned last, counting from 1 (skipped long lines count).
  std::size_t line_number() const { return line_number_; }
  /// Lines over the bound read past so far.
  std::size_t long_lines() const { return long_lines_; }
  const std::string& error() const { return error_; }

 private:
  LineStream(int fd, std::size_t max_line_bytes);
  bool refill();
  // The line held in line_ (a line that spans reads) is done: nullopt when it was too long.
  std::optional<std::string_view> end_of_held_line();

  int fd_ = -1;
  std::size_t max_line_bytes_;
  std::vector<char> block_;
  std::size_t begin_ = 0;  // unread bytes of block_: [begin_, end_)
  std::size_t end_ = 0;
  std::string line_;        // a line that spans reads
  bool holding_ = false;    // line_ holds the start of a line
  bool skipping_ = false;   // reading past a line over the bound
  bool at_end_ = false;
  std::size_t line_number_ = 0;
  std::size_t long_lines_ = 0;
  std::string error_;
};

/// "N lines over B bytes skipped": the one warning every reader gives for its long lines.
std::string long_lines_warning(std::size_t count, std::size_t max_line_bytes);

}  // namespace base
