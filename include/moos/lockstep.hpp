#pragma once
// Lockstep scheduling of MOOS applications on an InProcessBus: whole missions in one thread,
// in simulated time, with no sockets and no wall clock (hazard_study, docs/study.md).
//
// Contract:
// - The applications are started (MoosApp::start) on clients of one InProcessBus whose clock is
//   the ManualClock given here; the lockstep owns neither.
// - step() moves the clock to the earliest due cycle of any application (MoosApp's
//   next_cycle_due_moos_s: each app at its own AppTick, IdleAppTick honoured) and runs every
//   application that is due then, in the order they were added. Mail is delivered by the bus as
//   the MOOSDB delivers it (moos::Database: order, per-source FIFO, first write, wildcards) at
//   the instant it is posted, so an app cycled later in the same instant already sees it: the
//   live mission's delivery latency is zero here.
// - The clock only moves forward, and only to due times (or to run_until's end), so the same
//   applications, configuration and inputs give the same postings, byte for byte.

#include <functional>
#include <vector>

#include "moos/app.hpp"
#include "moos/bus.hpp"
#include "moos/clock.hpp"

namespace moos {

class Lockstep {
 public:
  /// `bus` must run on `clock` (InProcessBus(clock, ...)); both outlive the lockstep.
  Lockstep(InProcessBus& bus, ManualClock& clock);

  /// Schedules a started application (its comms a client of the bus); it must outlive the
  /// lockstep.
  void add(MoosApp& app);

  /// MOOS time of the earliest due cycle; +infinity without applications.
  double next_due_moos_s() const;
  /// Moves the clock to next_due_moos_s() and cycles every application due then, in the order
  /// added. Returns the MOOS time of the step; does nothing without applications.
  double step();
  /// Steps until the next due cycle lies after `end_moos_s` or `stop()` (checked after each
  /// step) is true; then the clock stands at the last step (stopped) or at `end_moos_s`.
  /// True if `stop` ended it.
  bool run_until(double end_moos_s, const std::function<bool()>& stop = {});

  /// MOOS time now (the bus's).
  double moos_time() const { return bus_.moos_time(); }

 private:
  void set_moos_time(double moos_s);
  /// step() once the earliest due time is known.
  double step_at(double due_moos_s);

  InProcessBus& bus_;
  ManualClock& clock_;
  std::vector<MoosApp*> apps_;
};

}  // namespace moos
