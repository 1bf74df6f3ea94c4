#pragma once
// HazardMetricApp: the uFldHazardMetric MOOS application, the shoreside grader, a thin adapter
// around libmission's HazardMetric (mission/metric.hpp), which holds the parameters, messages and
// score formula of the original (docs/mission-logic.md, "The grader"), its division by zero fixed.
//
// Contract
// - Configuration: every line of the block goes to HazardMetric::configure in file order; its
//   warnings become configuration warnings naming file and line. A `hazard_file` is read relative
//   to the mission file's folder and loaded (its warnings name the hazard file and line); a file
//   that cannot be read is the original's run warning (`Reading <f>: Empty or File Not found.`).
// - Start-up: HazardMetric::start at the start-up time; its postings (the search region's
//   VIEW_POLYGON, the transit lane with show_xpath, UHZ_MISSION_PARAMS) are sent as soon as the
//   client is connected (mission_app::MissionApp).
// - Mail: HAZARDSET_REPORT and HAZARD_SEARCH_START are handed over with the cycle's time (the
//   original stamps them when it handles its mail). Iterate: HazardMetric::iterate with the
//   iteration count (UHZ_MISSION_PARAMS every 50th).
// - Everything the grader decides is posted in order: HAZARD_SEARCH_SCORE as a MOOS double, the
//   rest as strings.

#include <string>

#include "mission/metric.hpp"
#include "mission_app.hpp"

namespace ufld_hazard_metric {

inline constexpr const char* kAppName = "uFldHazardMetric";
/// The original's AppTick (UHZ_MISSION_PARAMS every 50 iterations, 12.5 s).
inline constexpr double kDefaultAppTick_hz = 4.0;

moos::AppTraits metric_traits();

class HazardMetricApp final : public mission_app::MissionApp {
 public:
  HazardMetricApp();

  const mission::HazardMetric& metric() const { return metric_; }

 protected:
  bool on_start_up() override;
  void on_new_mail(const std::vector<moos::Message>& mail) override;
  void on_iterate() override;
  std::string build_report() override;

 private:
  void load_hazard_file(const moos::ConfigLine& line, const std::string& file);

  mission::HazardMetric metric_;
  std::vector<std::string> hazard_files_;
};

}  // namespace ufld_hazard_metric
