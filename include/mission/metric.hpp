#pragma once
// The shoreside grader, compatible with uFldHazardMetric (docs/mission-logic.md): same
// parameters, messages and
// score formula.
//
// Contract
// - Configuration (docs/mission-logic.md): penalty_missed_hazard (100), penalty_false_alarm (10),
//   penalty_nonopt_hazard (50, echoed only), penalty_max_time_over (0), penalty_max_time_rate (0),
//   max_time (0 = no limit), show_xpath (false), hazard_file. Keys are case-insensitive. Numbers
//   follow differences.md "Numbers" and must be >= 0; a bad value is a warning naming the
//   parameter and value, and the default stays. A repeated parameter takes the last value, with a
//   warning (D36). Unknown parameters are warned. The transit-lane half width is fixed at 20 m
//   (original).
// - Ground truth: the `hazard =` lines go through libhazard's loader (load_hazard_file_text), the
//   same code the sensor uses, so the two can never disagree about which objects exist and what
//   they are. `region =` (a convex polygon, else a warning) and `source =` are read here (as
//   uFldHazardMetric reads them); `//` comments are stripped. Several hazard files load together
//   (as the sensor, differences.md "Repeats"); the last region and source win. A missing file is
//   the application's to report (`hazard_file_missing`).
// - Scoring, object by object in file order: reported label and truth hazard ->
//   correct; reported and truth benign -> false alarm; hazard not reported -> missed; extra labels
//   not in the truth are ignored. total = missed P_m + FA P_fa + overage term, where
//   elapsed = now - search start (0 if never started), overage = elapsed - max_time (0 when
//   max_time is 0), and the term is P_over + P_rate * overage when overage > 0.
//   worst = P_fa (#benign) + P_m (#hazards); norm = clip(100 (worst - total) / worst, 0, 100).
//   Fixed (differences.md N17): with worst = 0 (no objects, or zero penalties) the original divides
//   by zero and posts NaN. We define norm = 100 when total = 0 (nothing could be lost and nothing
//   was) and norm = 0 when total > 0 (only a time penalty can make total positive then).
// - Reports: an empty source or the source `actual` is rejected with a run warning; a report
//   with no object parts only logs an event and is not stored; every other report is stored per
//   source (latest wins, with a count) and answered with HAZARD_SEARCH_SCORE (double),
//   HAZARDSET_EVAL_FULL, HAZARDSET_EVAL_FULL_<SRC>, HAZARDSET_EVAL, HAZARDSET_EVAL_<SRC> (the
//   original's order). EVAL times: received_time = now - grader start, start_time = search start
//   - grader start, or 0 if the search never started (the original printed minus the grader's
//   start time, a large negative number).
// - Start-up posts VIEW_POLYGON of the region (label search_region, edge gray45), the
//   minimum-hazard lane when show_xpath (label min_path, yellow fill, transparency 0.12), and
//   UHZ_MISSION_PARAMS; `iterate` posts UHZ_MISSION_PARAMS again on every 50th iteration.

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hazard/hazard_field.hpp"
#include "mission/messages/hazardset_eval.hpp"
#include "mission/messages/hazardset_report.hpp"
#include "mission/messages/mission_params.hpp"
#include "mission/outputs.hpp"
#include "mission/params.hpp"
#include "mission/polygon.hpp"
#include "mission/transit_lane.hpp"

namespace mission {

/// The original's fixed transit-lane half width (m).
inline constexpr double kTransitPathWidth_m = 20.0;
/// UHZ_MISSION_PARAMS is re-posted on iterations that are multiples of this (original).
inline constexpr long kMissionParamsEveryIterations = 50;

struct MetricConfig {
  double penalty_missed_hazard = 100.0;
  double penalty_false_alarm = 10.0;
  double penalty_nonopt_hazard = 50.0;
  double penalty_max_time_over = 0.0;
  double penalty_max_time_rate = 0.0;
  double max_time_s = 0.0;
  bool show_xpath = false;
};

const std::vector<ParamInfo>& metric_parameters();

/// One source's latest report and its evaluation.
struct SourceRecord {
  HazardsetReport report;
  HazardsetEval eval;
  long reports_received = 0;
};

class HazardMetric {
 public:
  HazardMetric() = default;

  /// Result of one configuration line: a warning ("" if none), and the file to read for a
  /// `hazard_file` line (the application reads it and calls load_hazard_file or
  /// hazard_file_missing).
  struct ConfigResult {
    std::string warning;
    std::optional<std::string> hazard_file;
  };
  ConfigResult configure(std::string_view key, std::string_view value);
  /// Loads a hazard file's text; returns the warnings (each names file and line).
  std::vector<std::string> load_hazard_file(std::string_view file_name, std::string_view text);
  /// The original's run warning for a file that cannot be read.
  static std::string hazard_file_missing(std::string_view file_name);

  /// After configuration: computes the worst score and the lane; posts the start-up visuals and
  /// UHZ_MISSION_PARAMS. `now_s` is the grader's start time.
  Outputs start(double now_s);
  /// Posts UHZ_MISSION_PARAMS when `iteration` is a multiple of 50 (the application's count).
  Outputs iterate(long iteration, double now_s);
  /// Whether iterate(`iteration`, ...) posts anything: the other iterations need build no
  /// Outputs (an application iterates four times a second).
  static bool iterate_posts(long iteration) {
    return iteration % kMissionParamsEveryIterations == 0;
  }
  /// HAZARD_SEARCH_START (any value).
  Outputs on_search_start(double now_s);
  /// HAZARDSET_REPORT.
  Outputs on_hazardset_report(std::string_view text, double now_s);

  /// Scores a report against the truth at `now_s` (pure; used by on_hazardset_report).
  HazardsetEval evaluate(const HazardsetReport& report, double now_s) const;

  const MetricConfig& config() const { return config_; }
  const hazard::HazardField& truth() const { return truth_; }
  const std::optional<ConvexPolygon>& region() const { return region_; }
  const std::string& source() const { return source_; }
  double worst_score() const;
  std::optional<TransitLane> transit_lane() const { return lane_; }
  MissionParams mission_params() const;
  const std::map<std::string, SourceRecord>& sources() const { return sources_; }
  long reports_received() const { return reports_received_; }
  std::optional<double> search_start_s() const { return search_start_s_; }

 private:
  MetricConfig config_;
  std::vector<std::string> seen_keys_;
  hazard::HazardField truth_;
  std::optional<ConvexPolygon> region_;
  std::string source_;
  std::string first_file_;
  std::optional<TransitLane> lane_;
  std::optional<double> start_s_;
  std::optional<double> search_start_s_;
  std::map<std::string, SourceRecord> sources_;
  long reports_received_ = 0;
};

}  // namespace mission
