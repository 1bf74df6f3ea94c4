#pragma once
// The load the process benchmark plays, as pure functions (no clock, no sockets): lawnmower
// tracks over the field, the swath test that finds the node report behind a detection, the texts
// it posts, and the AppCast iteration counter it reads back.
//
// Conventions: x east, y north, metres; MOOS headings in degrees clockwise from north.

#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bench {

struct Pose {
  double x_m = 0;
  double y_m = 0;
  double heading_deg = 0;
};

/// An axis-aligned rectangle of the field that one vehicle surveys.
struct Strip {
  double x_min_m = 0;
  double x_max_m = 0;
  double y_min_m = 0;
  double y_max_m = 0;
};

/// The square field [0, side_m]^2 cut into `vehicles` side-by-side strips of equal width.
std::vector<Strip> split_field(double side_m, int vehicles);

/// A lawnmower track over a strip: lanes parallel to y, `lane_spacing_m` apart, the first half
/// a spacing inside the west edge (at least one lane, in the middle of a narrow strip); north
/// along the first lane, across to the next, south, and so on. At the end of the last lane the
/// vehicle retraces its path, so any distance has a pose.
class Lawnmower {
 public:
  Lawnmower(const Strip& strip, double lane_spacing_m);
  /// The pose after `distance_m` (>= 0) along the track; the heading is that of the leg.
  Pose at(double distance_m) const;
  /// Length of one pass over every lane, metres.
  double length_m() const { return cumulative_m_.back(); }
  std::size_t waypoint_count() const { return waypoints_.size(); }

 private:
  std::vector<Pose> waypoints_;       // heading unused
  std::vector<double> cumulative_m_;  // distance from the start to each waypoint
};

/// True if (x_m, y_m) lies in the rectangle centred on `pose`: `half_width_m` to each side and
/// `half_length_m` fore and aft (boundary included).
bool in_swath(const Pose& pose, double x_m, double y_m, double half_width_m, double half_length_m);

/// A node report as the load generator sent it: when (real seconds) and where.
struct SentReport {
  double real_s = 0;
  Pose pose;
};
/// The delay of a detection of (x_m, y_m) received at `received_s`: real seconds since the
/// node report that first put the object in the swath, in the run of consecutive reports with
/// it inside that ends with the latest such report sent before `received_s`. nullopt when no
/// report in `history` (oldest first) had it inside.
std::optional<double> detection_delay(const std::deque<SentReport>& history, double received_s,
                                      double x_m, double y_m, double half_width_m,
                                      double half_length_m);

/// NODE_REPORT text with NAME, X, Y, SPD, HDG, TYPE, TIME and LENGTH.
std::string node_report(std::string_view name, const Pose& pose, double speed_mps, double time_s);

/// The iteration counter (`iter=N`) of an APPCAST string; nullopt if it has none.
std::optional<long long> appcast_iteration(std::string_view appcast);

/// The value of `key` in a comma list of key=value pairs (case-sensitive key), "" if absent.
std::string value_of(std::string_view text, std::string_view key);

/// Everything the mission file of one run needs.
struct MissionSpec {
  int port = 9000;
  double time_warp = 1;
  std::string community = "shoreside";
  double app_tick_hz = 4;
  std::optional<double> idle_app_tick_hz;  ///< IdleAppTick (ours, opt-in); none: not written
  std::string hazard_file;
  double swath_length_m = 5;
  bool show_hazards = false;
};
/// The .moos file: globals and one ProcessConfig block for uFldHazardSensor.
std::string mission_text(const MissionSpec& spec);

}  // namespace bench
