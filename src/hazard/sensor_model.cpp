#include "hazard/sensor_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/text.hpp"

namespace hazard {

// N5: pd^exp for exp up to 1e4 underflows; glibc's pow returns 0 below the subnormal range but a
// subnormal (e.g. 0.93^10000 = 1e-315) just above it, and subnormal operands cost hundreds of
// cycles in every later add or compare on x86. Such a probability is 300 orders of magnitude
// below the die's resolution (1e-4), so it is made exactly 0.
double roc_false_alarm_probability(double pd, double exp) {
  const double pfa = std::pow(pd, exp);
  return pfa < std::numeric_limits<double>::min() ? 0.0 : pfa;
}

double resemblance_false_alarm_probability(double pfa, double hr) { return (pfa + hr) / 2.0; }

double aspect_difference_deg(double heading_deg, double aspect_deg) {
  const double d = std::fabs(base::norm180(heading_deg - aspect_deg));  // [0, 180]
  return std::min(d, 180.0 - d);
}

double aspect_degradation(double diff_deg, double aspect_min_deg, double aspect_max_deg) {
  if (diff_deg <= aspect_min_deg) return 0.0;
  if (diff_deg >= aspect_max_deg) return 1.0;
  const double g = (diff_deg - aspect_min_deg) / (aspect_max_deg - aspect_min_deg);
  return std::clamp(g, 0.0, 1.0);
}

double degraded_exponent(double exp, double degradation) {
  return exp - degradation * (exp - 1.0);
}

double resemblance_classification_probability(double pc, double hr) {
  return pc + (1.0 - pc) * (1.0 - hr);
}

double aspect_classification_probability(double pc, double degradation) {
  return 0.5 + (1.0 - degradation) * (pc - 0.5);
}

}  // namespace hazard
