#include "hazard/heading_history.hpp"

#include <cmath>

#include "base/text.hpp"
#include "hazard/time_rules.hpp"

namespace hazard {

void HeadingHistory::add(double heading_deg, double time_s) {
  if (!samples_.empty() && !(time_s > samples_.back().time_s)) return;
  samples_.push_back({heading_deg, time_s});
  // Inside the window means newest - t < window (strict, spec 8.2), allowing for clock rounding
  // (time_rules.hpp), so the window holds the same number of samples all day at epoch times.
  while (samples_.size() > kMaxSamples ||
         elapsed_at_least(time_s, samples_.front().time_s, kTurnWindow_s)) {
    samples_.pop_front();
  }
}

double HeadingHistory::turn_rate_dps() const {
  if (samples_.size() < 2) return 0.0;
  double sum_deg = 0.0;
  for (std::size_t i = 1; i < samples_.size(); ++i) {
    sum_deg += std::fabs(base::norm180(samples_[i].heading_deg - samples_[i - 1].heading_deg));
  }
  const double span_s = samples_.back().time_s - samples_.front().time_s;
  return span_s > 0.0 ? sum_deg / span_s : 0.0;
}

}  // namespace hazard
