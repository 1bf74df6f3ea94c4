#pragma once
// A fixed survey scenario shared by the tests and the benchmarks (its determinism hash is
// pinned). Test and bench support, not production: the `scenario_support` library, outside src/.
//
// Two vehicles mow a 200-object field (hazards, benign objects with resemblance, aspect-sensitive
// objects) along straight legs at 1.5 m/s: archie with the 10 m option on five legs, betty with
// the 25 m option on two. Every object lies at least 5 m inside the swath's side edges, so which
// objects a pass enters does not depend on how often poses are sampled. After the survey each
// vehicle asks for a classification of every object (refusals included; some with priorities
// and `top`). play_mail() replays such mail through a hazard::Driver. No I/O.

#include <functional>
#include <string>
#include <vector>

#include "hazard/config.hpp"
#include "hazard/outputs.hpp"

namespace hazard {

class Driver;

struct TimedMail {
  double time_s = 0.0;
  std::string variable;
  std::string value;
};

struct Scenario {
  std::vector<ConfigEntry> config;  ///< the uFldHazardSensor block (file "scenario.moos")
  std::vector<TimedMail> mail;      ///< sorted by time
  double end_time_s = 0.0;          ///< when the last classification can have been released
};

/// The survey with node reports at `node_report_hz` (poses on the same straight tracks).
Scenario reference_survey(double node_report_hz);

/// Plays `mail` (sorted by time) through `driver` in the caller's loop of engine.hpp:
/// iterations at now = k / `tick_hz` (> 0), k = 0, 1, ..., while now <= `end_s`, each after the
/// mail stamped at or before it, every piece delivered at its own time. `on_mail` and `on_step` (either may be
/// empty) receive the outputs of each delivery and each step call.
void play_mail(Driver& driver, const std::vector<TimedMail>& mail, double tick_hz, double end_s,
               const std::function<void(const Outputs&)>& on_mail = {},
               const std::function<void(const Outputs&)>& on_step = {});

/// A square field of `objects` objects on a jittered grid `spacing_m` apart, centred on the
/// origin; every third a hazard. Lines are `hazard = ...` text (for benchmarks and replays).
std::string grid_field_text(int objects, double spacing_m);

}  // namespace hazard
