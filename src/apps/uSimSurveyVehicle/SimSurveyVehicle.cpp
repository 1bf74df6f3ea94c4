#include "SimSurveyVehicle.hpp"

#include <cmath>

#include "hazard/messages/node_report.hpp"
#include "base/same_text.hpp"
#include "base/text.hpp"
#include "mission/polygon.hpp"
#include "survey_route.hpp"

namespace usim_survey_vehicle {

namespace {

/// Node reports may come this fraction of a report interval early (the cycle grid jitters).
constexpr double kReportIntervalTolerance = 1e-6;

const std::vector<mission::ParamInfo> kAppParameters = {
    {"vname", "", "vehicle name (default: the community name)"},
    {"node_report_var", "NODE_REPORT", "variable of the node reports"},
    {"vehicle_type", "UUV", "TYPE field of the node reports"},
    {"deploy", "false", "follow the route at once (else wait for DEPLOY, DEPLOY_ALL, DEPLOY_<V>)"},
    {"done_flag", "", "VAR=value posted when the route is done (repeatable)"},
};

/// DEPLOY_<V>: the deploy flag of this vehicle alone (upper-cased like SURVEY_ROUTE_<V>).
std::string deploy_variable_for(std::string_view vname) {
  return "DEPLOY_" + base::to_upper(vname);
}

}  // namespace

const std::vector<mission::ParamInfo>& app_parameters() { return kAppParameters; }

moos::AppTraits sim_traits() { return mission_app::mission_traits(kAppName, kDefaultAppTick_hz); }

std::optional<Flag> parse_flag(std::string_view text) {
  const auto eq = text.find('=');
  if (eq == std::string_view::npos) return std::nullopt;
  Flag f{std::string(base::trim(text.substr(0, eq))),
         std::string(base::trim(text.substr(eq + 1))), std::nullopt};
  if (!mission_app::is_name(f.variable)) return std::nullopt;
  f.number = base::parse_number(f.value);
  return f;
}

SimSurveyVehicle::SimSurveyVehicle() : mission_app::MissionApp(sim_traits()) {}

std::optional<std::string> SimSurveyVehicle::apply_app_param(const moos::ConfigLine& line) {
  const std::string key = base::to_lower(line.key);
  const std::string& value = line.value;
  if (key == "vname") return mission_app::name_param(key, value, vname_, "a vehicle name");
  if (key == "node_report_var")
    return mission_app::name_param(key, value, node_report_var_, "a variable");
  if (key == "vehicle_type") return mission_app::name_param(key, value, vehicle_type_, "a type name");
  if (key == "deploy") return mission_app::bool_param(key, value, deployed_);
  if (key == "done_flag") {
    auto flag = parse_flag(value);
    if (!flag) return "parameter done_flag='" + value + "' is not VAR=value";
    done_flags_.push_back(std::move(*flag));
    return std::string();
  }
  return std::nullopt;
}

bool SimSurveyVehicle::on_start_up() {
  apply_config_lines([&](const moos::ConfigLine& line) {
    std::optional<std::string> problem = apply_app_param(line);
    return problem ? *problem
                   : mission::apply_survey_vehicle_param(config_, line.key, line.value).error;
  });
  vname_ = vehicle_name(vname_);
  // Neither changes after start-up: the report carries them from here on (no compare per report).
  report_.name = vname_;
  report_.type = vehicle_type_;
  if (const auto valid = mission::validate(config_.vehicle); !valid) {
    report_config_warning(valid.error + "; the vehicle's defaults are used");
    config_.vehicle = mission::VehicleParams{};
  }
  if (config_.report_interval_s * settings().app_tick_hz < 1.0 - kReportIntervalTolerance) {
    report_config_warning("report_interval " + base::fmt(config_.report_interval_s, 3) +
                          " s is shorter than an iteration (AppTick " +
                          base::fmt(settings().app_tick_hz, 3) +
                          "): one node report per iteration");
  }
  const std::optional<double> lat_origin_deg = settings().global_double("LatOrigin");
  const std::optional<double> lon_origin_deg = settings().global_double("LongOrigin");
  if (lat_origin_deg && lon_origin_deg)
    geodesy_.emplace(mission::GeoPoint{*lat_origin_deg, *lon_origin_deg});

  base::Result<std::vector<glm::dvec2>> route = mission::plan_route(config_);
  if (!route) {
    report_config_warning("no route: " + route.error);
  } else {
    route_m_ = std::move(*route.value);
  }
  const double now_s = cycle_time();
  last_pose_ = mission::Pose{config_.start_m, base::norm360(config_.start_heading_deg), 0.0, now_s};
  vehicle_.emplace(config_.vehicle, last_pose_);

  register_variable("DEPLOY");
  register_variable("DEPLOY_ALL");
  route_var_ = survey_route_variable_for(vname_);
  deploy_var_ = deploy_variable_for(vname_);
  register_variable(deploy_var_);
  register_variable(route_var_);
  start_route_if_ready();
  return true;
}

void SimSurveyVehicle::on_new_mail(const std::vector<moos::Message>& mail) {
  const auto is = [](const moos::Message& m, std::string_view name) {
    return base::same_text(m.key, name);
  };
  for (const moos::Message& m : mail) {
    if (is(m, route_var_)) {
      on_route(m);
    } else if (is(m, "DEPLOY") || is(m, "DEPLOY_ALL") || is(m, deploy_var_)) {
      on_deploy(m);
    }
  }
}

void SimSurveyVehicle::on_deploy(const moos::Message& m) {
  const auto b = base::parse_bool(mission_app::mail_text(m));
  if (!b) {
    report_run_warning(m.key + "='" + base::excerpt(mission_app::mail_text(m)) + "' is not true or false");
    return;
  }
  if (!*b) return;  // DEPLOY=false before deployment: nothing to stop
  if (!deployed_) report_event("Deployed (" + m.key + ")");
  deployed_ = true;
  start_route_if_ready();
}

void SimSurveyVehicle::on_route(const moos::Message& m) {
  auto points = mission::parse_points(mission_app::mail_text(m));
  if (!points) {
    report_run_warning(m.key + " ignored: " + points.error);
    return;
  }
  route_m_ = std::move(*points.value);
  route_started_ = false;
  ++routes_received_;
  report_event("New route with " + std::to_string(route_m_.size()) + " waypoints");
  start_route_if_ready();
}

void SimSurveyVehicle::start_route_if_ready() {
  if (!deployed_ || route_started_ || route_m_.empty() || !vehicle_) return;
  vehicle_->set_waypoints(route_m_);
  route_started_ = true;
  done_posted_ = false;
}

void SimSurveyVehicle::on_iterate() {
  const double now_s = cycle_time();
  last_pose_ = vehicle_->advance_to(now_s);
  if (!last_report_s_ ||
      now_s - *last_report_s_ >= config_.report_interval_s * (1.0 - kReportIntervalTolerance)) {
    post_node_report(last_pose_);
    last_report_s_ = now_s;
  }
  if (route_started_ && vehicle_->done() && !done_posted_) post_done_flags();
}

void SimSurveyVehicle::post_node_report(const mission::Pose& pose) {
  hazard::NodeReport& r = report_;  // its name and type are set at start-up
  r.x_m = pose.position_m.x;
  r.y_m = pose.position_m.y;
  r.speed_mps = pose.speed_mps;
  r.heading_deg = pose.heading_deg;
  r.lat_deg.reset();
  r.lon_deg.reset();
  if (geodesy_ && report_lat_lon_) {
    const mission::GeoPoint geo = geodesy_->to_geo(pose.position_m);
    r.lat_deg = geo.lat_deg;
    r.lon_deg = geo.lon_deg;
  }
  r.time_s = pose.time_s;
  std::string text = share_node_report_parses_ ? hazard::NodeReportMemo::this_thread().format(r)
                                               : hazard::format_node_report(r);
  notify(node_report_var_, std::move(text));  // the text moves on, uncopied
  ++node_reports_posted_;
}

void SimSurveyVehicle::post_done_flags() {
  done_posted_ = true;
  mission::Outputs out;
  for (const Flag& f : done_flags_) {
    if (f.number) {
      out.post_double(f.variable, *f.number);
    } else {
      out.post(f.variable, f.value);
    }
  }
  out.events.push_back("Route done at " + base::fmt(seconds_since_start(), 1) + " s");
  publish(out);
}

std::string SimSurveyVehicle::build_report() {
  if (!vehicle_) return {};
  std::string state;
  if (!deployed_) {
    state = "waiting for DEPLOY";
  } else if (!route_started_) {
    state = "idle, waiting for " + route_var_;
  } else if (vehicle_->done()) {
    state = "done";
  } else {
    state = "waypoint " + std::to_string(vehicle_->waypoints_reached() + 1) + " of " +
            std::to_string(vehicle_->waypoints().size());
  }
  std::string out;
  out += "Vehicle:  " + vname_ + " (" + vehicle_type_ + ")\n";
  out += "State:    " + state + "\n";
  out += "Pose:     x=" + base::fmt(last_pose_.position_m.x, 1) +
         " y=" + base::fmt(last_pose_.position_m.y, 1) +
         " hdg=" + base::fmt(last_pose_.heading_deg, 1) +
         " spd=" + base::fmt(last_pose_.speed_mps, 2) + "\n";
  out += "Reports:  " + std::to_string(node_reports_posted_) + " " + node_report_var_ + "\n";
  out += "Routes:   " + std::to_string(routes_received_) + " received\n";
  out += std::string("Geodesy:  ") + (geodesy_ ? "LAT/LON from LatOrigin/LongOrigin" : "no origin, no LAT/LON") + "\n";
  return out;
}

}  // namespace usim_survey_vehicle
