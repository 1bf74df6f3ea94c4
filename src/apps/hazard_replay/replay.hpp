#pragma once
// hazard_replay: the options and the replay loop (the command line: args.hpp) (issue 2; rulings "hazard_replay
// output", "Release timing", "Seeds").
//
// Contract: the loop delivers each input line at its time through hazard::Driver::deliver, the
// same entry point the app uses, and runs Driver::step at t0 + k / AppTick (k = 0, 1, ...) while
// that time is at or before the end (the last input, or --until); mail stamped at or before an
// iteration's time is delivered before that iteration. Mail after the last iteration but not
// after the end is still delivered (its postings are written), with no further iteration.
// Input lines are replayed in time order (stable for equal times). The engine is built from the
// block as uFldHazardSensor builds it (app_support::make_sensor_engine); the mission file's
// LatOrigin/LongOrigin globals go to it (geodesy: LAT/LON-only node reports, lat/lon hazard
// lines). Postings are written with the time of the mail or iteration that produced them;
// warnings, events and the seed go to the error stream. Nothing depends on the wall clock except an operating-system seed when neither
// --seed, random_seed nor seed_random = false fixes one.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace hazard_replay {

inline constexpr const char* kDefaultAppName = "uFldHazardSensor";

struct Options {
  std::string config_path;
  std::string input_path;
  std::string app_name = kDefaultAppName;
  std::optional<std::uint64_t> seed;
  std::optional<double> until_s;
  std::optional<std::string> output_path;
  bool help = false;
};

/// Runs the replay; writes the .alog to `out` and diagnostics to `err`. Returns the exit code
/// (0 done, 1 a file or block problem).
int run(const Options& options, std::ostream& out, std::ostream& err);

}  // namespace hazard_replay
