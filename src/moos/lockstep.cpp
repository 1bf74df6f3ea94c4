#include "moos/lockstep.hpp"

#include <limits>

namespace moos {

Lockstep::Lockstep(InProcessBus& bus, ManualClock& clock) : bus_(bus), clock_(clock) {}

void Lockstep::add(MoosApp& app) { apps_.push_back(&app); }

double Lockstep::next_due_moos_s() const {
  double due = std::numeric_limits<double>::infinity();
  for (const MoosApp* app : apps_) {
    const double t = app->next_cycle_due_moos_s();
    if (t < due) due = t;
  }
  return due;
}

void Lockstep::set_moos_time(double moos_s) {
  // The clock never runs backwards: a due time already past leaves it where it is.
  clock_.set_unix_s(moos_s / bus_.time_warp());
}

double Lockstep::step() {
  if (apps_.empty()) return moos_time();
  return step_at(next_due_moos_s());
}

double Lockstep::step_at(double due_moos_s) {
  set_moos_time(due_moos_s);
  // Every app reads the bus clock, which stands still until the next step: read once.
  const double now = moos_time();
  // cycle_if_due applies the app's own tolerance, so apps on one grid cycle together.
  for (MoosApp* app : apps_) app->cycle_if_due(now);
  return now;
}

bool Lockstep::run_until(double end_moos_s, const std::function<bool()>& stop) {
  while (!apps_.empty()) {
    const double due = next_due_moos_s();  // once per step: step_at, not step
    if (!(due <= end_moos_s)) break;
    step_at(due);
    if (stop && stop()) return true;
  }
  set_moos_time(end_moos_s);
  return false;
}

}  // namespace moos
