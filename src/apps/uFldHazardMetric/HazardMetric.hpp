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
// - A host that runs many missions over one field (hazard_study) may pass a MetricSource: the
//   grader is then configured by it instead of configure_metric (the same grader, warnings and
//   files, e.g. a copy of one configured once), so a large field is not loaded per mission.
// - Start-up: HazardMetric::start at the start-up time; its postings (the search region's
//   VIEW_POLYGON, the transit lane with show_xpath, UHZ_MISSION_PARAMS) are sent as soon as the
//   client is connected (mission_app::MissionApp).
// - Mail: HAZARDSET_REPORT and HAZARD_SEARCH_START are handed over with the cycle's time (the
//   original stamps them when it handles its mail). Iterate: HazardMetric::iterate with the
//   iteration count (UHZ_MISSION_PARAMS every 50th).
// - Everything the grader decides is posted in order: HAZARD_SEARCH_SCORE as a MOOS double, the
//   rest as strings.

#include <functional>
#include <string>
#include <vector>

#include "hazard/config.hpp"
#include "mission/metric.hpp"
#include "mission_app.hpp"

namespace ufld_hazard_metric {

inline constexpr const char* kAppName = "uFldHazardMetric";
/// The original's AppTick (UHZ_MISSION_PARAMS every 50 iterations, 12.5 s).
inline constexpr double kDefaultAppTick_hz = 4.0;

moos::AppTraits metric_traits();

/// The grader as a block's lines configure it, with what configuring it reported, in order.
struct ConfiguredMetric {
  mission::HazardMetric metric;
  std::vector<std::string> hazard_files;     ///< as the hazard_file lines name them
  std::vector<std::string> config_warnings;  ///< each naming its file and line
  std::vector<std::string> run_warnings;     ///< a hazard file that cannot be read
};

/// Every line to HazardMetric::configure in file order; each hazard_file read by `read` and
/// loaded (see the contract).
ConfiguredMetric configure_metric(const std::vector<moos::ConfigLine>& lines,
                                  const hazard::HazardFileReader& read);

/// Configures the grader from the block's lines and the mission file's folder.
using MetricSource = std::function<ConfiguredMetric(const std::vector<moos::ConfigLine>& lines,
                                                    const std::string& mission_directory)>;

class HazardMetricApp final : public mission_app::MissionApp {
 public:
  /// `source` empty: configure_metric, files read relative to the mission file's folder.
  explicit HazardMetricApp(MetricSource source = {});

  const mission::HazardMetric& metric() const { return metric_; }

 protected:
  bool on_start_up() override;
  void on_new_mail(const std::vector<moos::Message>& mail) override;
  void on_iterate() override;
  std::string build_report() override;

 private:
  MetricSource source_;
  mission::HazardMetric metric_;
  std::vector<std::string> hazard_files_;
};

}  // namespace ufld_hazard_metric
