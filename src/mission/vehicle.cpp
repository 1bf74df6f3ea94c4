// Kinematic survey vehicle. Contract: include/mission/vehicle.hpp.
//
// One step of length dt (Euler with the mid-step heading):
//   1. waypoint bookkeeping: while the target is captured (within capture_radius) or passed (the
//      projection on the track line reaches its end, less the turn anticipation: the distance
//      R tan(turn/2) at which an arc of the minimum turn radius R = speed / rate joins the next
//      line tangentially), move to the next; after the last: done;
//   2. desired heading = bearing to the lead point (projection + lead_m, capped at the target),
//      except while turning a corner: then the new line's own heading until it is reached, which
//      with the anticipation distance of step 1 flies the arc tangent to both lines (pure pursuit
//      alone swings wide and rolls out slowly at about the sensor's 1.5 deg/s blackout rate);
//   3. commanded heading = desired + noise; the heading moves toward it by at most rate * dt;
//   4. position += speed * dt * unit(mid-step heading);
//   5. noise: OU update d' = d * phi + sigma * sqrt(1 - phi^2) * N, phi = exp(-dt / tau)
//      (exact discretisation of the Ornstein-Uhlenbeck process, so the statistics do not depend
//      on step_s).

#include "mission/vehicle.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "mission/random.hpp"
#include "mission/survey.hpp"
#include "base/text.hpp"

namespace mission {

namespace {
constexpr std::uint64_t kNoiseStream = 0x68656164;  // "head": the heading-noise stream
constexpr double kDegPerRad = 57.295779513082320876798;
/// Turns sharper than this are not anticipated further: tan(turn/2) grows without bound near
/// 180 degrees, and a U-turn onto a parallel lane is two 90-degree corners anyway.
constexpr double kMaxAnticipatedTurn_deg = 120.0;

base::Result<void> bad(const char* name, double value, const char* rule) {
  return base::Result<void>::fail(std::string("vehicle parameter ") + name + "=" +
                                  base::fmt(value, 6) + " " + rule);
}
}  // namespace

base::Result<void> validate(const VehicleParams& p) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  auto non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!positive(p.speed_mps)) return bad("speed_mps", p.speed_mps, "must be > 0");
  if (!positive(p.max_turn_rate_dps))
    return bad("max_turn_rate_dps", p.max_turn_rate_dps, "must be > 0");
  if (!non_negative(p.heading_noise_deg))
    return bad("heading_noise_deg", p.heading_noise_deg, "must be >= 0");
  if (!positive(p.heading_noise_tau_s))
    return bad("heading_noise_tau_s", p.heading_noise_tau_s, "must be > 0");
  if (!positive(p.step_s)) return bad("step_s", p.step_s, "must be > 0");
  if (!non_negative(p.capture_radius_m))
    return bad("capture_radius_m", p.capture_radius_m, "must be >= 0");
  if (!positive(p.lead_m)) return bad("lead_m", p.lead_m, "must be > 0");
  return base::Result<void>::ok();
}

SurveyVehicle::SurveyVehicle(const VehicleParams& params, const Pose& start)
    : params_(params), start_time_s_(start.time_s) {
  assert(validate(params));
  state_.position_m = start.position_m;
  state_.heading_deg = base::norm360(start.heading_deg);
  state_.segment_start_m = start.position_m;
  last_pose_ = pose_of(state_, start.time_s);
}

void SurveyVehicle::set_waypoints(std::vector<glm::dvec2> waypoints_m) {
  waypoints_m_ = std::move(waypoints_m);
  legs_.clear();
  for (std::size_t i = 0; i < waypoints_m_.size(); ++i) {
    const glm::dvec2 track = waypoints_m_[i] - (i == 0 ? state_.position_m : waypoints_m_[i - 1]);
    const double length_m = glm::length(track);
    legs_.push_back(Leg{track, length_m, length_m > 0.0 ? track / length_m : glm::dvec2(0.0),
                        turn_anticipation_m(i),
                        i == 0 ? 0.0 : heading_of(waypoints_m_[i] - waypoints_m_[i - 1])});
  }
  state_.target = 0;
  state_.turning = false;
  state_.segment_start_m = state_.position_m;
  done_time_s_.reset();
  if (waypoints_m_.empty()) done_time_s_ = grid_time(state_.step_index);
}

double SurveyVehicle::grid_time(std::uint64_t step_index) const {
  return start_time_s_ + static_cast<double>(step_index) * params_.step_s;
}

void SurveyVehicle::step(State& s, double dt_s, bool whole_step) const {
  // 1. Waypoint bookkeeping (bounded by the number of waypoints). The track line of the target
  //    kept is step 2's too (legs_: the line from segment_start_m to the target).
  const Leg* leg = nullptr;
  while (s.target < waypoints_m_.size()) {
    const glm::dvec2 target = waypoints_m_[s.target];
    leg = &legs_[s.target];
    assert(leg->track_m == target - s.segment_start_m);
    const bool captured = glm::length(target - s.position_m) <= params_.capture_radius_m;
    const double along_m = leg->length_m > 0.0
                               ? glm::dot(s.position_m - s.segment_start_m, leg->track_m) /
                                     leg->length_m
                               : 0.0;
    const bool passed = leg->length_m > 0.0 && along_m >= leg->length_m - leg->anticipation_m;
    if (!captured && !passed) break;
    s.segment_start_m = target;
    ++s.target;
    s.turning = s.target > 0 && s.target < waypoints_m_.size();
  }
  if (s.target >= waypoints_m_.size()) return;  // done: the caller records the time

  // 2. Desired heading: while turning a corner, the new line's heading (a full-rate turn from the
  //    anticipation point is the arc tangent to both lines); then the lead point on the line.
  //    Turning means the line runs from waypoint target - 1, whose heading set_waypoints kept.
  const glm::dvec2 target = waypoints_m_[s.target];
  glm::dvec2 lead_point = target;
  const double length_m = leg->length_m;  // (leg: the target's, from the bookkeeping)
  if (length_m > 0.0) {
    const double along_m =
        std::clamp(glm::dot(s.position_m - s.segment_start_m, leg->unit), 0.0, length_m);
    lead_point = s.segment_start_m + leg->unit * std::min(along_m + params_.lead_m, length_m);
  }
  assert(!s.turning || (s.target > 0 && s.segment_start_m == waypoints_m_[s.target - 1]));
  const double desired_deg = s.turning && length_m > 0.0 ? leg->heading_deg
                                                         : heading_of(lead_point - s.position_m);

  // 3. Rate-limited turn toward the commanded heading.
  const double max_turn_deg = params_.max_turn_rate_dps * dt_s;
  const double turn_deg =
      std::clamp(base::norm180(desired_deg + s.noise_deg - s.heading_deg), -max_turn_deg,
                 max_turn_deg);
  if (std::abs(turn_deg) < max_turn_deg) s.turning = false;  // reached the commanded heading
  const double mid_heading_deg = s.heading_deg + 0.5 * turn_deg;
  s.heading_deg = base::norm360(s.heading_deg + turn_deg);

  // 4. Move.
  s.position_m += heading_vector(mid_heading_deg) * (params_.speed_mps * dt_s);

  // 5. Heading disturbance (only on whole steps; a preview keeps the current value).
  if (params_.heading_noise_deg > 0.0 && whole_step) {
    const double phi = std::exp(-dt_s / params_.heading_noise_tau_s);
    s.noise_deg = s.noise_deg * phi + params_.heading_noise_deg * std::sqrt(1.0 - phi * phi) *
                                          standard_normal(params_.seed, kNoiseStream, s.step_index);
  }
}

double SurveyVehicle::turn_anticipation_m(std::size_t target) const {
  if (target == 0 || target + 1 >= waypoints_m_.size()) return 0.0;
  const glm::dvec2 in = waypoints_m_[target] - waypoints_m_[target - 1];
  const glm::dvec2 out = waypoints_m_[target + 1] - waypoints_m_[target];
  if (glm::length(in) == 0.0 || glm::length(out) == 0.0) return 0.0;
  const double turn_deg = std::min(std::abs(base::norm180(heading_of(out) - heading_of(in))),
                                   kMaxAnticipatedTurn_deg);
  const double radius_m = params_.speed_mps / (params_.max_turn_rate_dps / kDegPerRad);
  // The arc of radius R tangent to both lines starts R tan(turn / 2) before the corner; never
  // more than half of either leg, so short legs are still flown.
  const double lead_in_m = radius_m * std::tan(0.5 * turn_deg / kDegPerRad);
  return std::min({lead_in_m, 0.5 * glm::length(in), 0.5 * glm::length(out)});
}

Pose SurveyVehicle::pose_of(const State& s, double time_s) const {
  const bool moving = s.target < waypoints_m_.size();
  return Pose{s.position_m, s.heading_deg, moving ? params_.speed_mps : 0.0, time_s};
}

Pose SurveyVehicle::advance_to(double now_s) {
  if (now_s < last_pose_.time_s) return last_pose_;
  if (!following()) {
    // Idle or done: nothing moves; keep the grid index current so a new route starts on time.
    const double steps = std::floor((now_s - start_time_s_) / params_.step_s);
    const auto grid_steps = static_cast<std::uint64_t>(std::max(steps, 0.0));
    state_.step_index = std::max(state_.step_index, grid_steps);
    last_pose_ = pose_of(state_, now_s);
    return last_pose_;
  }
  while (following() && grid_time(state_.step_index + 1) <= now_s) {
    const double step_start_s = grid_time(state_.step_index);
    step(state_, params_.step_s, true);
    ++state_.step_index;
    if (!following()) done_time_s_ = step_start_s;
  }
  if (!following()) return advance_to(now_s);
  const double partial_s = now_s - grid_time(state_.step_index);
  if (partial_s > 0.0) {
    State preview = state_;
    step(preview, partial_s, false);
    last_pose_ = pose_of(preview, now_s);
  } else {
    last_pose_ = pose_of(state_, now_s);  // on the grid: no preview to copy
  }
  return last_pose_;
}

}  // namespace mission
