// hazard_replay --score: the recorded reports graded as uFldHazardMetric grades them (contract in
// score.hpp).
#include "score.hpp"

#include <ostream>

#include "app_support.hpp"
#include "moos/app.hpp"
#include "mission/messages/hazard_search.hpp"
#include "mission/messages/hazardset_report.hpp"
#include "mission/metric.hpp"

namespace hazard_replay {

namespace {

std::string at(const moos::ConfigLine& line) {
  return line.file + ":" + std::to_string(line.line) + ": ";
}

// The block's lines through HazardMetric::configure, hazard files read relative to the
// mission file; an error text when a hazard file cannot be read.
std::string configure(mission::HazardMetric& metric, const moos::MissionFile& mission,
                      const moos::ProcessBlock& block, std::ostream& err) {
  const auto read = app_support::mission_relative_reader(mission.directory());
  for (const moos::ConfigLine& line : block.lines) {
    // AppTick, CommsTick, ...: the MOOS application's, never handed to the grader (app.hpp).
    if (moos::is_framework_parameter(line.key)) continue;
    const mission::HazardMetric::ConfigResult r = metric.configure(line.key, line.value);
    if (!r.warning.empty()) err << kMetricAppName << ": " << at(line) << r.warning << "\n";
    if (!r.hazard_file) continue;
    const auto text = read(*r.hazard_file);
    if (!text) {
      return at(line) + "cannot read hazard_file '" + *r.hazard_file + "': " + text.error;
    }
    for (const std::string& w : metric.load_hazard_file(*r.hazard_file, *text.value)) {
      err << kMetricAppName << ": " << w << "\n";
    }
  }
  return {};
}

// The latest HAZARD_SEARCH_SCORE among `out`'s postings, and its warnings to `err`.
void take(const mission::Outputs& out, std::optional<double>& score, std::ostream& err) {
  for (const mission::Posting& p : out.postings) {
    if (p.variable == mission::kHazardSearchScoreVar && p.number) score = *p.number;
  }
  for (const std::string& w : out.run_warnings) err << kMetricAppName << ": " << w << "\n";
}

}  // namespace

RecordedScore score_recorded_reports(const moos::MissionFile& mission,
                                     const std::vector<hazard::Mail>& mail, double end_s,
                                     std::ostream& err) {
  RecordedScore result;
  const moos::ProcessBlock* block = mission.block(kMetricAppName);
  if (!block) {
    result.error = std::string("--score needs a 'ProcessConfig = ") + kMetricAppName + "' block";
    return result;
  }
  mission::HazardMetric metric;
  result.error = configure(metric, mission, *block, err);
  if (!result.error.empty()) return result;
  if (mail.empty()) return result;
  take(metric.start(mail.front().time_s), result.score, err);
  for (const hazard::Mail& m : mail) {
    if (m.time_s > end_s) break;
    if (m.variable == mission::kHazardSearchStartVar) {
      take(metric.on_search_start(m.time_s), result.score, err);
    } else if (m.variable == mission::kHazardsetReportVar) {
      take(metric.on_hazardset_report(m.value, m.time_s), result.score, err);
    }
  }
  return result;
}

}  // namespace hazard_replay
