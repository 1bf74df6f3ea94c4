#include "hazard/heading_history.hpp"

#include <cmath>

#include "base/text.hpp"
#include "hazard/time_rules.hpp"

namespace hazard {

void HeadingHistory::add(double heading_deg, double time_s) {
  const bool empty = first_ == samples_.size();
  if (!empty && !(time_s > samples_.back().time_s)) return;
  const double step_deg =
      empty ? 0.0 : std::fabs(base::norm180(heading_deg - samples_.back().heading_deg));
  samples_.push_back({heading_deg, time_s, step_deg});
  if (step_deg != 0.0) ++turning_steps_;
  // Inside the window means newest - t < window (strict), allowing for clock rounding
  // (time_rules.hpp), so the window holds the same number of samples all day at epoch times.
  std::size_t first = first_;
  const std::size_t end = samples_.size();
  while (end - first > kMaxSamples ||
         elapsed_at_least(time_s, samples_[first].time_s, kTurnWindow_s)) {
    ++first;
    // The new oldest sample's step leads to the dropped one: it leaves the sum.
    if (first < end && samples_[first].step_deg != 0.0) --turning_steps_;
  }
  first_ = first;
  // Reclaimed once the dropped samples outnumber the kept ones: amortised O(1) per sample, and
  // the array never holds more than twice the samples in the window (plus a few).
  constexpr std::size_t kReclaimAfter = 32;
  if (first_ >= kReclaimAfter && first_ * 2 >= end) reclaim();
}

void HeadingHistory::reclaim() {
  samples_.erase(samples_.begin(), samples_.begin() + static_cast<std::ptrdiff_t>(first_));
  first_ = 0;
}

double HeadingHistory::turn_rate_dps() const {
  if (size() < 2 || turning_steps_ == 0) return 0.0;  // a sum of +0.0 steps: +0.0
  // The first sample's step leads to one already dropped: the window's steps are the rest.
  double sum_deg = 0.0;
  for (std::size_t i = first_ + 1; i < samples_.size(); ++i) sum_deg += samples_[i].step_deg;
  const double span_s = samples_.back().time_s - samples_[first_].time_s;
  return span_s > 0.0 ? sum_deg / span_s : 0.0;
}

}  // namespace hazard
