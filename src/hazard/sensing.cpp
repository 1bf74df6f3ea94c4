// Sensing (docs/differences.md, "Geometry and sensing"): node reports and sensor requests, the
// per-vehicle phase of
// step(): activity, the speed and turn gates, the swath, and the entry events, sampled at the
// latest pose or along the track of node reports (sensing_track.hpp).
#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include "hazard/engine.hpp"
#include "hazard/time_rules.hpp"
#include "base/text.hpp"

namespace hazard {

namespace {

std::string no_node_report_warning(const std::string& vname) {
  return "No NODE_REPORT received for " + vname;
}

}  // namespace

// A LAT/LON-only report was placed by the parser (geodesy.hpp); the engine only sees x/y.
void Engine::handle_node_report(const NodeReport& r, double now_s, Outputs& out) {
  const auto id = vehicle_id(r.name, now_s, out);
  if (!id) return;  // the vehicle table is full (warned, counted)
  VehicleState& v = vehicles_[*id];
  v.pose = Pose{{r.x_m, r.y_m}, r.heading_deg, r.speed_mps};
  if (v.heading_history) v.heading_history->add(r.heading_deg, now_s);
  if (track_mode()) add_to_track(v, out);
  if (v.warned_no_node_report) {
    out.retracted_run_warnings.push_back(no_node_report_warning(v.name));
    v.warned_no_node_report = false;
  }
}

// A sensor request switches the sensor on for kSensorActiveWindow_s and keeps the vehicle's
// width held (settings.cpp).
void Engine::handle_sensor_request(const SensorRequest& r, double now_s, Outputs& out) {
  const auto id = vehicle_id(r.vname, now_s, out);
  if (!id) return;  // the vehicle table is full (warned, counted)
  VehicleState& v = vehicles_[*id];
  ++v.counters.sensor_requests;
  v.last_sensor_request_s = now_s;
  v.last_width_claim_s = now_s;
}

bool Engine::active(const VehicleState& v, double now_s) const {
  return v.last_sensor_request_s &&
         !elapsed_at_least(now_s, *v.last_sensor_request_s, kSensorActiveWindow_s);
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
  // Without visuals or a track the swath serves the entries alone: none while the sensor is off
  // (its state frozen), none with nothing inside and no object near.
  if (!effects_.swath_visuals && !track_mode() && !(on && (!v.inside.empty() || !quiet(v)))) {
    return;
  }
  const Swath swath(v.pose->position_m, v.pose->heading_deg, v.setting->width_m,
                    config_.swath_length_m);
  if (effects_.swath_visuals) post_swath(v, swath, on, out);
  if (track_mode()) return sense_track(v, now_s, out);  // gated per report (sensing_track.hpp)
  // During a blackout nothing changes, not even inside/outside (differences.md "Pass").
  if (on) update_entries(v, swath, now_s, out);
}

// A point the swath contains lies within W + L/2 (plus rounding) of its centre on each axis;
// `reach` adds a metre. The box is queried again after kQuietSlack_m of travel (the field never
// moves).
bool Engine::quiet(VehicleState& v) const {
  constexpr double kQuietSlack_m = 10.0;
  const double reach = v.setting->width_m + config_.swath_length_m / 2.0 + 1.0;
  return v.quiet_box.nothing_near(v.pose->position_m, reach, kQuietSlack_m, [&](const Box& box) {
    bool none = true;
    field_.grid().for_each_in_box(box, [&](ObjectId, glm::dvec2 o) {
      if (o.x >= box.min_x && o.x <= box.max_x && o.y >= box.min_y && o.y <= box.max_y) {
        none = false;
      }
    });
    return none;
  });
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

// Sampling (the default; docs/accuracy.md): the objects inside the swath at the latest pose,
// against the objects inside at the last sensor-on iteration.
void Engine::update_entries(VehicleState& v, const Swath& swath, double now_s, Outputs& out) {
  scratch_inside_.clear();
  field_.grid().for_each_in_box(swath.bounds(), [&](ObjectId id, glm::dvec2 position) {
    if (swath.contains(position)) scratch_inside_.push_back(id);
  });
  std::sort(scratch_inside_.begin(), scratch_inside_.end());
  // A sensor event is an object inside now that was not inside before (into a reused vector:
  // every active vehicle, every iteration).
  scratch_entering_.clear();
  std::set_difference(scratch_inside_.begin(), scratch_inside_.end(), v.inside.begin(),
                      v.inside.end(), std::back_inserter(scratch_entering_));
  v.inside.swap(scratch_inside_);
  for (ObjectId id : scratch_entering_) roll_detection(v, id, v.pose->heading_deg, now_s, out);
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
  TrackPose pose{v.pose->position_m, v.pose->heading_deg,
                 gates_pass(v.pose->speed_mps, v.heading_history), false};
  if (!v.track.empty()) pose.teleport = is_teleport(v, v.track.back().position_m, out);
  v.track.push_back(pose);
}

// A jump no vehicle can make between two reports (kMaxSweepJump_m) is not swept: a vehicle that
// reappears 10 km away would otherwise sweep the whole jump (hundreds of thousands of objects
// in a dense field). A fixed distance, not max_vehicle_speed times the elapsed time: the
// driver's clamp can give reports of one mail batch the same time, and the gate may be off.
bool Engine::is_teleport(const VehicleState& v, glm::dvec2 from_m, Outputs& out) {
  const glm::dvec2 d = v.pose->position_m - from_m;
  const double jump_m = std::hypot(d.x, d.y);
  if (!(jump_m > kMaxSweepJump_m)) return false;
  ++drops_.teleports;
  out.run_warnings.push_back(v.name + " jumped " + base::fix(jump_m, 1) +
                             " m between two node reports (more than kMaxSweepJump_m = " +
                             base::fix(kMaxSweepJump_m, 0) + " m); the jump is not swept");
  return true;
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

  // Candidates per run of pieces between teleports: never the box around a jump.
  scratch_candidates_.assign(v.inside.begin(), v.inside.end());
  auto add_candidates = [&](const Box& box) {
    field_.grid().for_each_in_box(box, [&](ObjectId id, glm::dvec2) {
      scratch_candidates_.push_back(id);
    });
  };
  Box box = pieces.front().box;
  for (const TrackPiece& p : pieces) {
    if (p.after_teleport) {
      add_candidates(box);
      box = p.box;
    }
    box = merged(box, p.box);
  }
  add_candidates(box);
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

}  // namespace hazard
