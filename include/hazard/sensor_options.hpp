#pragma once
// The sensor option table (manual 4, differences.md D3, D4, D20, D21, "Width choice").
//
// Contract: options are held sorted by width ascending (ids 0..n-1 in that order) and also in
// configuration order for the summary (D21). Widths are unique (within kWidthMatchTolerance_m);
// a second option with the same width is refused. Width choice and the default are pure
// functions of the table and a caller-supplied "is this option full" predicate (the engine knows
// which vehicles hold which width).

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"
#include "hazard/messages/options_summary.hpp"

namespace hazard {

/// Widths closer than this are the same width (differences.md "Width choice").
inline constexpr double kWidthMatchTolerance_m = 1e-6;

struct SensorOption {
  double width_m = 0.0;  ///< > 0, to each side of the vehicle (D2)
  double exp = 1.0;      ///< ROC exponent >= 1
  double pclass = 0.5;   ///< probability of correct classification in [0.5, 1]
  int max_vehicles = 0;  ///< vehicles that may hold this width at once; 0 = unlimited (D20)
  OptionsSummaryEntry as_written;  ///< value texts as configured (D21)
};

/// Parse result of one `sensor_config` value.
struct SensorConfigParse {
  std::optional<SensorOption> option;
  std::string error;                  ///< names the field and value (empty when accepted)
  std::vector<std::string> warnings;  ///< unknown keys (the option still loads)
};

/// `width=25, exp=4, pclass=0.80[, max=1]`; `class` = `pclass`; keys case-insensitive, any order.
/// Validation (differences.md "Validation"): width > 0, exp >= 1, pclass in [0.5, 1], max a
/// whole number >= 0.
SensorConfigParse parse_sensor_config(std::string_view value);

using OptionIndex = std::size_t;

class SensorOptions {
 public:
  /// Adds an option: the number of options now configured, or (changing nothing) why not when
  /// its width is taken.
  base::Result<std::size_t> add(SensorOption option);

  bool empty() const { return sorted_.empty(); }
  std::size_t size() const { return sorted_.size(); }
  /// Option `i` in width order.
  const SensorOption& option(OptionIndex i) const { return sorted_[i]; }
  const std::vector<SensorOption>& by_width() const { return sorted_; }
  /// The UHZ_OPTIONS_SUMMARY content, in configuration order (D21).
  OptionsSummary summary() const;

  /// D4: the highest width not above the average of the smallest and largest widths.
  /// Requires !empty().
  double default_width_m() const;

  /// D3/D20: among options for which `is_full` is false, the requested width (within
  /// kWidthMatchTolerance_m), else the nearest lower, else the nearest higher. nullopt when
  /// every option is full (or the table is empty).
  std::optional<OptionIndex> choose(double requested_width_m,
                                    const std::function<bool(OptionIndex)>& is_full) const;

 private:
  std::vector<SensorOption> sorted_;
  std::vector<OptionsSummaryEntry> config_order_;
};

}  // namespace hazard
