#include "hazard/engine.hpp"

#include <algorithm>
#include <cmath>

#include "hazard/messages/config_ack.hpp"
#include "hazard/messages/detection_report.hpp"
#include "hazard/messages/hazard_report.hpp"
#include "hazard/messages/options_summary.hpp"
#include "hazard/messages/sensor_clear.hpp"
#include "hazard/messages/sensor_request.hpp"
#include "hazard/messages/view_circle.hpp"
#include "hazard/messages/view_marker.hpp"
#include "hazard/messages/view_polygon.hpp"
#include "hazard/messages/view_seglist.hpp"
#include "hazard/sensor_model.hpp"
#include "base/text.hpp"
#include "hazard/time_rules.hpp"

namespace hazard {

namespace {

// Visual constants of the original (spec 5.3, 5.4) and the rulings' colours (D19).
constexpr double kCircleRadius_m = 10.0;
constexpr int kDetectionCircleVertices = 12;
constexpr int kClassificationCircleVertices = 5;  // drawn as a pentagon
constexpr double kCircleEdgeSize = 1.0;
constexpr double kCircleTransparency = 0.3;
constexpr double kAffectedEdgeSize = 2.0;        // aspect-affected classification
constexpr double kAffectedTransparency = 0.5;
constexpr double kSwathEdgeSize = 0.0;
constexpr double kMarkerFillWithoutHr = 0.5;     // benign marker fill: 1 - hr, hr absent -> 0.5
constexpr double kSeglistPartialLength_m = 15.0; // aspect axis without a window
constexpr double kSeglistBaseLength_m = 5.0;     // + 25 * (mean window / 90)
constexpr double kSeglistWindowLength_m = 25.0;
constexpr double kQuarterTurnDeg = 90.0;

constexpr std::string_view kNodeReport = "NODE_REPORT";
constexpr std::string_view kSensorRequest = "UHZ_SENSOR_REQUEST";
constexpr std::string_view kConfigRequest = "UHZ_CONFIG_REQUEST";
constexpr std::string_view kClassifyRequest = "UHZ_CLASSIFY_REQUEST";
constexpr std::string_view kSensorClear = "UHZ_SENSOR_CLEAR";
constexpr std::string_view kPmvConnect = "PMV_CONNECT";

std::string no_node_report_warning(const std::string& vname) {
  return "No NODE_REPORT received for " + vname;
}

ObjectType flipped(ObjectType t) {
  return t == ObjectType::kHazard ? ObjectType::kBenign : ObjectType::kHazard;
}

std::optional<double> latest(std::optional<double> a, std::optional<double> b) {
  if (!a) return b;
  if (!b) return a;
  return std::max(*a, *b);
}

ViewCircle circle_at(const HazardObject& o, int vertices, double now_s) {
  ViewCircle c;
  c.x_m = o.x_m;
  c.y_m = o.y_m;
  c.radius_m = kCircleRadius_m;
  c.vertices = vertices;
  c.time_s = now_s;
  c.edge_size = kCircleEdgeSize;
  c.fill_transparency = kCircleTransparency;
  return c;
}

glm::dvec2 project(glm::dvec2 from, double heading_deg, double distance_m) {
  const SinCos sc = sin_cos_deg(heading_deg);
  return {from.x + distance_m * sc.sin, from.y + distance_m * sc.cos};
}

}  // namespace

Engine::Engine(EngineSetup setup, SeedChoice seed)
    : config_(std::move(setup.config)),
      field_(std::move(setup.field)),
      setup_warnings_(std::move(setup.config_warnings)),
      hazard_files_(std::move(setup.hazard_files)),
      effects_(choose_effects(config_, field_)),
      placement_(std::move(setup.placement)),
      seed_(seed),
      dice_(seed.seed) {
  field_.build_index();
}

// ---------------------------------------------------------------------------------------------
// Interface

const std::vector<InterfaceVariable>& Engine::subscriptions() {
  static const std::vector<InterfaceVariable> v = {
      {"NODE_REPORT", "NAME=archie,X=51,Y=11.3,SPD=1.5,HDG=90", "a vehicle's pose"},
      {"UHZ_SENSOR_REQUEST", "vname=archie", "keep the vehicle's sensor on for 600 s"},
      {"UHZ_CONFIG_REQUEST", "vname=archie,width=25,pd=0.9", "choose a sensor setting"},
      {"UHZ_CLASSIFY_REQUEST", "vname=archie,label=12,priority=80",
       "classify a detected object (action=top or action=clear optional)"},
      {"UHZ_SENSOR_CLEAR", "vname=archie", "empty the vehicle's pending classifications"},
      {"PMV_CONNECT", "pMarineViewer", "post the object markers again"},
  };
  return v;
}

const std::vector<InterfaceVariable>& Engine::publications() {
  static const std::vector<InterfaceVariable> v = {
      {"UHZ_DETECTION_REPORT", "vname=archie,x=51,y=11.3,label=12", "a detection"},
      {"UHZ_DETECTION_REPORT_<V>", "x=51,y=11.3,label=12", "a detection, for vehicle V"},
      {"UHZ_HAZARD_REPORT", "vname=archie,x=51,y=11.3,label=12,type=hazard",
       "a classification answer"},
      {"UHZ_HAZARD_REPORT_<V>", "x=51,y=11.3,label=12,type=hazard",
       "a classification answer, for vehicle V"},
      {"UHZ_CONFIG_ACK", "vname=archie,width=25,pd=0.9,pfa=0.656,pclass=0.8",
       "the settings in force after a configuration"},
      {"UHZ_CONFIG_ACK_<V>", "vname=archie,width=25,pd=0.9,pfa=0.656,pclass=0.8",
       "the same, for vehicle V"},
      {"UHZ_OPTIONS_SUMMARY", "width=25,exp=4,pclass=0.80:width=50,exp=2,pclass=0.60",
       "the configured sensor options"},
      {"VIEW_POLYGON",
       "pts={25,2.5:25,-2.5:-25,-2.5:-25,2.5},label=sensor_swath_archie,msg=0.90,"
       "edge_color=green,fill_color=white,vertex_size=0,edge_size=0,fill_transparency=0.2",
       "a vehicle's swath"},
      {"VIEW_CIRCLE",
       "x=51,y=11.3,radius=10,vertices=12,edge_color=white,fill_color=white,time=12.5,"
       "vertex_size=0,edge_size=1,fill_transparency=0.3",
       "detection and classification cues"},
      {"VIEW_MARKER", "x=51,y=11.3,width=8,primary_color=green,type=triangle,label=12",
       "an object of the field"},
      {"VIEW_SEGLIST", "pts={51,26.3:51,-3.7},edge_color=gray70,vertex_size=0,edge_size=1",
       "an object's aspect axis"},
  };
  return v;
}

// The name index is the lookup: a binary search over the ids in name order (a few compares for
// a fleet of 100), so no second name -> id map has to be kept in step with it.
std::vector<VehicleId>::const_iterator Engine::name_position(std::string_view name) const {
  return std::lower_bound(by_name_.begin(), by_name_.end(), name,
                          [&](VehicleId a, std::string_view n) { return vehicles_[a].name < n; });
}

std::optional<VehicleId> Engine::find_vehicle(std::string_view name) const {
  const auto pos = name_position(name);
  if (pos == by_name_.end() || vehicles_[*pos].name != name) return std::nullopt;
  return *pos;
}

VehicleId Engine::vehicle_id(std::string_view name) {
  const auto pos = name_position(name);
  if (pos != by_name_.end() && vehicles_[*pos].name == name) return *pos;
  const auto id = static_cast<VehicleId>(vehicles_.size());
  VehicleState v;
  v.name = std::string(name);
  v.variable_suffix = "_" + base::to_upper(name);
  v.name_hash = hash_name(name);
  if (effects_.turn_blackout) v.heading_history.emplace();
  vehicles_.push_back(std::move(v));
  by_name_.insert(pos, id);
  return id;
}

// ---------------------------------------------------------------------------------------------
// Start-up and mail

Outputs Engine::start(double now_s) {
  Outputs out;
  start_time_s_ = now_s;
  out.config_warnings = setup_warnings_;
  if (effects_.hazard_markers) post_object_visuals(out);
  return out;
}

Outputs Engine::on_mail(std::string_view variable, std::string_view value, double now_s) {
  Outputs out;
  const auto& subs = subscriptions();
  const bool subscribed = std::any_of(subs.begin(), subs.end(), [&](const InterfaceVariable& s) {
    return s.name == variable;
  });
  if (!subscribed) return out;
  if (value.size() > kMaxMailValueBytes) {
    out.run_warnings.push_back(std::string(variable) + ": value of " +
                               std::to_string(value.size()) + " bytes exceeds " +
                               std::to_string(kMaxMailValueBytes) + "; ignored: '" +
                               base::excerpt(value) + "'");
    return out;
  }
  auto malformed = [&](const std::string& error) {
    out.run_warnings.push_back(std::string(variable) + ": " + error + "; ignored: '" +
                               base::excerpt(value) + "'");
  };
  // Each message: its module's parser, then its handler; a parse failure is one warning.
  auto route = [&](auto parse, auto handle) {
    const auto parsed = parse(value);
    if (parsed) {
      handle(*parsed.value);
    } else {
      malformed(parsed.error);
    }
  };
  if (variable == kNodeReport) {
    route([&](std::string_view text) { return parse_node_report(text, &placement_); },
          [&](const NodeReport& r) { handle_node_report(r, now_s, out); });
  } else if (variable == kSensorRequest) {
    route(parse_sensor_request,
          [&](const SensorRequest& r) { handle_sensor_request(r.vname, now_s); });
  } else if (variable == kConfigRequest) {
    route(parse_config_request,
          [&](const ConfigRequest& r) { handle_config_request(r, now_s, out); });
  } else if (variable == kClassifyRequest) {
    route(parse_classify_request,
          [&](const ClassifyRequest& r) { handle_classify_request(r, now_s, out); });
  } else if (variable == kSensorClear) {
    route(parse_sensor_clear, [&](const SensorClear& r) { clear_queue(r.vname, out); });
  } else if (variable == kPmvConnect) {
    if (effects_.hazard_markers) post_object_visuals(out);
  }
  return out;
}

// A LAT/LON-only report was placed by the parser (geodesy.hpp); the engine only sees x/y.
void Engine::handle_node_report(const NodeReport& r, double now_s, Outputs& out) {
  VehicleState& v = vehicles_[vehicle_id(r.name)];
  v.pose = Pose{{r.x_m, r.y_m}, r.heading_deg, r.speed_mps};
  if (v.heading_history) v.heading_history->add(r.heading_deg, now_s);
  if (track_mode()) add_to_track(v, out);
  if (v.warned_no_node_report) {
    out.retracted_run_warnings.push_back(no_node_report_warning(v.name));
    v.warned_no_node_report = false;
  }
}

void Engine::handle_sensor_request(std::string_view vname, double now_s) {
  VehicleState& v = vehicles_[vehicle_id(vname)];
  ++v.counters.sensor_requests;
  v.last_sensor_request_s = now_s;
}

void Engine::post_object_visuals(Outputs& out) const {
  for (const HazardObject& o : field_.objects()) {
    const bool hazard = o.is_hazard();
    ViewMarker m;
    m.x_m = o.x_m;
    m.y_m = o.y_m;
    m.width_m = o.marker_width_m.value_or(hazard ? config_.hazard_marker_width_m
                                                 : config_.benign_marker_width_m);
    m.primary_color = o.color.value_or(hazard ? config_.hazard_color : config_.benign_color);
    m.shape = o.shape.value_or(hazard ? config_.hazard_shape : config_.benign_shape);
    m.label = o.label;
    if (!hazard) m.fill_transparency = 1.0 - o.resemblance.value_or(kMarkerFillWithoutHr);
    out.post("VIEW_MARKER", format_view_marker(m));
    if (!o.aspect_deg) continue;
    // The aspect axis (spec 5.4; rulings "Visuals": every aspect, 0 included).
    const double length_m =
        (o.aspect_min_deg && o.aspect_max_deg)
            ? kSeglistBaseLength_m + kSeglistWindowLength_m *
                                         ((*o.aspect_min_deg + *o.aspect_max_deg) / 2.0) /
                                         kQuarterTurnDeg
            : kSeglistPartialLength_m;
    const glm::dvec2 at{o.x_m, o.y_m};
    ViewSeglist s;
    s.points = {project(at, *o.aspect_deg, length_m), project(at, *o.aspect_deg + 180.0, length_m)};
    s.edge_color = "gray70";
    s.edge_size = 1.0;
    out.post("VIEW_SEGLIST", format_view_seglist(s));
  }
}

// ---------------------------------------------------------------------------------------------
// Settings

bool Engine::active(const VehicleState& v, double now_s) const {
  return v.last_sensor_request_s &&
         !elapsed_at_least(now_s, *v.last_sensor_request_s, kSensorActiveWindow_s);
}

bool Engine::option_full(OptionIndex option, VehicleId asking, double now_s) const {
  const int max = config_.options.option(option).max_vehicles;
  if (max == 0) return false;
  int holders = 0;
  for (VehicleId id = 0; id < vehicles_.size(); ++id) {
    const VehicleState& other = vehicles_[id];
    if (id != asking && other.setting && other.setting->option == option &&
        active(other, now_s)) {
      ++holders;
    }
  }
  return holders >= max;
}

std::optional<OptionIndex> Engine::choose_option(double width_m, VehicleId asking,
                                                 double now_s) const {
  return config_.options.choose(
      width_m, [&](OptionIndex i) { return option_full(i, asking, now_s); });
}

void Engine::set_option(VehicleState& v, OptionIndex option, double pd) {
  const SensorOption& o = config_.options.option(option);
  v.setting = SensorSetting{option, o.width_m, o.exp, o.pclass, pd,
                            roc_false_alarm_probability(pd, o.exp)};
}

void Engine::post_ack(const VehicleState& v, Outputs& out) const {
  const SensorSetting& s = *v.setting;
  const std::string ack = format_config_ack(ConfigAck{v.name, s.width_m, s.pd, s.pfa, s.pclass});
  out.post("UHZ_CONFIG_ACK", ack);
  out.post("UHZ_CONFIG_ACK" + v.variable_suffix, ack);
}

OptionIndex Engine::option_or_smallest(std::optional<OptionIndex> choice, const VehicleState& v,
                                       Outputs& out) const {
  if (!choice) {
    out.run_warnings.push_back("Every sensor option is full; " + v.name +
                               " gets the smallest width");
  }
  return choice.value_or(0);
}

// A successful width setting counts in the report; only a requested one opens the
// min_reset_interval window (D4, D11).
void Engine::record_width_setting(VehicleState& v, double now_s, bool opens_window) {
  ++v.counters.width_resets;
  v.counters.last_width_reset_s = now_s;
  if (opens_window) v.width_window_start_s = now_s;
}

// D4: the default width through the width choice (so `max` applies; rulings "Width choice"),
// with `pd`. Counts as a width setting but opens no min_reset_interval window.
void Engine::set_default_width(VehicleId id, double pd, double now_s, Outputs& out) {
  VehicleState& v = vehicles_[id];
  const auto choice = choose_option(config_.options.default_width_m(), id, now_s);
  set_option(v, option_or_smallest(choice, v, out), pd);
  ++v.counters.width_attempts;
  record_width_setting(v, now_s, /*opens_window=*/false);
}

// A sensing vehicle without a setting gets the default one, announced like a request's (D4).
void Engine::apply_default_setting(VehicleId id, double now_s, Outputs& out) {
  set_default_width(id, kDefaultPd, now_s, out);
  const VehicleState& v = vehicles_[id];
  out.events.push_back("Setting default sensor settings for: " + v.name);
  post_ack(v, out);
}

// Rulings "Settings": exactly one ack per accepted request, with the settings in force after it.
void Engine::handle_config_request(const ConfigRequest& r, double now_s, Outputs& out) {
  if (config_.options.empty()) {
    out.run_warnings.push_back("UHZ_CONFIG_REQUEST from " + r.vname +
                               ": no sensor_config options exist; ignored");
    return;
  }
  const VehicleId id = vehicle_id(r.vname);
  VehicleState& v = vehicles_[id];
  const char* what =
      r.width_m ? "Setting sensor settings for: " : "Setting sensor PD settings for: ";
  out.events.push_back(what + v.name);
  auto set_pd = [&](double pd) {
    v.setting->pd = pd;
    v.setting->pfa = roc_false_alarm_probability(pd, v.setting->exp);
    ++v.counters.pd_resets;
    v.counters.last_pd_reset_s = now_s;
  };

  if (!r.width_m) {
    if (!v.setting) {
      // pd-only without a setting: the default width with the requested pd, in one ack.
      set_default_width(id, *r.pd, now_s, out);
    }
    set_pd(*r.pd);  // pd-only updates are never rate-limited (D11)
    return post_ack(v, out);
  }

  ++v.counters.width_attempts;
  const auto choice = choose_option(*r.width_m, id, now_s);
  if (!v.setting) {
    set_option(v, option_or_smallest(choice, v, out), r.pd.value_or(kDefaultPd));
  } else if (!choice) {
    out.run_warnings.push_back("Every sensor option is full; " + v.name +
                               " keeps its current setting");
    set_pd(r.pd.value_or(v.setting->pd));
    return post_ack(v, out);
  } else if (*choice == v.setting->option) {
    set_pd(r.pd.value_or(v.setting->pd));  // "Unchanged width": a pd-only update
    return post_ack(v, out);
  } else if (v.width_window_start_s &&
             !elapsed_at_least(now_s, *v.width_window_start_s, config_.min_reset_interval_s)) {
    out.events.push_back("Sensor reset denied (too soon) for vehicle: " + v.name);
    set_pd(r.pd.value_or(v.setting->pd));  // D11: the width stays, the pd applies
    return post_ack(v, out);
  } else {
    set_option(v, *choice, r.pd.value_or(v.setting->pd));
  }
  record_width_setting(v, now_s, /*opens_window=*/true);
  post_ack(v, out);
}

// ---------------------------------------------------------------------------------------------
// Classification (D7, D8, D10, D37)

void Engine::handle_classify_request(const ClassifyRequest& r, double now_s, Outputs& out) {
  if (r.action == ClassifyAction::kClear) return clear_queue(r.vname, out);
  const auto id = find_vehicle(r.vname);
  if (!id) {
    out.run_warnings.push_back("Classify request from unknown vehicle " + r.vname +
                               " (label " + r.label + "); refused");
    return;
  }
  VehicleState& v = vehicles_[*id];
  ++v.counters.classify_requests;
  const auto object = field_.find(r.label);
  if (!object) {
    out.run_warnings.push_back(v.name + " classify request for unknown label: " + r.label);
    return;
  }
  if (!v.setting) {
    out.run_warnings.push_back("No sensor setting (no classifier) for " + v.name +
                               "; classify request for " + r.label + " refused");
    return;
  }
  const auto credits = v.credits.find(*object);
  if (credits == v.credits.end() || credits->second.empty()) {
    out.run_warnings.push_back("No detection credit for " + v.name + " and label " + r.label +
                               " (one classification per detection); refused");
    return;
  }
  const Credit credit = credits->second.front();
  credits->second.pop_front();
  if (credits->second.empty()) v.credits.erase(credits);

  // Decided now, with the settings in force now (rulings "Credits").
  const HazardObject& o = field_.object(*object);
  const double pc = v.setting->pclass;
  const double pc_resemblance = (effects_.resemblance && !o.is_hazard() && o.resemblance)
                                    ? resemblance_classification_probability(pc, *o.resemblance)
                                    : pc;
  const double pc_aspect =
      (effects_.aspect && o.has_aspect_triple())
          ? aspect_classification_probability(pc_resemblance,
                                              degradation(o, credit.heading_deg))
          : pc_resemblance;
  const double die = dice_.classification_v(v.name_hash, field_.label_hash(*object), credit.pass);
  const bool correct = classification_correct(die, pc_aspect);
  notify(v, *object, credit.pass, DiePurpose::kClassification, correct);
  PendingAnswer answer;
  answer.object = *object;
  answer.reported = correct ? o.type : flipped(o.type);
  answer.aspect_affected = !correct && classification_correct(die, pc_resemblance);
  answer.credit = credit;
  const bool top = r.action == ClassifyAction::kTop;
  v.queue.push(answer, r.priority.value_or(kDefaultClassifyPriority), top);
  if (top) v.last_top_s = now_s;
  out.events.push_back("Classify request queued for " + v.name + ": label " + o.label +
                       ", pass " + std::to_string(credit.pass) + ", pc " + base::fix(pc_aspect, 5) +
                       ", die " + base::fix(die, 4));
}

void Engine::clear_queue(std::string_view vname, Outputs& out) {
  const auto id = find_vehicle(vname);
  if (!id) return;
  VehicleState& v = vehicles_[*id];
  const std::vector<PendingAnswer> cleared = v.queue.clear();
  for (const PendingAnswer& a : cleared) {
    // The credit goes back in pass order, so the same die is rolled again (rulings "Clear").
    std::deque<Credit>& list = v.credits[a.object];
    const auto pos = std::lower_bound(list.begin(), list.end(), a.credit.pass,
                                      [](const Credit& c, std::uint32_t p) { return c.pass < p; });
    list.insert(pos, a.credit);
  }
  out.events.push_back("Classify queue cleared for " + v.name + " (" +
                       std::to_string(cleared.size()) + " entries)");
}

void Engine::release_classifications(double now_s, Outputs& out) {
  for (VehicleId id : by_name_) {
    VehicleState& v = vehicles_[id];
    if (v.queue.empty()) continue;
    const auto last = latest(v.last_release_s, v.last_top_s);
    if (last && !elapsed_at_least(now_s, *last, config_.min_classify_interval_s)) continue;
    const PendingAnswer answer = *v.queue.pop();
    v.last_release_s = now_s;
    ++v.counters.answers;
    const HazardObject& o = field_.object(answer.object);
    HazardReport report{std::nullopt, o.x_m, o.y_m, o.label, answer.reported,
                        o.aspect_deg, o.aspect_min_deg, o.aspect_max_deg};
    out.post("UHZ_HAZARD_REPORT" + v.variable_suffix, format_hazard_report(report));
    report.vname = v.name;
    out.post("UHZ_HAZARD_REPORT", format_hazard_report(report));
    out.events.push_back("Hazard report sent to vehicle: " + v.name + " (label " + o.label + ")");
    if (!effects_.detection_visuals) continue;
    ViewCircle c = circle_at(o, kClassificationCircleVertices, now_s);
    c.edge_color = c.fill_color = answer.reported == ObjectType::kHazard ? "yellow" : "green";
    if (answer.aspect_affected) {
      c.fill_color = "pink";
      c.edge_size = kAffectedEdgeSize;
      c.fill_transparency = kAffectedTransparency;
    }
    out.post("VIEW_CIRCLE", format_view_circle(c));
  }
}

// ---------------------------------------------------------------------------------------------
// Iteration

Outputs Engine::step(double now_s) {
  Outputs out;
  post_options_summary_if_due(now_s, out);
  for (VehicleId id : by_name_) sense(id, now_s, out);
  release_classifications(now_s, out);
  return out;
}

void Engine::post_options_summary_if_due(double now_s, Outputs& out) {
  if (last_summary_s_ &&
      !elapsed_at_least(now_s, *last_summary_s_, config_.options_summary_interval_s)) {
    return;
  }
  last_summary_s_ = now_s;
  out.post("UHZ_OPTIONS_SUMMARY", format_options_summary(config_.options.summary()));
}

void Engine::sense(VehicleId id, double now_s, Outputs& out) {
  VehicleState& v = vehicles_[id];
  if (!active(v, now_s)) {
    if (track_mode()) collapse_track(v);  // inactive: the track's segments are not sensed
    return;
  }
  if (!v.pose) {
    if (!v.warned_no_node_report) out.run_warnings.push_back(no_node_report_warning(v.name));
    v.warned_no_node_report = true;
    return;
  }
  if (!v.setting) {
    if (config_.options.empty()) {
      if (!v.warned_no_setting) {
        out.run_warnings.push_back("No sensor setting for " + v.name +
                                   ": no sensor_config options exist");
      }
      v.warned_no_setting = true;
      if (track_mode()) collapse_track(v);
      return;
    }
    apply_default_setting(id, now_s, out);
  }
  const bool on = sensor_on(v);
  const Swath swath(v.pose->position_m, v.pose->heading_deg, v.setting->width_m,
                    config_.swath_length_m);
  if (effects_.swath_visuals) post_swath(v, swath, on, out);
  if (track_mode()) return sense_track(v, now_s, out);  // gated per report (sensing_track.hpp)
  // During a blackout nothing changes, not even inside/outside (rulings "Pass").
  if (on) update_entries(v, swath, now_s, out);
}

bool Engine::sensor_on(const VehicleState& v) const {
  return gates_pass(v.pose->speed_mps, v.heading_history);
}

bool Engine::gates_pass(double speed_mps, const std::optional<HeadingHistory>& history) const {
  if (effects_.speed_gate && speed_mps > *config_.max_vehicle_speed_mps) return false;
  if (effects_.turn_blackout && history->turn_rate_dps() > *config_.max_turn_rate_dps) {
    return false;
  }
  return true;
}

void Engine::post_swath(const VehicleState& v, const Swath& swath, bool on, Outputs& out) const {
  const SensorSetting& s = *v.setting;
  ViewPolygon p;
  const auto corners = swath.corners();
  p.points.assign(corners.begin(), corners.end());
  p.label = "sensor_swath_" + v.name;
  if (config_.show_pd && config_.show_pfa) {
    p.msg = base::fix(s.pd, 2) + "/" + base::fix(s.pfa, 2);
  } else if (config_.show_pd) {
    p.msg = base::fix(s.pd, 2);
  } else if (config_.show_pfa) {
    p.msg = "pfa=" + base::fix(s.pfa, 2);
  } else {
    p.msg = "_null_";  // the original's "no label" word
  }
  p.edge_color = "green";
  p.fill_color = on ? "white" : "red";
  p.edge_size = kSwathEdgeSize;
  p.fill_transparency = config_.swath_transparency;
  out.post("VIEW_POLYGON", format_view_polygon(p));
}

// Sampling (the default, spec 8.5): the objects inside the swath at the latest pose, against the
// objects inside at the last sensor-on iteration.
void Engine::update_entries(VehicleState& v, const Swath& swath, double now_s, Outputs& out) {
  scratch_inside_.clear();
  field_.grid().for_each_in_box(swath.bounds(), [&](ObjectId id, glm::dvec2 position) {
    if (swath.contains(position)) scratch_inside_.push_back(id);
  });
  std::sort(scratch_inside_.begin(), scratch_inside_.end());
  // A sensor event is an object inside now that was not inside before (spec 8.5).
  std::vector<ObjectId> entering;
  std::set_difference(scratch_inside_.begin(), scratch_inside_.end(), v.inside.begin(),
                      v.inside.end(), std::back_inserter(entering));
  v.inside.swap(scratch_inside_);
  for (ObjectId id : entering) roll_detection(v, id, v.pose->heading_deg, now_s, out);
}

// Each node report joins the track with the gates as they stand after it (sensing_track.hpp).
void Engine::add_to_track(VehicleState& v, Outputs& out) {
  if (v.track.size() >= kMaxTrackPoses) {
    if (!v.track_overflowed) {
      out.run_warnings.push_back(v.name + ": more than " + std::to_string(kMaxTrackPoses) +
                                 " node reports between two iterations; the oldest are dropped");
    }
    v.track_overflowed = true;
    v.track.erase(v.track.begin());
  }
  v.track.push_back(TrackPose{v.pose->position_m, v.pose->heading_deg,
                              gates_pass(v.pose->speed_mps, v.heading_history)});
}

// Keeps only the latest report as the start of the next track; its own state is sensed again
// at the next evaluation (as the sampled mode does when a vehicle becomes active again).
void Engine::collapse_track(VehicleState& v) {
  if (v.track.size() > 1) v.track.erase(v.track.begin(), v.track.end() - 1);
  v.track_start_sensed = false;
  v.track_overflowed = false;
}

// Sub-stepping and sweeping: the segments since the last evaluation, then the events in piece
// order (sensing_track.hpp). Candidates: the objects near any piece, and those inside before.
void Engine::sense_track(VehicleState& v, double now_s, Outputs& out) {
  if (v.track.empty()) return;  // every node report joins the track; none yet: nothing to do
  const TrackMode mode = effects_.swept_swath ? TrackMode::kSweep : TrackMode::kSubsteps;
  const std::vector<TrackPiece> pieces =
      track_pieces(v.track, !v.track_start_sensed, mode, config_.swath_substeps,
                   v.setting->width_m, config_.swath_length_m);
  collapse_track(v);            // the latest report starts the next track ...
  v.track_start_sensed = true;  // ... and has been sensed now
  if (pieces.empty()) return;  // no sensed piece: nothing changes

  Box box = pieces.front().box;
  for (const TrackPiece& p : pieces) box = merged(box, p.box);
  scratch_candidates_.assign(v.inside.begin(), v.inside.end());
  field_.grid().for_each_in_box(box, [&](ObjectId id, glm::dvec2) {
    scratch_candidates_.push_back(id);
  });
  std::sort(scratch_candidates_.begin(), scratch_candidates_.end());
  scratch_candidates_.erase(std::unique(scratch_candidates_.begin(), scratch_candidates_.end()),
                            scratch_candidates_.end());

  std::vector<std::pair<std::uint32_t, ObjectId>> events;  // (piece, object)
  scratch_inside_.clear();
  for (ObjectId id : scratch_candidates_) {
    const bool was_inside = std::binary_search(v.inside.begin(), v.inside.end(), id);
    scratch_event_pieces_.clear();
    if (walk_pieces(pieces, field_.position(id), was_inside, scratch_event_pieces_)) {
      scratch_inside_.push_back(id);
    }
    for (std::uint32_t piece : scratch_event_pieces_) events.emplace_back(piece, id);
  }
  v.inside.swap(scratch_inside_);
  std::sort(events.begin(), events.end());
  for (const auto& [piece, id] : events) {
    roll_detection(v, id, pieces[piece].heading_deg, now_s, out);
  }
}

double Engine::degradation(const HazardObject& o, double heading_deg) const {
  return aspect_degradation(aspect_difference_deg(heading_deg, *o.aspect_deg), *o.aspect_min_deg,
                            *o.aspect_max_deg);
}

void Engine::roll_detection(VehicleState& v, ObjectId id, double heading_deg, double now_s,
                            Outputs& out) {
  const HazardObject& o = field_.object(id);
  const SensorSetting& s = *v.setting;
  const std::uint32_t pass = ++v.passes[id];
  ++(o.is_hazard() ? v.counters.hazard_chances : v.counters.benign_chances);

  // Thresholds (manual 3.1, 6.1, 7.1; D5): hazards detect with pd; benign objects with pfa,
  // degraded by aspect (pfa' = pd^exp'), then combined with resemblance.
  double plain_p = s.pd, degraded_p = s.pd;
  if (!o.is_hazard()) {
    plain_p = degraded_p = s.pfa;
    if (effects_.aspect && o.has_aspect_triple()) {
      degraded_p = roc_false_alarm_probability(
          s.pd, degraded_exponent(s.exp, degradation(o, heading_deg)));
    }
    if (effects_.resemblance && o.resemblance) {
      plain_p = resemblance_false_alarm_probability(plain_p, *o.resemblance);
      degraded_p = resemblance_false_alarm_probability(degraded_p, *o.resemblance);
    }
  }
  const double u = dice_.detection_u(v.name_hash, field_.label_hash(id), pass);
  const bool detected = detection_succeeds(u, degraded_p);
  notify(v, id, pass, DiePurpose::kDetection, detected);
  if (!detected) return;

  ++v.counters.detections;
  ++(o.is_hazard() ? v.counters.hazard_reports : v.counters.benign_reports);
  v.credits[id].push_back(Credit{pass, heading_deg});
  DetectionReport report{v.name, o.x_m, o.y_m, o.label,
                         o.aspect_deg, o.aspect_min_deg, o.aspect_max_deg};
  out.post("UHZ_DETECTION_REPORT", format_detection_report(report));
  report.vname.reset();
  out.post("UHZ_DETECTION_REPORT" + v.variable_suffix, format_detection_report(report));
  out.events.push_back("Detection report sent to vehicle: " + v.name + " (label " + o.label + ")");
  if (!effects_.detection_visuals) return;
  ViewCircle c = circle_at(o, kDetectionCircleVertices, now_s);
  c.duration_s = config_.show_detections.duration_s;
  // Pink when only the degraded ROC produced the detection (manual 7.3, D5).
  const bool changed_by_aspect = !detection_succeeds(u, plain_p);
  c.edge_color = c.fill_color = changed_by_aspect ? "pink" : "white";
  out.post("VIEW_CIRCLE", format_view_circle(c));
}

std::vector<std::string> Engine::invariant_violations() const {
  std::vector<std::string> bad;
  auto check = [&](bool ok, const std::string& what) {
    if (!ok) bad.push_back(what);
  };
  check(by_name_.size() == vehicles_.size(), "name index size");
  for (std::size_t i = 1; i < by_name_.size(); ++i) {
    check(vehicles_[by_name_[i - 1]].name < vehicles_[by_name_[i]].name, "name order");
  }
  for (const VehicleState& v : vehicles_) {
    const std::string who = v.name + ": ";
    check(v.heading_history.has_value() == effects_.turn_blackout, who + "heading history");
    check(v.track.empty() || track_mode(), who + "a track without sweeping or sub-stepping");
    check(v.track.size() <= kMaxTrackPoses, who + "track longer than its bound");
    for (std::size_t i = 0; i < v.inside.size(); ++i) {
      check(v.inside[i] < field_.size(), who + "inside id out of range");
      check(i == 0 || v.inside[i - 1] < v.inside[i], who + "inside list not sorted");
      const auto pass = v.passes.find(v.inside[i]);
      check(pass != v.passes.end() && pass->second >= 1, who + "inside object without a pass");
    }
    for (const auto& [id, list] : v.credits) {
      const auto pass = v.passes.find(id);
      check(!list.empty(), who + "empty credit list");
      for (std::size_t i = 0; i < list.size(); ++i) {
        check(pass != v.passes.end() && list[i].pass <= pass->second, who + "credit beyond passes");
        check(i == 0 || list[i - 1].pass < list[i].pass, who + "credits not in pass order");
      }
    }
    if (v.setting) {
      const SensorSetting& s = *v.setting;
      check(s.option < config_.options.size(), who + "option index");
      if (s.option < config_.options.size()) {
        check(s.width_m == config_.options.option(s.option).width_m, who + "width of option");
      }
      check(s.pd >= 0.0 && s.pd <= 1.0, who + "pd range");
      check(s.pfa == roc_false_alarm_probability(s.pd, s.exp), who + "pfa = pd^exp");
    }
  }
  return bad;
}

void Engine::notify(const VehicleState& v, ObjectId id, std::uint32_t pass, DiePurpose purpose,
                    bool outcome) const {
  if (observer_) observer_(Decision{v.name, field_.object(id).label, pass, purpose, outcome});
}

}  // namespace hazard
