#include "HazardMgr.hpp"

#include <algorithm>

#include "hazard/messages/config_ack.hpp"
#include "hazard/messages/detection_report.hpp"
#include "hazard/messages/hazard_report.hpp"
#include "hazard/messages/node_report.hpp"
#include "base/same_text.hpp"
#include "base/text.hpp"
#include "mission/messages/hazard_handover.hpp"
#include "mission/messages/hazardset_report.hpp"
#include "mission/messages/mission_params.hpp"
#include "mission/polygon.hpp"
#include "survey_route.hpp"

namespace phazard_mgr {

namespace {

const std::vector<mission::ParamInfo> kAppParameters = {
    {"vname", "", "vehicle name (default: the community name)"},
    {"node_report_var", "NODE_REPORT", "variable of this vehicle's node reports (own pose)"},
    {"suffixed_mail", "true", "read UHZ_*_<V> (one MOOSDB); false: bridged, un-suffixed names"},
    {"handover_to", "", "vehicle to hand the detections to after the report"},
    {"reacquire", "false", "answer a hand-over with a route to SURVEY_ROUTE_<V>"},
    {"reacquire_leg", "30", "straight run before and after each reacquired object, m (> 0)"},
    {"await_handovers_from", "", "vehicles whose hand-overs the report waits for (a,b,...)"},
    {"report_wait_max", "600", "longest wait from HAZARDSET_REQUEST to the report, s (>= 0)"},
};

}  // namespace

const std::vector<mission::ParamInfo>& app_parameters() { return kAppParameters; }

moos::AppTraits manager_traits() { return mission_app::mission_traits(kAppName, kDefaultAppTick_hz); }

HazardMgr::HazardMgr() : mission_app::MissionApp(manager_traits()) {}

std::string HazardMgr::mail_variable(const std::string& base) const {
  return app_.suffixed_mail ? base + "_" + base::to_upper(config_.vname) : base;
}

long HazardMgr::outstanding_answers() const {
  if (!manager_) return 0;
  const auto& c = manager_->counters();
  return std::max(0L, c.classify_requests - c.classify_answers);
}

std::optional<std::string> HazardMgr::apply_app_param(const moos::ConfigLine& line) {
  const std::string key = base::to_lower(line.key);
  const std::string& value = line.value;
  auto name_value = [&](std::string& field) {
    return mission_app::name_param(key, value, field, "a name");
  };
  auto bool_value = [&](bool& field) { return mission_app::bool_param(key, value, field); };
  auto number_value = [&](double& field, double low, bool low_inclusive) -> std::string {
    const auto v = base::parse_number(value);
    if (!v || *v < low || (!low_inclusive && *v == low))
      return "parameter " + key + "='" + value + "' must be a number " +
             (low_inclusive ? ">= " : "> ") + base::fmt(low);
    field = *v;
    return {};
  };
  if (key == "vname") return name_value(app_.vname);
  if (key == "node_report_var") return name_value(app_.node_report_var);
  if (key == "handover_to") return name_value(app_.handover_to);
  if (key == "suffixed_mail") return bool_value(app_.suffixed_mail);
  if (key == "reacquire") return bool_value(app_.reacquire);
  if (key == "reacquire_leg") return number_value(app_.reacquire_leg_m, 0.0, false);
  if (key == "report_wait_max") return number_value(app_.report_wait_max_s, 0.0, true);
  if (key == "await_handovers_from") {
    std::vector<std::string> names;
    for (std::string_view n : base::split_trimmed(value, ',')) {
      if (!mission_app::is_name(n)) return "parameter " + key + "='" + value + "' is not a list of names";
      names.emplace_back(n);
    }
    app_.await_handovers_from = std::move(names);
    return std::string();
  }
  return std::nullopt;
}

bool HazardMgr::on_start_up() {
  apply_config_lines([&](const moos::ConfigLine& line) {
    std::optional<std::string> problem = apply_app_param(line);
    return problem ? *problem : mission::apply_manager_param(config_, line.key, line.value).error;
  });
  config_.vname = vehicle_name(app_.vname);
  if (const auto valid = mission::validate(config_); !valid) {
    report_config_warning(valid.error + "; the manager's defaults are used");
    const std::string vname = config_.vname;
    config_ = mission::ManagerConfig{};
    config_.vname = vname;
  }
  manager_.emplace(config_);
  mail_names_ = {mail_variable("UHZ_CONFIG_ACK"), mail_variable("UHZ_DETECTION_REPORT"),
                 mail_variable("UHZ_HAZARD_REPORT"), mail_variable(mission::kHazardHandoverVar),
                 mail_variable("HAZARDSET_REQUEST")};
  for (const std::string* name :
       {&mail_names_.config_ack, &mail_names_.detection_report, &mail_names_.hazard_report,
        &mail_names_.handover, &mail_names_.hazardset_request}) {
    register_variable(*name);
  }
  register_variable(mission::kMissionParamsVar);
  register_variable(app_.node_report_var);
  return true;
}

void HazardMgr::on_new_mail(const std::vector<moos::Message>& mail) {
  const double cycle_s = cycle_time();
  for (const moos::Message& m : mail) {
    // Never later than the cycle (a foreign clock must not put mail in the future), never
    // earlier than mail already handled (the library's clocks run forward).
    const double t = std::max(last_mail_time_s_, std::min(m.time, cycle_s));
    last_mail_time_s_ = t;
    // Node reports are most of the mail: read where they lie, not copied, and without the
    // text handle() makes of the rest.
    if (m.is_string() && base::same_text(m.key, app_.node_report_var)) {
      on_node_report(m.sval, t);
    } else {
      handle(m, t);
    }
  }
}

void HazardMgr::handle(const moos::Message& m, double time_s) {
  const auto is = [&](std::string_view name) { return base::same_text(m.key, name); };
  const std::string text = mission_app::mail_text(m);
  auto warn_parse = [&](const std::string& error) {
    report_run_warning(m.key + " ignored: " + error);
  };
  if (is(app_.node_report_var)) {  // a double: on_new_mail reads the strings itself
    on_node_report(text, time_s);
  } else if (is(mail_names_.config_ack)) {
    auto ack = hazard::parse_config_ack(text);
    if (!ack) return warn_parse(ack.error);
    publish(manager_->on_config_ack(*ack.value, time_s));
  } else if (is(mail_names_.detection_report)) {
    auto report = hazard::parse_detection_report(text);
    if (!report) return warn_parse(report.error);
    publish(manager_->on_detection(*report.value, time_s));
  } else if (is(mail_names_.hazard_report)) {
    auto report = hazard::parse_hazard_report(text);
    if (!report) return warn_parse(report.error);
    publish(manager_->on_classification(*report.value, time_s));
  } else if (is(mission::kMissionParamsVar)) {
    on_mission_params(text);
  } else if (is(mail_names_.handover)) {
    on_handover(text, time_s);
  } else if (is(mail_names_.hazardset_request)) {
    if (!report_requested_s_) report_requested_s_ = time_s;
    report_event("HAZARDSET_REQUEST received");
  }
}

// uFldHazardMetric repeats UHZ_MISSION_PARAMS every few seconds, nearly always the same text.
// Applying the text that was last applied, and produced no output, again changes nothing (only
// this call sets the penalties, lane width and region), so the repeat is not parsed.
void HazardMgr::on_mission_params(const std::string& text) {
  if (applied_mission_params_ && *applied_mission_params_ == text) return;
  applied_mission_params_.reset();
  ++mission_params_parsed_;
  auto params = mission::parse_mission_params(text);
  if (!params) {
    report_run_warning(std::string(mission::kMissionParamsVar) + " ignored: " + params.error);
    return;
  }
  const mission::Outputs out = manager_->on_mission_params(*params.value);
  if (out.postings.empty() && out.events.empty() && out.run_warnings.empty() &&
      out.config_warnings.empty()) {
    applied_mission_params_ = text;
  }
  publish(out);
}

void HazardMgr::on_node_report(const std::string& text, double time_s) {
  // Every manager on one MOOSDB reads every vehicle's reports; the managers (and sensor) of one
  // process share the parse of a text.
  // (By reference: valid until the next parse, so everything is read before publish().)
  const auto& report = hazard::NodeReportMemo::this_thread().parse(text, nullptr);
  if (!report) {
    report_run_warning(app_.node_report_var + " ignored: " + report.error);
    return;
  }
  const hazard::NodeReport& r = *report.value;
  if (!base::same_text(r.name, config_.vname)) return;  // another vehicle's pose, on a shared MOOSDB
  // The pose's own time when the report carries one: never ahead of the mail time, never
  // before the previous pose (the turn-rate history runs forward).
  const double pose_s = std::max(last_pose_time_s_, r.time_s ? std::min(*r.time_s, time_s) : time_s);
  last_pose_time_s_ = pose_s;
  last_position_m_ = glm::dvec2{r.x_m, r.y_m};
  manager_->on_pose(*last_position_m_, r.heading_deg, r.speed_mps, pose_s);
  if (route_pending_) post_reacquire_route();
}

void HazardMgr::on_handover(const std::string& text, double time_s) {
  auto handover = mission::parse_handover(text);
  if (!handover) {
    report_run_warning(mail_variable(mission::kHazardHandoverVar) + " ignored: " + handover.error);
    return;
  }
  const bool for_us = handover.value->dest == config_.vname;
  publish(manager_->on_handover(*handover.value, time_s));
  if (!for_us) return;
  handovers_from_.insert(handover.value->source);
  if (app_.reacquire) {
    route_pending_ = true;
    if (last_position_m_) post_reacquire_route();
  }
}

void HazardMgr::post_reacquire_route() {
  route_pending_ = false;
  std::vector<glm::dvec2> route =
      manager_->reacquire_route(*last_position_m_, mission::ReacquireOptions{app_.reacquire_leg_m});
  // Nothing to reacquire: a route to where the vehicle is, so it is done at once (contract).
  if (route.empty()) route.push_back(*last_position_m_);
  mission::Outputs out;
  out.post(usim_survey_vehicle::survey_route_variable_for(config_.vname),
           mission::format_points(route));
  out.events.push_back("Reacquisition route with " + std::to_string(route.size()) +
                       " waypoints posted");
  publish(out);
  ++routes_posted_;
}

bool HazardMgr::report_ready(double now_s) const {
  if (!report_requested_s_) return false;
  const double waited_s = now_s - *report_requested_s_;
  if (waited_s >= app_.report_wait_max_s) return true;
  // Detections of the last passes may still be on their way (the manager's own allowance).
  if (waited_s < config_.detection_latency_s) return false;
  if (outstanding_answers() > 0) return false;
  return std::all_of(app_.await_handovers_from.begin(), app_.await_handovers_from.end(),
                     [&](const std::string& v) { return handovers_from_.count(v) > 0; });
}

void HazardMgr::post_report(double now_s) {
  if (outstanding_answers() > 0)
    report_event("Reporting with " + std::to_string(outstanding_answers()) +
                 " classification answers outstanding");
  for (const std::string& v : app_.await_handovers_from)
    if (!handovers_from_.count(v)) report_event("Reporting without a hand-over from " + v);
  publish(manager_->on_hazardset_request(now_s));
  if (!app_.handover_to.empty()) publish(manager_->handover_to(app_.handover_to));
  report_requested_s_.reset();
  ++reports_posted_;
}

void HazardMgr::on_iterate() {
  const double now_s = std::max(cycle_time(), last_mail_time_s_);
  tick_out_.clear();
  manager_->tick(now_s, tick_out_);
  publish(tick_out_);  // (nearly every tick is quiet: publish() then makes no call)
  if (report_ready(now_s)) post_report(now_s);
}

std::string HazardMgr::object_table() const {
  std::vector<mission::ObjectBelief> beliefs = manager_->beliefs();
  std::string out = "Label      X        Y        P(haz)  Det Miss H/B  Report\n";
  out += "---------- -------- -------- ------- --- ---- ----- ------\n";
  std::size_t shown = 0;
  for (const mission::ObjectBelief& b : beliefs) {
    if (shown++ == kMaxReportRows) break;
    using mission_app::column;
    out += column(b.label, 11) + column(base::fmt(b.position_m.x, 1), 9) +
           column(base::fmt(b.position_m.y, 1), 9) + column(base::fix(b.p_hazard, 3), 8) +
           column(std::to_string(b.own.detections), 4) +
           column(std::to_string(b.own.missed_passes), 5) +
           column(std::to_string(b.own.said_hazard) + "/" + std::to_string(b.own.said_benign), 6) +
           (b.reported ? "yes" : "no") + (b.handed_over ? " (handed over)" : "") + "\n";
  }
  if (beliefs.size() > kMaxReportRows)
    out += "... and " + std::to_string(beliefs.size() - kMaxReportRows) + " more objects\n";
  return out;
}

std::string HazardMgr::build_report() {
  if (!manager_) return {};
  const auto& c = manager_->counters();
  std::string out;
  out += "Vehicle:        " + config_.vname + "\n";
  out += "Sensor:         " + std::string(manager_->acked() ? "acknowledged" : "not acknowledged") +
         " (requested width " + base::fmt(config_.swath_width_m, 1) + ", pd " +
         base::fmt(config_.pd, 3) + ")\n";
  out += "Penalties:      missed hazard " + base::fmt(manager_->penalties().missed_hazard) +
         ", false alarm " + base::fmt(manager_->penalties().false_alarm) + "\n";
  out += "Detections:     " + std::to_string(c.detections) + "\n";
  out += "Classify:       " + std::to_string(c.classify_requests) + " requested, " +
         std::to_string(c.classify_answers) + " answered\n";
  out += "Passes missed:  " + std::to_string(c.missed_passes) + " counted (" +
         std::to_string(c.hindsight_passes) + " in hindsight), " +
         std::to_string(c.doubtful_passes) + " doubtful\n";
  out += "Hand-overs in:  " + std::to_string(handovers_from_.size()) + "\n";
  out += "Reports posted: " + std::to_string(reports_posted_) +
         (report_requested_s_ ? " (one requested, waiting)" : "") + "\n";
  out += "Routes posted:  " + std::to_string(routes_posted_) + "\n\n";
  return out + object_table();
}

}  // namespace phazard_mgr
