#pragma once
// Heading history and turn rate (manual 8; docs/differences.md, "Geometry and sensing").
//
// Contract: samples (heading, receipt time) are kept only while they can matter: those within
// kTurnWindow_s of the newest sample (at most kMaxSamples). A sample is added only if its time is
// strictly after the newest (several reports in one mail batch count once). The turn rate is the
// sum of absolute heading steps |base::norm180(h_i - h_(i-1))| over the samples inside the window,
// divided by the time from the oldest sample inside the window to the newest; 0 when that time
// is 0 (one sample). It is anchored at the newest sample, not at "now" (frozen if reports stop),
// and it wraps correctly across 0/360 (norm180 of each step: 359.9 -> 0.1 is a 0.2 deg step).
// "Within the window" allows for clock rounding (time_rules.hpp).
// Cost: each step is computed once, when its sample arrives, and the samples lie in one array
// (the gate reads about 20 of them per iteration at 10 Hz node reports); the sum is taken in
// sample order, so the rate is the same double as summing the steps afresh. A window whose steps
// are all zero (a straight leg: the common case) is known by a count and its sum is not taken:
// it would be +0.0, and so is the rate.

#include <cstddef>
#include <vector>

namespace hazard {

class HeadingHistory {
 public:
  /// Turn-rate window (manual 8: "defined over the previous 2 seconds").
  static constexpr double kTurnWindow_s = 2.0;
  /// Bound on memory if reports arrive absurdly fast.
  static constexpr std::size_t kMaxSamples = 1000;

  void add(double heading_deg, double time_s);
  /// deg/s, >= 0.
  double turn_rate_dps() const;
  std::size_t size() const { return samples_.size() - first_; }

 private:
  struct Sample {
    double heading_deg;
    double time_s;
    double step_deg;  ///< |norm180(heading - the previous sample's)|; 0 for the first sample
  };
  /// Frees the storage of the dropped samples (before first_).
  void reclaim();

  std::vector<Sample> samples_;  ///< oldest first, from first_ on
  std::size_t first_ = 0;
  /// Non-zero steps among the window's summed steps (samples after first_).
  std::size_t turning_steps_ = 0;
};

}  // namespace hazard
