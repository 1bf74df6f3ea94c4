#pragma once
// hazard_replay's input log, streamed: memory is bounded independently of the log's size, so a
// log piped in (`<(zcat run.alog.gz)`, a FIFO) costs what a file does.
//
// Contract:
// - Lines are read one at a time (base::LineStream); a line over kMaxInputLineBytes is skipped.
// - Entries come out in time order within a reorder window (kReorderWindowLines lines or
//   kReorderWindowBytes of text, stable for equal times): a logger writes in time order, and
//   mild disorder (merged logs) is put right. An entry earlier than one already given out (out
//   of order by more than the window) comes out late; Driver::deliver holds the clock, so it is
//   delivered at the time reached.
// - Skipped and late lines are counted: malformed lines are warned of with file and line, the
//   first base::kMaxWarningsPerKind of them; unusable times, long lines and late entries get one
//   warning each, with their count, at the end (finish()).

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <queue>
#include <string>
#include <vector>

#include "base/line_stream.hpp"
#include "base/warning_budget.hpp"
#include "hazard/driver.hpp"

namespace hazard_replay {

/// The longest input line, in bytes: well above the engine's kMaxMailValueBytes (a longer value
/// is ignored with a run warning), far below a memory problem.
inline constexpr std::size_t kMaxInputLineBytes = std::size_t{1} << 20;
inline constexpr std::size_t kReorderWindowLines = 10000;
inline constexpr std::size_t kReorderWindowBytes = std::size_t{16} << 20;

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
  InputLog(base::LineStream lines, std::string path, std::ostream& err);
  struct Held {
    double time_s;
    std::uint64_t order;  // arrival: equal times keep the log's order
    std::string variable;
    std::string value;
  };
  struct Later {
    bool operator()(const Held& a, const Held& b) const {
      return a.time_s != b.time_s ? a.time_s > b.time_s : a.order > b.order;
    }
  };
  bool window_full() const;
  bool read_line();  // false at the end of the log
  void fill();

  base::LineStream lines_;
  std::string path_;
  std::ostream* err_;
  double logstart_s_ = 0.0;
  std::priority_queue<Held, std::vector<Held>, Later> window_;
  std::size_t window_bytes_ = 0;
  std::uint64_t arrivals_ = 0;
  bool at_end_ = false;
  Held current_{};
  hazard::Mail mail_{};
  std::optional<double> last_time_s_;
  base::WarningBudget malformed_{base::kMaxWarningsPerKind};
  std::size_t unusable_times_ = 0;
  std::size_t late_ = 0;
};

}  // namespace hazard_replay
