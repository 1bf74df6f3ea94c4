#include "HazardMetric.hpp"

#include "app_support.hpp"
#include "base/text.hpp"
#include "mission/messages/hazard_search.hpp"
#include "mission/messages/hazardset_report.hpp"

namespace ufld_hazard_metric {

moos::AppTraits metric_traits() { return mission_app::mission_traits(kAppName, kDefaultAppTick_hz); }

namespace {

void load_hazard_file(const moos::ConfigLine& line, const std::string& file,
                      const hazard::HazardFileReader& read, ConfiguredMetric& c) {
  c.hazard_files.push_back(file);
  const auto text = read(file);
  if (!text) {
    c.run_warnings.push_back(mission::HazardMetric::hazard_file_missing(file));
    c.config_warnings.push_back(
        mission_app::at_line(line, "cannot read hazard_file '" + file + "': " + text.error));
    return;
  }
  for (std::string& w : c.metric.load_hazard_file(file, *text.value))
    c.config_warnings.push_back(std::move(w));
}

}  // namespace

ConfiguredMetric configure_metric(const std::vector<moos::ConfigLine>& lines,
                                  const hazard::HazardFileReader& read) {
  ConfiguredMetric c;
  for (const moos::ConfigLine& line : lines) {
    const mission::HazardMetric::ConfigResult r = c.metric.configure(line.key, line.value);
    if (!r.warning.empty()) c.config_warnings.push_back(mission_app::at_line(line, r.warning));
    if (r.hazard_file) load_hazard_file(line, *r.hazard_file, read, c);
  }
  return c;
}

HazardMetricApp::HazardMetricApp(MetricSource source)
    : mission_app::MissionApp(metric_traits()), source_(std::move(source)) {}

bool HazardMetricApp::on_start_up() {
  ConfiguredMetric c =
      source_ ? source_(config_lines(), settings().mission_directory)
              : configure_metric(config_lines(),
                                 app_support::mission_relative_reader(settings().mission_directory));
  metric_ = std::move(c.metric);
  hazard_files_ = std::move(c.hazard_files);
  for (const std::string& w : c.config_warnings) report_config_warning(w);
  for (const std::string& w : c.run_warnings) report_run_warning(w);
  register_variable(mission::kHazardsetReportVar);
  register_variable(mission::kHazardSearchStartVar);
  publish(metric_.start(cycle_time()));
  return true;
}

void HazardMetricApp::on_new_mail(const std::vector<moos::Message>& mail) {
  const double now_s = cycle_time();
  for (const moos::Message& m : mail) {
    const std::string text = mission_app::mail_text(m);
    if (m.key == mission::kHazardsetReportVar) {
      publish(metric_.on_hazardset_report(text, now_s));
    } else if (m.key == mission::kHazardSearchStartVar) {
      publish(metric_.on_search_start(now_s));
    }
  }
}

void HazardMetricApp::on_iterate() {
  const auto iteration = static_cast<long>(this->iteration());
  if (mission::HazardMetric::iterate_posts(iteration))
    publish(metric_.iterate(iteration, cycle_time()));
}

std::string HazardMetricApp::build_report() {
  const mission::MetricConfig& c = metric_.config();
  std::string out;
  out += "Hazard file:  " + (metric_.source().empty() ? std::string("(none)") : metric_.source()) +
         "\n";
  out += "    Hazard:   " + std::to_string(metric_.truth().hazard_count()) + "\n";
  out += "    Benign:   " + std::to_string(metric_.truth().benign_count()) + "\n";
  out += "Penalties:    missed hazard " + base::fmt(c.penalty_missed_hazard) + ", false alarm " +
         base::fmt(c.penalty_false_alarm) + ", max_time " + base::fmt(c.max_time_s, 2) +
         " (over " + base::fmt(c.penalty_max_time_over) + ", rate " +
         base::fmt(c.penalty_max_time_rate) + ")\n";
  out += "Worst score:  " + base::fmt(metric_.worst_score(), 2) + "\n";
  out += "Search start: " +
         (metric_.search_start_s()
              ? base::fmt(*metric_.search_start_s() - start_time(), 2) + " s after start-up"
              : std::string("not started")) +
         "\n\n";
  out += "Source      Reports  Score   Correct  Missed  False alarms\n";
  out += "----------  -------  ------  -------  ------  ------------\n";
  using mission_app::column;
  for (const auto& [source, record] : metric_.sources()) {
    const mission::HazardsetEval& e = record.eval;
    out += column(source, 12) + column(std::to_string(record.reports_received), 9) +
           column(base::fmt(e.norm_score, 2), 8) + column(std::to_string(e.correct_hazards), 9) +
           column(std::to_string(e.missed_hazards), 8) + std::to_string(e.false_alarms) + "\n";
  }
  if (metric_.sources().empty()) out += "(no reports yet)\n";
  return out;
}

}  // namespace ufld_hazard_metric
