// IdleAppTick (ours, opt-in; contract in include/moos/app.hpp): a quiet app skips AppTick slots.
//
// Why: at warp W an app cycles W x AppTick times per real second, and each cycle wakes two
// threads and posts _ITER_GAP and _ITER_LEN, so a sensor with nothing to do costs more than a
// busy one's sensing. Skipping only slots at which iterate() would do nothing, and only whole
// slots of the grid, keeps every posting of the app itself at the time it would have had.

#include <algorithm>
#include <cmath>

#include "moos/app.hpp"

namespace moos {

double MoosApp::grid_slot_at_or_after(double t) const {
  if (t <= next_due_moos_s_) return next_due_moos_s_;
  const double period = period_moos_s_;
  const double periods = std::ceil((t - next_due_moos_s_) / period - kScheduleToleranceFraction);
  return next_due_moos_s_ + periods * period;
}

double MoosApp::idle_due_moos_s() const {
  // Mail (or a reconnect) waits: the slot it would have had without the option, the first one
  // at or after its arrival (the slots skipped before it had nothing to do). Fixed by the
  // arrival, not by the clock, or a loop that wakes just after a slot would chase the next one.
  if (mail_waiting()) return grid_slot_at_or_after(first_mail_moos_s_.load());
  return grid_slot_at_or_after(*idle_resume_moos_s_);
}

void MoosApp::plan_idle(double cycle_start_moos_s) {
  if (!comms_ || !comms_->is_connected()) return;
  const double quiet_until = quiet_until_moos_s(cycle_start_moos_s);
  const double resume =
      std::min(cycle_start_moos_s + 1.0 / *settings_.idle_app_tick_hz, quiet_until);
  if (resume > next_due_moos_s_) idle_resume_moos_s_ = resume;
}

void MoosApp::note_mail() {
  // Only the first arrival counts: a stream of mail must not postpone its own handling. A race
  // with the fetch can only make the recorded time earlier, which makes the cycle earlier.
  if (!mail_signal_.pending()) first_mail_moos_s_ = comms_->moos_time();
  mail_signal_.notify();
}

void MoosApp::sleep_until_due(Clock& clock, double real_s) {
  if (idle_resume_moos_s_ && !mail_waiting()) {
    clock.sleep_real_s_unless_woken(real_s, mail_signal_);
  } else {
    // Due at a slot anyway: mail must not shorten the wait.
    clock.sleep_real_s(std::min(real_s, kMaxLoopSleep_real_s));
  }
}

}  // namespace moos
