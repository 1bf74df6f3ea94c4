#pragma once
// hazard_replay: the options and the replay loop (the command line: args.hpp; the rules:
// docs/differences.md, "hazard_replay", and docs/configuration.md, "Running offline").
//
// With --seeds=A..B the same replay runs once per seed and, instead of the .alog, writes one
// JSON line per seed: {"seed":S,"detections":D,"classifications":C}, with ,"score":X before the
// brace under --score when the input holds a report the metric grades (score.hpp).
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

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hazard/driver.hpp"
#include "moos/alog.hpp"

namespace hazard_replay {

inline constexpr const char* kDefaultAppName = "uFldHazardSensor";

/// The most input --seeds holds, in bytes of entries (their text and about 40 bytes a line): it
/// replays the input once per seed. A single replay holds only a reorder window of its log
/// (input_log.hpp), whatever the log's size.
inline constexpr std::size_t kMaxInputLogBytes = std::size_t{4} << 30;

/// Seeds first..last, both included.
struct SeedRange {
  std::uint64_t first = 0;
  std::uint64_t last = 0;
};
/// Bound on one --seeds run (a mistyped range must not run for days).
inline constexpr std::uint64_t kMaxSeedsPerRun = 1000000;

struct Options {
  std::string config_path;
  std::string input_path;
  std::string app_name = kDefaultAppName;
  std::optional<std::uint64_t> seed;
  /// --seeds=A..B: one replay per seed, one JSON line each instead of the .alog (seeds.cpp).
  std::optional<SeedRange> seeds;
  /// --score (with --seeds): each line also carries the metric's score of the input's report
  /// (score.hpp).
  bool score = false;
  std::optional<double> until_s;
  std::optional<std::string> output_path;
  /// `--NAME=value` arguments (NAME starting with a capital letter): `$(NAME)` in CONFIG.moos,
  /// as a MOOS app takes them from pAntler's command line.
  std::map<std::string, std::string> substitutions;
  bool help = false;
  bool version = false;  ///< --version: print the release and exit
};

/// The input mail in time order and the iteration times: t0 + k / tick_hz up to end_s.
struct Timeline {
  const std::vector<hazard::Mail>* mail = nullptr;  ///< views into the input's text
  double start_s = 0.0;
  double end_s = 0.0;
  double tick_hz = 4.0;
};

/// The replay loop (contract above): start, then mail and iterations in time order; every
/// call's outputs go to `sink`. Nothing when there is no mail.
void replay(hazard::Driver& driver, const Timeline& timeline,
            const std::function<void(const hazard::TimedOutputs&)>& sink);

/// What the streamed loop left out: mail more than kMaxIterations iterations after the first
/// (a time no run reaches; the rest of the replay goes on).
struct StreamCounts {
  std::size_t too_far = 0;
};

/// The same loop over mail that arrives one at a time (`next_mail` gives nullptr at the end), in
/// time order, with the end at `until_s` or else at the last mail: no mail is held, so a log of
/// any size replays in bounded memory. Mail after `until_s` is read and not delivered.
StreamCounts replay_stream(hazard::Driver& driver,
                           const std::function<const hazard::Mail*()>& next_mail,
                           std::optional<double> until_s, double tick_hz,
                           const std::function<void(const hazard::TimedOutputs&)>& sink);

/// What one seed's replay produced (--seeds): detection and classification reports, counted
/// once each (the un-suffixed UHZ_DETECTION_REPORT and UHZ_HAZARD_REPORT postings).
struct SeedCounts {
  std::uint64_t detections = 0;
  std::uint64_t classifications = 0;
};

/// The engine one seed of a study runs: `built` with `seed`, building no posting text the JSON
/// line does not read (hazard::PostingReaders::kReportCounts: no visuals); its reports, and so
/// the line, are those of the same seed's .alog replay.
hazard::Engine study_engine(const hazard::Engine& built, std::uint64_t seed);

/// Replays `timeline` through `driver`, counting its reports (seeds.cpp).
SeedCounts count_reports(hazard::Driver& driver, const Timeline& timeline);

/// One JSON line, `{"seed":S,"detections":D,"classifications":C}`, or with `score`
/// `{"seed":S,"detections":D,"classifications":C,"score":X}` (X the shortest exact decimal);
/// no newline.
std::string seed_summary_json(std::uint64_t seed, const SeedCounts& counts,
                              std::optional<double> score = std::nullopt);

/// Runs the replay; writes the .alog to `out` and diagnostics to `err`. Returns the exit code
/// (0 done, 1 a file or block problem).
int run(const Options& options, std::ostream& out, std::ostream& err);

}  // namespace hazard_replay
