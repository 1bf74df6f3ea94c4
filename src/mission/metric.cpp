// The grader. Contract: include/mission/metric.hpp.

#include "mission/metric.hpp"

#include <algorithm>
#include <string_view>
#include <unordered_set>

#include "hazard/messages/view_polygon.hpp"
#include "base/text.hpp"
#include "mission/messages/hazard_search.hpp"

namespace mission {

namespace {

struct NumberParam {
  ParamInfo info;
  double MetricConfig::*field;
};

const std::vector<NumberParam>& number_params() {
  static const std::vector<NumberParam> rows = {
      {{"penalty_missed_hazard", "100", "penalty for each hazard not reported"},
       &MetricConfig::penalty_missed_hazard},
      {{"penalty_false_alarm", "10", "penalty for each benign object reported"},
       &MetricConfig::penalty_false_alarm},
      {{"penalty_nonopt_hazard", "50", "echoed in UHZ_MISSION_PARAMS, never scored"},
       &MetricConfig::penalty_nonopt_hazard},
      {{"penalty_max_time_over", "0", "penalty once the search time exceeds max_time"},
       &MetricConfig::penalty_max_time_over},
      {{"penalty_max_time_rate", "0", "penalty per second over max_time"},
       &MetricConfig::penalty_max_time_rate},
      {{"max_time", "0", "search time limit in seconds (0 = no limit)"}, &MetricConfig::max_time_s},
  };
  return rows;
}

const ParamInfo kShowXpath{"show_xpath", "false", "draw the minimum-hazard transit lane"};
const ParamInfo kHazardFile{"hazard_file", "", "ground truth (the sensor's hazard file)"};

// `//` comments are stripped from hazard files (as uFldHazardMetric does).
std::string_view without_comment(std::string_view line) {
  const auto pos = line.find("//");
  return pos == std::string_view::npos ? line : line.substr(0, pos);
}

}  // namespace

const std::vector<ParamInfo>& metric_parameters() {
  static const std::vector<ParamInfo> infos = [] {
    std::vector<ParamInfo> out = param_infos(number_params());
    out.push_back(kShowXpath);
    out.push_back(kHazardFile);
    return out;
  }();
  return infos;
}

HazardMetric::ConfigResult HazardMetric::configure(std::string_view key, std::string_view value) {
  const std::string name = base::to_lower(base::trim(key));
  value = base::trim(value);
  if (name == kHazardFile.name) return {"", std::string(value)};
  ConfigResult result;
  // Only applied lines count as settings; a rejected line does not make the next one a repeat.
  const bool repeated = std::find(seen_keys_.begin(), seen_keys_.end(), name) != seen_keys_.end();
  auto warn = [&](std::string text) {
    result.warning = std::move(text);
    return result;
  };
  if (name == kShowXpath.name) {
    const auto v = base::parse_bool(value);
    if (!v) return warn("parameter show_xpath='" + std::string(value) + "' is not true or false");
    config_.show_xpath = *v;
  } else {
    const auto row = std::find_if(number_params().begin(), number_params().end(),
                                  [&](const NumberParam& p) { return name == p.info.name; });
    if (row == number_params().end())
      return warn("unknown parameter '" + std::string(base::trim(key)) + "'");
    const auto v = base::parse_number(value);
    const std::string keeps = "; keeps " + base::fmt(config_.*(row->field));
    const std::string text(value);
    if (!v) return warn("parameter " + name + "='" + text + "' is not a number" + keeps);
    if (*v < 0.0) return warn("parameter " + name + "=" + text + " must be >= 0" + keeps);
    config_.*(row->field) = *v;
  }
  seen_keys_.push_back(name);
  if (repeated) {
    result.warning = "parameter " + name + " is repeated; the last value (" + std::string(value) +
                     ") is used";
  }
  return result;
}

std::vector<std::string> HazardMetric::load_hazard_file(std::string_view file_name,
                                                       std::string_view text) {
  std::vector<std::string> warnings;
  hazard::load_hazard_file_text(text, file_name, truth_, warnings);
  if (first_file_.empty()) first_file_ = std::string(file_name);
  int line_number = 0;
  for (std::string_view raw : base::split_trimmed(text, '\n')) {
    ++line_number;
    const std::string_view line = base::trim(without_comment(raw));
    const auto eq = line.find('=');
    if (eq == std::string_view::npos) continue;
    const std::string_view left = base::trim(line.substr(0, eq));
    const std::string_view right = base::trim(line.substr(eq + 1));
    if (base::iequals(left, "source")) {
      source_ = std::string(right);
    } else if (base::iequals(left, "region")) {
      auto parsed = ConvexPolygon::parse(right);
      if (!parsed) {
        warnings.push_back(std::string(file_name) + ":" + std::to_string(line_number) +
                           ": bad region spec: " + parsed.error);
      } else {
        region_ = std::move(parsed.value);
      }
    }
  }
  return warnings;
}

std::string HazardMetric::hazard_file_missing(std::string_view file_name) {
  return "Reading " + std::string(file_name) + ": Empty or File Not found.";
}

double HazardMetric::worst_score() const {
  return config_.penalty_false_alarm * truth_.benign_count() +
         config_.penalty_missed_hazard * truth_.hazard_count();
}

MissionParams HazardMetric::mission_params() const {
  MissionParams p;
  p.penalty_missed_hazard = config_.penalty_missed_hazard;
  p.penalty_nonopt_hazard = config_.penalty_nonopt_hazard;
  p.penalty_false_alarm = config_.penalty_false_alarm;
  p.penalty_max_time_over = config_.penalty_max_time_over;
  p.max_time_s = config_.max_time_s;
  p.penalty_max_time_rate = config_.penalty_max_time_rate;
  p.transit_path_width_m = kTransitPathWidth_m;
  if (region_) p.search_region = region_->spec_pts();
  return p;
}

Outputs HazardMetric::start(double now_s) {
  Outputs out;
  start_s_ = now_s;
  if (source_.empty()) source_ = first_file_;
  if (region_) {
    std::vector<glm::dvec2> hazards;
    for (hazard::ObjectId id = 0; id < truth_.size(); ++id)
      if (truth_.is_hazard(id)) hazards.push_back(truth_.position(id));
    lane_ = min_hazard_lane(*region_, hazards, kTransitPathWidth_m);
    hazard::ViewPolygon poly;
    poly.points = region_->vertices();
    poly.label = "search_region";
    poly.edge_color = "gray45";
    poly.edge_size = 1.0;
    out.post("VIEW_POLYGON", hazard::format_view_polygon(poly));
    if (config_.show_xpath && lane_) {
      hazard::ViewPolygon lane;
      lane.points = transit_lane_corners(*region_, lane_->x_m, kTransitPathWidth_m);
      lane.label = "min_path";
      lane.fill_color = "yellow";
      lane.fill_transparency = 0.12;
      out.post("VIEW_POLYGON", hazard::format_view_polygon(lane));
    }
  }
  out.post(kMissionParamsVar, format_mission_params(mission_params()));
  out.events.push_back("Ground truth: " + std::to_string(truth_.hazard_count()) + " hazards, " +
                       std::to_string(truth_.benign_count()) + " benign objects");
  return out;
}

Outputs HazardMetric::iterate(long iteration, double /*now_s*/) {
  Outputs out;
  if (iterate_posts(iteration))
    out.post(kMissionParamsVar, format_mission_params(mission_params()));
  return out;
}

Outputs HazardMetric::on_search_start(double now_s) {
  Outputs out;
  search_start_s_ = now_s;
  out.events.push_back("Search started");
  return out;
}

HazardsetEval HazardMetric::evaluate(const HazardsetReport& report, double now_s) const {
  HazardsetEval e;
  e.vname = report.source;
  e.report_name = report.name;
  // The report's labels, collected once: HazardsetReport::has_label per truth object would cost
  // truth x report comparisons (50 million for a 10,000-object field and a 5,000-object report).
  std::unordered_set<std::string_view> reported_labels;
  for (const ReportedObject& r : report.objects)
    if (r.label) reported_labels.insert(*r.label);
  for (hazard::ObjectId id = 0; id < truth_.size(); ++id) {
    const hazard::HazardObject truth = truth_.object(id);
    ObjectEval o{truth.label, hazard::type_name(truth.type), reported_labels.count(truth.label) > 0,
                 std::nullopt};
    if (o.reported && truth.is_hazard()) {
      ++e.correct_hazards;
    } else if (o.reported) {
      ++e.false_alarms;
      o.penalty = config_.penalty_false_alarm;
    } else if (truth.is_hazard()) {
      ++e.missed_hazards;
      o.penalty = config_.penalty_missed_hazard;
    }
    e.object_report.push_back(std::move(o));
  }
  e.score_missed_hazards = static_cast<double>(e.missed_hazards) * config_.penalty_missed_hazard;
  e.score_false_alarms = static_cast<double>(e.false_alarms) * config_.penalty_false_alarm;
  const double elapsed_s = search_start_s_ ? now_s - *search_start_s_ : 0.0;
  const double overage_s = config_.max_time_s > 0.0 ? elapsed_s - config_.max_time_s : 0.0;
  if (overage_s > 0.0)
    e.score_time_overage =
        config_.penalty_max_time_over + config_.penalty_max_time_rate * overage_s;
  e.total_score = e.score_missed_hazards + e.score_false_alarms + e.score_time_overage;
  const double worst = worst_score();
  if (worst > 0.0) {
    e.norm_score = std::clamp(100.0 * (worst - e.total_score) / worst, 0.0, 100.0);
  } else {
    e.norm_score = e.total_score > 0.0 ? 0.0 : 100.0;  // worst = 0 (see the header)
  }
  e.total_objects = static_cast<long>(report.objects.size());
  e.total_time_s = elapsed_s;
  e.received_time_s = start_s_ ? now_s - *start_s_ : 0.0;
  e.start_time_s = search_start_s_ && start_s_ ? *search_start_s_ - *start_s_ : 0.0;
  e.penalty_false_alarm = config_.penalty_false_alarm;
  e.penalty_missed_hazard = config_.penalty_missed_hazard;
  e.penalty_max_time_over = config_.penalty_max_time_over;
  e.penalty_max_time_rate = config_.penalty_max_time_rate;
  e.max_time_s = config_.max_time_s;
  return e;
}

Outputs HazardMetric::on_hazardset_report(std::string_view text, double now_s) {
  Outputs out;
  HazardsetReport report = parse_hazardset_report(text);
  if (report.source.empty()) {
    out.run_warnings.push_back("Rejected HAZARDSET_REPORT: Missing Source info");
    return out;
  }
  if (report.source == "actual") {
    out.run_warnings.push_back("Rejected HAZARDSET_REPORT: Source claims to be actual");
    return out;
  }
  if (report.objects.empty()) {
    out.events.push_back("Warning: HAZARDSET_REPORT of size zero received from " + report.source);
    return out;
  }
  ++reports_received_;
  SourceRecord& record = sources_[report.source];
  record.eval = evaluate(report, now_s);
  record.report = std::move(report);
  ++record.reports_received;
  const std::string suffix = "_" + base::to_upper(record.eval.vname);
  out.post_double(kHazardSearchScoreVar, record.eval.norm_score);
  const std::string full = format_hazardset_eval_full(record.eval);
  const std::string brief = format_hazardset_eval(record.eval);
  out.post(kHazardsetEvalFullVar, full);
  out.post(std::string(kHazardsetEvalFullVar) + suffix, full);
  out.post(kHazardsetEvalVar, brief);
  out.post(std::string(kHazardsetEvalVar) + suffix, brief);
  out.events.push_back("Received valid report from: " + record.eval.vname + " (score " +
                       base::fmt(record.eval.norm_score, 2) + ")");
  return out;
}

}  // namespace mission
