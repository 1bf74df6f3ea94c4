#pragma once
// A fixed survey scenario shared by the tests, the benchmark and the demo (style practice 11).
//
// Two vehicles mow a 200-object field (hazards, benign objects with resemblance, aspect-sensitive
// objects) along straight legs at 1.5 m/s: archie with the 10 m option on five legs, betty with
// the 25 m option on two. Every object lies at least 5 m inside the swath's side edges, so which
// objects a pass enters does not depend on how often poses are sampled. After the survey each
// vehicle asks for a classification of every object (refusals included; some with priorities
// and `top`). Data only: no I/O.

#include <string>
#include <vector>

#include "hazard/config.hpp"

namespace hazard {

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

/// A square field of `objects` objects on a jittered grid `spacing_m` apart, centred on the
/// origin; every third a hazard. Lines are `hazard = ...` text (for benchmarks and replays).
std::string grid_field_text(int objects, double spacing_m);

}  // namespace hazard
