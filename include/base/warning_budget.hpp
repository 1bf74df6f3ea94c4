#pragma once
// Bounded warnings. Hostile input (a line of millions of unknown keys, a log of millions of bad
// lines) must cost a bounded number of warnings, not gigabytes of them: each producer keeps the
// first few of a kind and counts the rest, and one summary line says how many were left out.
//
// Contract: the first `limit` calls to admit() return true, later ones false and are counted;
// summary() is "... and K more <what>" when K > 0, empty otherwise.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace base {

/// Warnings one input line (a hazard line, a sensor_config value) adds, then one summary.
inline constexpr std::size_t kMaxWarningsPerLine = 8;
/// Warnings of one kind a program prints in one run (hazard_replay's config warnings, run
/// warnings, skipped log lines), then one summary at the end.
inline constexpr std::size_t kMaxWarningsPerKind = 100;

class WarningBudget {
 public:
  explicit WarningBudget(std::size_t limit) : limit_(limit) {}

  /// True while fewer than `limit` were admitted; otherwise counts one left out.
  bool admit() {
    if (admitted_ < limit_) {
      ++admitted_;
      return true;
    }
    ++dropped_;
    return false;
  }
  /// Appends `text` to `list` when admitted.
  void add(std::vector<std::string>& list, std::string text) {
    if (admit()) list.push_back(std::move(text));
  }
  std::size_t dropped() const { return dropped_; }
  std::string summary(std::string_view what) const {
    if (dropped_ == 0) return {};
    return "... and " + std::to_string(dropped_) + " more " + std::string(what);
  }

 private:
  std::size_t limit_;
  std::size_t admitted_ = 0;
  std::size_t dropped_ = 0;
};

}  // namespace base
