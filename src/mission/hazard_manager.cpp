// The vehicle-side hazard manager. Contract and rules: include/mission/hazard_manager.hpp; its
// parameter table is in hazard_manager_params.cpp.
//
// Data structures: one Record per known object (ids are indices, names only at the edge); a
// uniform grid of record ids (kCell_m cells, cell_index.hpp) so a pose touches only the objects
// near its swath; the list of objects currently inside the swath (their exits are checked every pose); the
// list of ended passes awaiting a late detection; the vehicle's own track, thinned to one sample
// per `track_sample_spacing_m` (plus every change of sensor state), for hindsight passes.
// Rejected alternative: resolving a pass the moment it ends. Detections travel through the MOOSDB
// and possibly pShare, so the report for a pass can arrive after the vehicle has left the object.

#include "mission/hazard_manager.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>

#include "hazard/messages/classify_request.hpp"
#include "hazard/messages/config_request.hpp"
#include "hazard/messages/sensor_request.hpp"
#include "hazard/swath.hpp"
#include "base/text.hpp"
#include "mission/transit_lane.hpp"

namespace mission {

namespace {

/// Grid cell of the manager's object index and track index (m). A pose looks at the cells of
/// the axis-aligned box around its footprint (50 m by 5 m for W = 25 on a north-south or east-west
/// lane, about 37 m square at 45 degrees): 10 m cells keep the box close to the footprint in dense
/// fields and cost little in sparse ones (cell_index.hpp skips empty cells cheaply).
constexpr double kCell_m = 10.0;

// The sensor's footprint at one pose, and its core (W - margin to each side). Length and margin
// are the configuration's (sensor_swath_length, pass_margin). Most objects tested lie outside the
// rectangle, so the reach (a hypot) and the core (a sine and cosine) are built on first use.
class Footprint {
 public:
  Footprint(glm::dvec2 position_m, double heading_deg, double half_width_m,
            const ManagerConfig& config)
      : center_(position_m),
        heading_deg_(heading_deg),
        half_width_m_(half_width_m),
        core_half_width_m_(half_width_m - config.pass_margin_m),
        length_m_(config.sensor_swath_length_m) {
    if (half_width_m > 0.0) full_.emplace(position_m, heading_deg, half_width_m, length_m_);
  }
  bool in_full(glm::dvec2 p) const { return full_ && full_->contains(p) && near(p); }
  bool in_core(glm::dvec2 p) const {
    if (!(core_half_width_m_ > 0.0)) return false;
    if (!core_) core_.emplace(center_, heading_deg_, core_half_width_m_, length_m_);
    return core_->contains(p) && near(p);
  }
  /// The box holding every point in_full accepts; nullopt when it accepts none.
  std::optional<hazard::Box> bounds() const {
    if (!full_) return std::nullopt;
    return full_->bounds();
  }

 private:
  bool near(glm::dvec2 p) const {
    if (!reach_m_) reach_m_ = std::hypot(half_width_m_, 0.5 * length_m_);
    return glm::length(p - center_) <= *reach_m_ + 1e-9;
  }
  glm::dvec2 center_;
  double heading_deg_;
  double half_width_m_;
  double core_half_width_m_;
  double length_m_;
  std::optional<hazard::Swath> full_;
  mutable std::optional<hazard::Swath> core_;
  mutable std::optional<double> reach_m_;
};

std::string fmt_setting(double width, double pd, double pfa, double pclass) {
  return "width=" + base::fmt(width, 1) + ",pd=" + base::fmt(pd, 3) + ",pfa=" +
         base::fmt(pfa, 3) + ",pclass=" + base::fmt(pclass, 3);
}

}  // namespace

// ---- the manager ---------------------------------------------------------------------------

HazardManager::HazardManager(ManagerConfig config)
    : config_(std::move(config)), track_cells_(kCell_m), grid_(kCell_m) {
  assert(validate(config_));
}

double HazardManager::log_odds(const Record& r) const {
  double lo = logit(config_.prior_hazard) + r.own.log_lr;
  for (const auto& entry : r.imported) lo += entry.second.log_lr;
  return lo;
}

std::optional<HazardManager::Id> HazardManager::find(std::string_view label) const {
  const auto it = by_label_.find(std::string(label));
  if (it == by_label_.end()) return std::nullopt;
  return it->second;
}

HazardManager::Id HazardManager::find_or_add(std::string_view label, glm::dvec2 position_m) {
  if (auto id = find(label)) return *id;
  const auto id = static_cast<Id>(records_.size());
  Record r;
  r.label = std::string(label);
  r.position_m = position_m;
  records_.push_back(std::move(r));
  by_label_.emplace(std::string(label), id);
  grid_.add(id, position_m);
  quiet_.forget();
  return id;
}

Outputs HazardManager::tick(double now_s) {
  Outputs out;
  tick(now_s, out);
  return out;
}

void HazardManager::tick(double now_s, Outputs& out) {
  if (!setting_ && (!last_config_request_s_ ||
                    now_s - *last_config_request_s_ >= config_.config_retry_interval_s)) {
    out.post("UHZ_CONFIG_REQUEST",
             hazard::format_config_request({config_.vname, config_.swath_width_m, config_.pd}));
    last_config_request_s_ = now_s;
  }
  if (setting_ && (!last_sensor_request_s_ ||
                   now_s - *last_sensor_request_s_ >= config_.sensor_request_interval_s)) {
    out.post("UHZ_SENSOR_REQUEST", hazard::format_sensor_request({config_.vname}));
    last_sensor_request_s_ = now_s;
  }
  resolve_passes(now_s, out);
}

Outputs HazardManager::on_config_ack(const hazard::ConfigAck& ack, double /*now_s*/) {
  Outputs out;
  if (ack.vname != config_.vname) {
    out.run_warnings.push_back("UHZ_CONFIG_ACK for '" + ack.vname + "' ignored (this vehicle is '" +
                               config_.vname + "')");
    return out;
  }
  setting_ = Setting{ack.width_m, ack.pd, ack.pfa, ack.pclass};
  out.events.push_back("Sensor setting acknowledged: " +
                       fmt_setting(ack.width_m, ack.pd, ack.pfa, ack.pclass));
  return out;
}

void HazardManager::on_pose(glm::dvec2 position_m, double heading_deg, double speed_mps,
                            double now_s) {
  headings_.add(heading_deg, now_s);
  const double rate_dps = headings_.turn_rate_dps();
  const bool speed_ok = !(speed_mps > config_.sensor_max_speed_mps);
  // The sensor's test: off when rate > limit or speed > limit, strictly.
  const bool on =
      setting_.has_value() && !(rate_dps > config_.sensor_max_turn_rate_dps) && speed_ok;
  const bool clear =
      on && !(rate_dps > config_.clear_turn_fraction * config_.sensor_max_turn_rate_dps);
  const TrackSample sample{now_s,        position_m,
                           heading_deg,  on,
                           clear,        setting_ ? setting_->width_m : 0.0,
                           setting_ ? setting_->pd : 0.0,
                           setting_ ? setting_->pfa : 0.0};
  const bool keep = track_.empty() ||
                    glm::length(position_m - track_.back().position_m) >=
                        config_.track_sample_spacing_m ||
                    track_.back().sensor_on != on || track_.back().clear != clear ||
                    track_.back().half_width_m != sample.half_width_m;
  if (keep) add_track_sample(sample);
  last_pose_ = sample;
  update_passes(sample);
}

void HazardManager::add_track_sample(const TrackSample& sample) {
  const auto index = static_cast<std::uint32_t>(track_.size());
  track_.push_back(sample);
  if (on_prefix_.empty()) on_prefix_.push_back(0);
  on_prefix_.push_back(on_prefix_.back() + (sample.sensor_on ? 1u : 0u));
  track_cells_.add(index, sample.position_m);
  track_max_half_width_m_ = std::max(track_max_half_width_m_, sample.half_width_m);
}

void HazardManager::update_passes(const TrackSample& s) {
  if (!s.sensor_on) return;  // the sensor freezes its inside/outside state while off
  // No object known yet (a vehicle waiting for a hand-over): none inside, none can enter.
  if (records_.empty()) return;
  // None inside and none near (most poses of a survey): no exit, no entry, no footprint.
  if (inside_.empty() && no_record_near(s.position_m, s.half_width_m)) return;
  const Footprint foot(s.position_m, s.heading_deg, s.half_width_m, config_);
  // Exits (and core reached) for the objects inside.
  for (std::size_t i = 0; i < inside_.size();) {
    Record& r = records_[inside_[i]];
    if (foot.in_full(r.position_m)) {
      if (foot.in_core(r.position_m)) r.pass->reached_core = true;
      ++i;
      continue;
    }
    r.inside = false;
    r.pass->exited_s = s.time_s;
    unresolved_.push_back(inside_[i]);
    inside_[i] = inside_.back();
    inside_.pop_back();
  }
  // Entries, in the index's order (cell column, row, then id).
  const std::optional<hazard::Box> box = foot.bounds();
  if (!box) return;  // no width acked yet: nothing is inside
  grid_.for_each_in_box({box->min_x, box->min_y}, {box->max_x, box->max_y}, [&](Id id) {
    Record& r = records_[id];
    if (r.inside || !foot.in_full(r.position_m)) return;
    if (r.pass) {
      // A new pass began before the last one's latency ran out: decide the last one now.
      Outputs ignored;
      resolve(r, ignored);
      unresolved_.erase(std::remove(unresolved_.begin(), unresolved_.end(), id), unresolved_.end());
    }
    r.inside = true;
    r.pass = Pass{s.time_s, std::nullopt, foot.in_core(r.position_m), s.clear, false};
    if (r.unmatched_detection_s &&
        s.time_s - *r.unmatched_detection_s <= config_.detection_latency_s) {
      r.pass->detected = true;  // the report came just before we saw the entry
      r.unmatched_detection_s.reset();
    }
    inside_.push_back(id);
  });
}

// A record the footprint accepts lies within hypot(W, L/2) of the pose (Footprint::near), so
// within W + L/2 on each axis; `reach` adds a metre for rounding. The box is queried again after
// kCell_m of travel (a query about every 50 poses at 2 m/s and 10 Hz), or when a record was
// added (find_or_add forgets it; records never move).
bool HazardManager::no_record_near(glm::dvec2 position_m, double half_width_m) {
  const double reach = half_width_m + 0.5 * config_.sensor_swath_length_m + 1.0;
  return quiet_.nothing_near(position_m, reach, kCell_m, [&](const hazard::Box& box) {
    // Every record in a cell that meets the box is visited: none visited, none in the box.
    bool none = true;
    grid_.for_each_in_box({box.min_x, box.min_y}, {box.max_x, box.max_y},
                          [&](Id) { none = false; });
    return none;
  });
}

void HazardManager::resolve_passes(double now_s, Outputs& out) {
  for (std::size_t i = 0; i < unresolved_.size();) {
    Record& r = records_[unresolved_[i]];
    if (r.pass && r.pass->exited_s && now_s - *r.pass->exited_s < config_.detection_latency_s) {
      ++i;
      continue;
    }
    resolve(r, out);
    unresolved_[i] = unresolved_.back();
    unresolved_.pop_back();
  }
}

void HazardManager::resolve(Record& r, Outputs& out) {
  if (!r.pass) return;
  const Pass pass = *r.pass;
  r.pass.reset();
  if (pass.detected) return;
  if (pass.reached_core && pass.clear && config_.count_missed_passes && setting_) {
    r.own.add_missed_pass(setting_->pd, setting_->pfa);
    ++counters_.missed_passes;
    out.events.push_back("Pass over " + r.label + " without a detection: P(hazard)=" +
                         base::fmt(logistic(log_odds(r)), 3));
  } else {
    ++counters_.doubtful_passes;
  }
}

std::vector<std::pair<double, double>> HazardManager::hindsight_misses(const Record& r,
                                                                       double before_s) const {
  // Replays the sensor's inside/outside state over the samples before `before_s`, visiting only
  // the samples in the track cells around the object. A sensor-on sample that is not visited
  // lies in another cell, beyond the footprint's reach, so it ends any pass in progress; the
  // prefix counts of sensor-on samples tell whether such a sample lies between two visited ones.
  const auto end = static_cast<std::size_t>(
      std::lower_bound(track_.begin(), track_.end(), before_s,
                       [](const TrackSample& s, double t) { return s.time_s < t; }) -
      track_.begin());
  const double reach_m = std::hypot(track_max_half_width_m_, 0.5 * config_.sensor_swath_length_m);
  std::vector<std::uint32_t> nearby;
  const glm::dvec2 corner{reach_m, reach_m};
  track_cells_.for_each_in_box(r.position_m - corner, r.position_m + corner, [&](std::uint32_t i) {
    if (i < end) nearby.push_back(i);
  });
  std::sort(nearby.begin(), nearby.end());

  std::vector<std::pair<double, double>> misses;
  bool inside = false;
  bool core = false;
  bool clear = false;
  std::pair<double, double> setting{0.0, 0.0};
  auto leave = [&] {
    if (inside && core && clear) misses.push_back(setting);
    inside = false;
  };
  auto on_samples_between = [&](std::size_t from, std::size_t to) {  // in [from, to)
    return to > from ? on_prefix_[to] - on_prefix_[from] : 0u;
  };
  std::size_t previous = 0;
  bool first = true;
  for (std::uint32_t i : nearby) {
    if (!first && on_samples_between(previous + 1, i) > 0) leave();
    if (first && on_samples_between(0, i) > 0) leave();
    first = false;
    previous = i;
    const TrackSample& s = track_[i];
    if (!s.sensor_on) continue;  // frozen
    const Footprint foot(s.position_m, s.heading_deg, s.half_width_m, config_);
    if (!foot.in_full(r.position_m)) {
      leave();
      continue;
    }
    if (!inside) {
      inside = true;
      core = false;
      clear = s.clear;
      setting = {s.pd, s.pfa};
    }
    core = core || foot.in_core(r.position_m);
  }
  // A pass still open counts only if the sensor looked elsewhere before `before_s`.
  if (!first && on_samples_between(previous + 1, end) > 0) leave();
  return misses;
}

Outputs HazardManager::on_detection(const hazard::DetectionReport& report, double now_s) {
  Outputs out;
  if (report.vname && *report.vname != config_.vname) {
    out.run_warnings.push_back("UHZ_DETECTION_REPORT for '" + *report.vname + "' ignored");
    return out;
  }
  const bool is_new = !find(report.label).has_value();
  const Id id = find_or_add(report.label, {report.x_m, report.y_m});
  Record& r = records_[id];
  if (report.aspect_deg) r.aspect_deg = report.aspect_deg;
  if (report.aspect_min_deg) r.aspect_min_deg = report.aspect_min_deg;
  if (report.aspect_max_deg) r.aspect_max_deg = report.aspect_max_deg;
  ++counters_.detections;
  if (!setting_) {
    // pd and pfa are unknown until the ack: the detection is counted but carries no weight.
    out.run_warnings.push_back("Detection of " + r.label +
                               " before any UHZ_CONFIG_ACK: not weighed");
    r.own.add_detection(1.0, 1.0);
    return out;
  }
  if (is_new && config_.count_missed_passes) {
    for (const auto& [pd, pfa] : hindsight_misses(r, now_s - config_.detection_latency_s)) {
      r.own.add_missed_pass(pd, pfa);
      ++counters_.hindsight_passes;
    }
  }
  if (r.pass && !r.pass->detected) {
    r.pass->detected = true;
  } else if (is_new && last_pose_ && last_pose_->sensor_on &&
             Footprint(last_pose_->position_m, last_pose_->heading_deg, last_pose_->half_width_m,
                       config_)
                 .in_full(r.position_m)) {
    // First sight while inside: this is the pass in progress.
    r.inside = true;
    r.pass = Pass{now_s, std::nullopt, false, last_pose_->clear, true};
    inside_.push_back(id);
  } else {
    r.unmatched_detection_s = now_s;
  }
  r.own.add_detection(setting_->pd, setting_->pfa);
  out.events.push_back("Detection of " + r.label + ": P(hazard)=" +
                       base::fmt(logistic(log_odds(r)), 3));
  if (config_.classify) out.append(request_classification(r));
  return out;
}

Outputs HazardManager::request_classification(Record& r) {
  Outputs out;
  const double priority = classification_priority(logistic(log_odds(r)), setting_->pclass,
                                                  penalties_, config_.classify_lookahead);
  hazard::ClassifyRequest request;
  request.vname = config_.vname;
  request.label = r.label;
  request.priority = std::round(priority * 100.0) / 100.0;  // two decimals are plenty
  out.post("UHZ_CLASSIFY_REQUEST", hazard::format_classify_request(request));
  r.pending_pclass.push_back(setting_->pclass);
  ++counters_.classify_requests;
  return out;
}

Outputs HazardManager::on_classification(const hazard::HazardReport& report, double /*now_s*/) {
  Outputs out;
  if (report.vname && *report.vname != config_.vname) {
    out.run_warnings.push_back("UHZ_HAZARD_REPORT for '" + *report.vname + "' ignored");
    return out;
  }
  Record& r = records_[find_or_add(report.label, {report.x_m, report.y_m})];
  double pclass = setting_ ? setting_->pclass : 0.5;
  if (!r.pending_pclass.empty()) {
    pclass = r.pending_pclass.front();
    r.pending_pclass.erase(r.pending_pclass.begin());
  } else {
    out.run_warnings.push_back("Classification of " + r.label + " without a pending request");
  }
  const bool said_hazard = report.type == hazard::ObjectType::kHazard;
  r.own.add_classification(said_hazard, pclass);
  ++counters_.classify_answers;
  out.events.push_back("Classified " + r.label + " as " + (said_hazard ? "hazard" : "benign") +
                       ": P(hazard)=" + base::fmt(logistic(log_odds(r)), 3));
  return out;
}

Outputs HazardManager::on_mission_params(const MissionParams& params) {
  Outputs out;
  if (params.penalty_missed_hazard < 0.0 || params.penalty_false_alarm < 0.0) {
    out.run_warnings.push_back("UHZ_MISSION_PARAMS with a negative penalty ignored");
    return out;
  }
  penalties_ = Penalties{params.penalty_missed_hazard, params.penalty_false_alarm};
  transit_half_width_m_ = params.transit_path_width_m;
  if (params.search_region) {
    auto parsed = ConvexPolygon::parse(*params.search_region);
    if (parsed) params_region_ = std::move(parsed.value);
  }
  return out;
}

Outputs HazardManager::on_handover(const Handover& handover, double /*now_s*/) {
  Outputs out;
  if (handover.dest != config_.vname || handover.source == config_.vname) {
    out.run_warnings.push_back("HAZARD_HANDOVER from '" + handover.source + "' to '" +
                               handover.dest + "' ignored (this vehicle is '" + config_.vname +
                               "')");
    return out;
  }
  for (const std::string& w : handover.warnings) out.run_warnings.push_back(w);
  for (const HandoverObject& o : handover.objects) {
    Record& r = records_[find_or_add(o.label, {o.x_m, o.y_m})];
    r.imported[handover.source] = o.evidence;
    r.handed_over = true;
  }
  out.events.push_back("Hand-over from " + handover.source + ": " +
                       std::to_string(handover.objects.size()) + " objects");
  return out;
}

HazardsetReport HazardManager::make_report() const {
  HazardsetReport report;
  report.source = config_.vname;
  report.name = config_.report_name;
  std::vector<glm::dvec2> reported;
  for (const Record& r : records_) {
    if (!should_report(logistic(log_odds(r)), penalties_)) continue;
    report.objects.push_back({r.label, r.position_m.x, r.position_m.y, r.aspect_deg,
                              r.aspect_min_deg, r.aspect_max_deg});
    reported.push_back(r.position_m);
  }
  const std::optional<ConvexPolygon>& region = config_.region ? config_.region : params_region_;
  if (config_.report_xpath && region && transit_half_width_m_ > 0.0) {
    const auto lane = min_hazard_lane(*region, reported, transit_half_width_m_);
    if (lane) report.xpath_m = lane->x_m;
  }
  return report;
}

Outputs HazardManager::on_hazardset_request(double /*now_s*/) {
  Outputs out;
  const HazardsetReport report = make_report();
  out.post(kHazardsetReportVar, format_hazardset_report(report));
  out.events.push_back("HAZARDSET_REPORT posted with " + std::to_string(report.objects.size()) +
                       " of " + std::to_string(records_.size()) + " objects");
  return out;
}

Handover HazardManager::make_handover(std::string_view dest) const {
  Handover h;
  h.source = config_.vname;
  h.dest = std::string(dest);
  h.prior_hazard = config_.prior_hazard;
  for (const Record& r : records_) {
    HandoverObject o{r.label, r.position_m.x, r.position_m.y, r.own};
    for (const auto& entry : r.imported) {
      o.evidence.log_lr += entry.second.log_lr;
      o.evidence.detections += entry.second.detections;
      o.evidence.missed_passes += entry.second.missed_passes;
      o.evidence.said_hazard += entry.second.said_hazard;
      o.evidence.said_benign += entry.second.said_benign;
    }
    h.objects.push_back(std::move(o));
  }
  return h;
}

Outputs HazardManager::handover_to(std::string_view dest) const {
  Outputs out;
  const std::string text = format_handover(make_handover(dest));
  out.post(kHazardHandoverVar, text);
  out.post(handover_variable_for(dest), text);
  out.events.push_back("Hand-over to " + std::string(dest) + ": " +
                       std::to_string(records_.size()) + " objects");
  return out;
}

std::vector<glm::dvec2> HazardManager::reacquire_route(glm::dvec2 start_m,
                                                       const ReacquireOptions& options) const {
  const bool any_handed = std::any_of(records_.begin(), records_.end(),
                                      [](const Record& r) { return r.handed_over; });
  std::vector<glm::dvec2> objects;
  for (const Record& r : records_)
    if (r.handed_over || !any_handed) objects.push_back(r.position_m);
  return plan_reacquire_route(start_m, objects, options);
}

ObjectBelief HazardManager::view(const Record& r) const {
  ObjectBelief b;
  b.label = r.label;
  b.position_m = r.position_m;
  b.p_hazard = logistic(log_odds(r));
  b.own = r.own;
  for (const auto& entry : r.imported) b.imported_log_lr += entry.second.log_lr;
  b.handed_over = r.handed_over;
  b.reported = should_report(b.p_hazard, penalties_);
  b.classify_priority = setting_ ? classification_priority(b.p_hazard, setting_->pclass, penalties_,
                                                           config_.classify_lookahead)
                                  : 0.0;
  return b;
}

std::vector<ObjectBelief> HazardManager::beliefs() const {
  std::vector<ObjectBelief> out;
  for (const Record& r : records_) out.push_back(view(r));
  return out;
}

std::optional<ObjectBelief> HazardManager::belief(std::string_view label) const {
  const auto id = find(label);
  if (!id) return std::nullopt;
  return view(records_[*id]);
}

}  // namespace mission
