// Quiet time: until when the engine's iterations would do nothing (engine.hpp, quiet_until_s).
//
// A step does four things (Engine::step): the options summary when due, sensing for active
// vehicles, releasing queued answers, and the next batch of field visuals. Without new mail the
// last three can only start while a sensor is active, an answer is queued or visuals are
// pending, and an inactive vehicle's sensing only collapses its track, which the step after the
// next mail does as well. So the engine is quiet until the summary falls due exactly when none
// of the three holds.

#include <algorithm>

#include "hazard/engine.hpp"

namespace hazard {

double Engine::quiet_until_s(double now_s) const {
  if (field_visuals_pending() > 0) return now_s;
  for (const VehicleState& v : vehicles_) {
    if (active(v, now_s) || !v.queue.empty()) return now_s;
  }
  if (!last_summary_s_) return now_s;
  return std::max(now_s, *last_summary_s_ + config_.options_summary_interval_s);
}

}  // namespace hazard
