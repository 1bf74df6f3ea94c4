#pragma once
// A kinematic survey vehicle: constant speed, a turn-rate limit, optional low-pass heading noise,
// following a list of waypoints along the lines that join them; "done" after the last one.
//
// Contract
// - Pure and deterministic: the state advances in fixed internal steps of `step_s` on a grid
//   anchored at the start time, so the track does not depend on how often (or with which `now`
//   values) the application calls `advance_to`. The pose reported at a `now` between grid points
//   is a preview of the next step cut at `now` (not stored).
// - The heading never changes faster than `max_turn_rate_dps` (between any two reported poses,
//   including previews). Headings: 0 = north = +y, clockwise, in [0, 360).
// - Steering: toward a point `lead_m` ahead of the vehicle's projection on the current track line
//   (previous waypoint -> next waypoint), which converges onto the line without orbiting a point.
//   A waypoint is reached when within `capture_radius_m`, or when the vehicle has passed the line
//   through the waypoint perpendicular to the track (so a turn wider than the lane spacing cannot
//   make it circle forever). Corners are anticipated: the turn starts where an arc of the minimum
//   turn radius joins the next line, so the vehicle rolls out straight onto the next lane.
// - Heading noise (off by default, `heading_noise_deg = 0`): a first-order Gauss-Markov
//   (Ornstein-Uhlenbeck) disturbance of the commanded heading with stationary standard deviation
//   `heading_noise_deg` and correlation time `heading_noise_tau_s`, drawn from (seed, step).
//   Why low-pass: the sensor blacks out when the SUM of absolute heading steps over 2 s exceeds
//   max_turn_rate; white noise of 1 degree at 4 Hz already sums to about 4.5 deg/s.
//   With the defaults tau = 20 s and noise 1 deg, the steps sum to about 0.4 deg/s (tested).
//   Why off by default: the original Jake vehicles (uSimMarine) had no heading noise either.
// - Cost: linear in simulated time (20 steps per second by default) while following; nothing
//   while idle or done.

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/result.hpp"

namespace mission {

struct VehicleParams {
  double speed_mps = 1.5;           ///< cruise speed, > 0; below the sensor's 2.0 limit (D14)
  double max_turn_rate_dps = 10.0;  ///< turn-rate limit, > 0 (a small AUV turns 5-15 deg/s)
  double heading_noise_deg = 0.0;   ///< stationary std of the disturbance, >= 0; 0 = off
  double heading_noise_tau_s = 20.0;  ///< correlation time of the disturbance, > 0
  double step_s = 0.05;             ///< internal integration step, > 0 (20 Hz)
  std::uint64_t seed = 1;           ///< noise seed
  double capture_radius_m = 5.0;    ///< waypoint reached within this distance, >= 0
  double lead_m = 15.0;             ///< look-ahead along the track line, > 0
};

/// Checks every field: fails naming the first field at fault and its value.
base::Result<void> validate(const VehicleParams& params);

struct Pose {
  glm::dvec2 position_m{0.0, 0.0};  ///< local x east, y north
  double heading_deg = 0.0;         ///< [0, 360)
  double speed_mps = 0.0;           ///< 0 while idle or done
  double time_s = 0.0;
};

class SurveyVehicle {
 public:
  /// `params` must pass `validate` (asserted). The vehicle starts idle at `start` (its time_s is
  /// the grid anchor).
  SurveyVehicle(const VehicleParams& params, const Pose& start);

  /// Replaces the route, starting from the vehicle's committed state; an empty list makes the
  /// vehicle done at once. The first track line runs from the current position.
  void set_waypoints(std::vector<glm::dvec2> waypoints_m);

  /// Advances the committed state over every whole step up to `now_s` and returns the pose at
  /// exactly `now_s`. A `now_s` earlier than the last call returns the pose of the last call.
  Pose advance_to(double now_s);

  bool following() const { return state_.target < waypoints_m_.size(); }
  bool done() const { return done_time_s_.has_value(); }
  /// Grid time at which the last waypoint was reached (nullopt until then).
  std::optional<double> done_time_s() const { return done_time_s_; }
  /// Number of waypoints reached so far in the current route.
  std::size_t waypoints_reached() const { return state_.target; }
  const std::vector<glm::dvec2>& waypoints() const { return waypoints_m_; }

  /// The internal state, for tests and invariant checks.
  struct State {
    glm::dvec2 position_m{0.0, 0.0};
    double heading_deg = 0.0;
    double noise_deg = 0.0;          ///< current heading disturbance
    glm::dvec2 segment_start_m{0.0, 0.0};
    std::size_t target = 0;          ///< index of the waypoint being approached
    bool turning = false;            ///< turning a corner onto the current line
    std::uint64_t step_index = 0;    ///< grid steps since the start
  };
  const State& state() const { return state_; }

 private:
  /// One step of dt_s, in place; `whole_step` false for a preview (the noise state is not
  /// advanced).
  void step(State& s, double dt_s, bool whole_step) const;
  Pose pose_of(const State& s, double time_s) const;
  /// How early the turn toward waypoint `target + 1` starts (metres before `target`).
  double turn_anticipation_m(std::size_t target) const;
  double grid_time(std::uint64_t step_index) const;

  VehicleParams params_;
  double start_time_s_ = 0.0;
  std::vector<glm::dvec2> waypoints_m_;
  /// Per waypoint, computed once per route (step() needs them every step): the track line to
  /// it from the previous one (waypoint 0's from where the route started: segment_start_m while
  /// that is the target), its length and direction (a square root and three divisions saved a
  /// step), how early the turn after it starts, and the line's heading.
  struct Leg {
    glm::dvec2 track_m;
    double length_m;
    glm::dvec2 unit;  ///< track_m / length_m; unused when the length is 0
    double anticipation_m;  ///< turn_anticipation_m(i)
    /// heading_of(waypoint i - waypoint i-1) (0 for i = 0): the desired heading while turning
    /// onto line i.
    double heading_deg;
  };
  std::vector<Leg> legs_;
  State state_;
  std::optional<double> done_time_s_;
  Pose last_pose_;
};

}  // namespace mission
