#pragma once
// hazard_replay's input log, read a line at a time: memory of our own is bounded independently
// of the log's size, so a log piped in (`<(zcat run.alog.gz)`, a FIFO) costs what a file does.
//
// Contract:
// - A regular file is mapped (base::WholeFile: no copy; its pages are the page cache's, and
//   entries are views into them); a pipe is streamed (base::LineStream: one read block, and each
//   held entry's text copied). Either way a line over kMaxInputLineBytes is skipped and counted.
// - Entries come out in time order within a reorder window (kReorderWindowLines lines or
//   kReorderWindowBytes of text, stable for equal times): a logger writes in time order, and
//   mild disorder (merged logs) is put right. An entry earlier than one already given out (out
//   of order by more than the window) comes out late; Driver::deliver holds the clock, so it is
//   delivered at the time reached.
// - Skipped and late lines are counted: malformed lines are warned of with file and line, the
//   first base::kMaxWarningsPerKind of them; unusable times, long lines and late entries get one
//   warning each, with their count, at the end (finish()).

#include <cstddef>
#include <deque>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>

#include "base/file.hpp"
#include "base/line_stream.hpp"
#include "base/warning_budget.hpp"
#include "hazard/driver.hpp"

namespace hazard_replay {

/// The longest input line, in bytes: well above the engine's kMaxMailValueBytes (a longer value
/// is ignored with a run warning), far below a memory problem.
inline constexpr std::size_t kMaxInputLineBytes = std::size_t{1} << 20;
inline constexpr std::size_t kReorderWindowLines = 10000;
inline constexpr std::size_t kReorderWindowBytes = std::size_t{16} << 20;
/// The largest regular file mapped, in bytes (beyond the 4 GiB --seeds may hold).
inline constexpr std::size_t kMaxMappedLogBytes = std::size_t{1} << 40;

class InputLog {
 public:
  /// The log at `path`, read up to its first entries (so logstart_s() is known), or nullopt
  /// with `problem` set. Warnings of malformed lines go to `err`.
  static std::optional<InputLog> open(const std::string& path, std::ostream& err,
                                      std::string& problem);

  /// The LOGSTART header's value (0 without one).
  double logstart_s() const { return logstart_s_; }
  /// The next entry, valid until the next call; nullptr at the end.
  const hazard::Mail* next();
  /// The counted warnings, one line each ("hazard_replay: <path>: ..."); call at the end.
  void finish(std::ostream& err) const;

 private:
  InputLog(std::string path, std::ostream& err) : path_(std::move(path)), err_(&err) {}
  // An entry's text: views into the mapped file, or (streamed) its own copy. Offsets, not
  // views, so that moving it (a short copy lives inside the string) keeps it valid.
  struct Held {
    double time_s = 0.0;
    const char* base = nullptr;  // the mapped file, or nullptr: `text`
    std::string text;
    std::size_t variable_at = 0, variable_size = 0, value_at = 0, value_size = 0;
    const char* start() const { return base ? base : text.data(); }
    std::string_view variable() const { return {start() + variable_at, variable_size}; }
    std::string_view value() const { return {start() + value_at, value_size}; }
  };
  bool window_full() const;
  void hold(Held entry);
  std::optional<std::string_view> next_line();
  bool read_line();  // false at the end of the log
  void fill();

  std::optional<base::WholeFile> mapped_;
  std::size_t cursor_ = 0;  // in the mapped file
  std::optional<base::LineStream> stream_;
  std::size_t line_number_ = 0;
  std::size_t long_lines_ = 0;  // of the mapped file (the stream counts its own)
  std::string path_;
  std::ostream* err_;
  double logstart_s_ = 0.0;
  // In time order, equal times in arrival order. A log in order costs a push at the back and a
  // pop at the front a line; a line out of order is inserted where it belongs.
  std::deque<Held> window_;
  std::size_t window_bytes_ = 0;
  bool at_end_ = false;
  Held current_{};
  hazard::Mail mail_{};
  std::optional<double> last_time_s_;
  base::WarningBudget malformed_{base::kMaxWarningsPerKind};
  std::size_t unusable_times_ = 0;
  std::size_t late_ = 0;
};

}  // namespace hazard_replay
