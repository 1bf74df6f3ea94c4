// The AppTick schedule of a MoosApp (contract in include/moos/app.hpp): when each cycle is due,
// and the loops that run cycles at their slots.
//
// Cycles keep the grid start + k / AppTick in MOOS time, so an app's postings do not drift. A
// loaded machine wakes an app late now and then (at warp 50 an AppTick-4 app has 5 ms real per
// period): a cycle less than kMaxCatchUpPeriods late is followed at once by the slot it overran,
// so such a wake-up costs no cycle; later than that the missed slots are skipped, so an app that
// cannot keep up is never far behind.

#include "moos/app.hpp"

namespace moos {

void MoosApp::schedule_next(double cycle_start) {
  const double period = period_moos_s_;
  const double tolerance = period * kScheduleToleranceFraction;
  const double due = due_moos_s();  // the slot this cycle had, IdleAppTick's skipping included
  const double late = cycle_start - due;
  if (late + tolerance < 0) {
    next_due_moos_s_ = cycle_start + period;  // an early (manual) cycle restarts the schedule
  } else if (late < kMaxCatchUpPeriods * period) {
    next_due_moos_s_ = due + period;  // on time, or woken late: keep the grid
  } else {
    next_due_moos_s_ = cycle_start + period;  // far behind: skip the missed slots
  }
}

bool MoosApp::cycle_if_due(double now) {
  if (now + due_tolerance_moos_s_ < due_moos_s()) return false;
  cycle_at(now);
  return true;
}

void MoosApp::run_for(double moos_s) {
  if (!comms_) return;
  Clock& clock = comms_->clock();
  const double warp = comms_->time_warp();
  const double end = moos_time() + moos_s;
  const double tolerance = kScheduleToleranceFraction / settings_.app_tick_hz;
  while (!stop_ && due_moos_s() <= end + tolerance) {
    clock.sleep_real_s((due_moos_s() - moos_time()) / warp);
    cycle();
  }
  clock.sleep_real_s((end - moos_time()) / warp);
}

void MoosApp::run_until_stopped(const std::atomic<bool>* external_stop) {
  if (!comms_) return;
  Clock& clock = comms_->clock();
  while (!stop_ && !(external_stop && *external_stop)) {
    const double wait_real = (due_moos_s() - moos_time()) / comms_->time_warp();
    if (wait_real > 0) {
      sleep_until_due(clock, wait_real);
      continue;
    }
    cycle();
  }
}

}  // namespace moos
