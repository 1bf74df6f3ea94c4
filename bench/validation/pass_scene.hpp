#pragma once
// The scene of the validation benchmark (docs/validation.md), as pure functions: a grid of
// objects one scripted vehicle passes over in straight lanes, back and forth, and the tallies of
// what a sensor reported about each group of objects.
//
// Conventions: x east, y north, metres; MOOS headings in degrees clockwise from north. The
// vehicle drives along y = 0: east (heading 90) over lane 0, west over lane 1, and so on, each
// lane from x = -margin to x = span + margin, turning on the spot at the lane ends.
//
// Groups of objects:
// - "inside": rows at |y| <= 17 m, 8 m or more within the 25 m swath width, one sensor event
//   per object per lane;
// - "outside": rows at |y| = 33 and 45 m, 8 m or more beyond the swath width: never sensed;
// - "edge_3", "edge_7", "edge_12": hazards 3, 7 and 12 m beyond each lane end, on the track and
//   10 m to either side. A sensor whose swath reaches L metres ahead and behind the vehicle
//   senses those with d <= L once per visit of their lane end (the start counts as a visit of
//   the west end): the swath length of docs/differences.md D1, seen at a lane end where the
//   vehicle turns on the spot (the turn-rate gate switches the sensor off just after).
// Kinds: "H" hazard, "B" benign without hr, "B0" benign with hr=0, "Bh" benign with hr=0.5,
// assigned round-robin so that every kind has the same share of every row.

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace validation {

struct SceneObject {
  std::string label;
  std::string kind;   ///< H, B, B0, Bh
  std::string group;  ///< inside, outside, edge_3, edge_7, edge_12
  double x_m = 0;
  double y_m = 0;
};

struct SceneSpec {
  int columns = 100;        ///< objects per row along the track
  double spacing_m = 4;     ///< between columns
  double margin_m = 40;     ///< lane end beyond the first and last column
  double resemblance = 0.5; ///< hr of the Bh kind
};

/// Every object of the scene, labels "o1", "o2", ... in a fixed order.
std::vector<SceneObject> make_scene(const SceneSpec& spec);
/// The hazard file of the scene (one `hazard = ...` line per object; Bh objects with hr =
/// `resemblance`).
std::string hazard_file_text(const std::vector<SceneObject>& objects, double resemblance);

/// The length of one lane, metres.
double lane_length_m(const SceneSpec& spec);

struct TrackPose {
  double x_m = 0;
  double y_m = 0;
  double heading_deg = 90;
  long long lane = 0;  ///< lanes completed before this pose
};
/// The vehicle's pose after `distance_m` (>= 0) along the lanes.
TrackPose pose_at(const SceneSpec& spec, double distance_m);

/// The passes of the vehicle by one object in `lanes` complete lanes: `lanes` for the inside
/// and outside rows; for an edge object the visits of its lane end (the start included). An
/// inside object has one sensor event per pass, an outside one none, and an edge object one per
/// pass if the swath reaches its distance d ahead of the vehicle, none otherwise.
long long passes_by(const SceneObject& object, long long lanes);

/// What a sensor reported about one group of objects of one kind.
struct Tally {
  long long objects = 0;
  long long passes = 0;      ///< passes_by summed over the objects
  long long detections = 0;
  long long classify_requests = 0;
  long long answers = 0;     ///< hazard reports received
  long long correct = 0;     ///< answers naming the true type
};
/// Key: group + "," + kind; pass_bench writes the pd = 1 control vehicle's groups as "ctrl_" +
/// group.
using Tallies = std::map<std::string, Tally>;

/// The result file: `#` lines of `header` (key=value each), then the CSV header line
/// "group,kind,objects,passes,detections,classify_requests,answers,correct" and one line per
/// tally in key order.
std::string tallies_csv(const std::vector<std::pair<std::string, std::string>>& header,
                        const Tallies& tallies);

}  // namespace validation
