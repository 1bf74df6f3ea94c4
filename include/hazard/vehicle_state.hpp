#pragma once
// VehicleState: everything the engine knows about one vehicle, in one record.
//
// Contract: a vehicle is found by a small id (VehicleId, assigned in order of first appearance);
// its name appears only at the message edge. Per-(vehicle, object) state lives inside the
// vehicle's record keyed by ObjectId, so together the key is the integer pair (vehicle id, object
// id), never a joined string (N14); it exists only for objects this vehicle has had in its swath.
// Timers are std::optional: nullopt means "never happened" (N11).
// Hot part (read every sensing iteration): pose, setting, sensor-request time, the sorted list of
// objects currently inside the swath. Cold part: the per-object records (pass count and
// credits), queue, counters.
// Memory: a pair costs its hash node and bucket (about 57 bytes with glibc), each
// unused credit 16 bytes in the vehicle's credit pool (credit_lists.hpp; bench/engine/
// pair_state_bench, docs/robustness.md "Soak"). Pairs and credits are kept for the whole run
// (differences.md "Credits", "Passes, dice and reproducibility"): a long mission grows by one
// record per object met and 16 bytes per detection never classified.
// Rejected alternatives: one map for pass counts and another to a std::deque of credits (the
// first layout: a deque allocates a 512-byte block and its map for a single credit, about 770
// bytes per detected pair); a std::vector of credits per object (about 110 bytes per pair with
// one credit, but with its spare capacity and the smaller buffers it leaves behind as it
// grows, the soak's heap held 35 bytes more per credit added, and the soak failed); an
// open-addressing table for the records (it would save part of the 57 bytes, but the records
// stop growing once a vehicle has met its objects; the credits do not).

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/vec2.hpp>

#include "hazard/classify_queue.hpp"
#include "hazard/credit_lists.hpp"
#include "hazard/hazard_field.hpp"
#include "hazard/heading_history.hpp"
#include "hazard/sensing_track.hpp"
#include "hazard/sensor_options.hpp"
#include "hazard/quiet_box.hpp"

namespace hazard {

using VehicleId = std::uint32_t;

/// The latest valid node report.
struct Pose {
  glm::dvec2 position_m{0.0, 0.0};
  double heading_deg = 0.0;  ///< [0, 360)
  double speed_mps = 0.0;
};

/// The setting in force (manual 4): an option plus the chosen pd.
struct SensorSetting {
  OptionIndex option = 0;
  double width_m = 0.0;
  double exp = 1.0;
  double pclass = 0.5;
  double pd = 0.0;
  double pfa = 0.0;  ///< pd^exp
};

/// Report counters (docs/uFldHazardSensor.md; D32).
struct VehicleCounters {
  int sensor_requests = 0;
  int width_attempts = 0;  ///< incl. the automatic default and denied requests
  int width_resets = 0;    ///< successful width settings, incl. the automatic default
  std::optional<double> last_width_reset_s;
  int pd_resets = 0;
  std::optional<double> last_pd_reset_s;
  int detections = 0;
  int hazard_chances = 0;
  int hazard_reports = 0;
  int benign_chances = 0;
  int benign_reports = 0;
  int classify_requests = 0;  ///< all, including refused ones
  int answers = 0;            ///< released
};

/// What the engine keeps per (vehicle, object) pair once the object was in the swath.
struct ObjectRecord {
  /// Sensor events so far (the pass number of the latest event); >= 1.
  std::uint32_t passes = 0;
  /// Unused classification credits, oldest first (in pass order, D7), in the vehicle's pool:
  /// at most kMaxCreditsPerObject from detections, plus those a clear returns.
  CreditList credits;
};

struct VehicleState {
  std::string name;
  std::string variable_suffix;  ///< "_" + upper-cased name
  std::uint64_t name_hash = 0;  ///< dice key

  std::optional<Pose> pose;
  /// The last mail from or about this vehicle (who may be forgotten, engine.hpp kMaxVehicles).
  double last_mail_s = 0.0;
  std::optional<double> last_sensor_request_s;
  /// The last configuration or sensor request: the width is held for kWidthHoldWindow_s after
  /// it (differences.md "Width choice").
  std::optional<double> last_width_claim_s;
  std::optional<SensorSetting> setting;
  /// Start of the min_reset_interval window: the last width change by request (never by the
  /// automatic default, D4).
  std::optional<double> width_window_start_s;
  /// Only when the turn_blackout effect is on.
  std::optional<HeadingHistory> heading_history;
  /// Objects inside the swath at the last sensor-on iteration, sorted.
  std::vector<ObjectId> inside;
  /// Whether an object is near: while none is and none is inside, sensing changes nothing.
  QuietBox quiet_box;
  /// Only with swath_sweep or swath_substeps (empty, never allocated, otherwise): the pose where
  /// the last evaluation ended, then the node reports since (sensing_track.hpp).
  std::vector<TrackPose> track;
  /// Whether track[0] itself has been sensed (false before the first evaluation and after an
  /// iteration at which the vehicle was inactive).
  bool track_start_sensed = false;
  /// More than kMaxTrackPoses reports arrived since the last evaluation (warned once).
  bool track_overflowed = false;

  /// One record per object this vehicle has had in its swath (never removed: the pass count
  /// keys the dice).
  std::unordered_map<ObjectId, ObjectRecord> objects;
  /// The pool holding every record's credits.
  CreditLists credits;
  ClassifyQueue queue;
  std::optional<double> last_release_s;
  std::optional<double> last_top_s;

  VehicleCounters counters;
  bool warned_no_node_report = false;
  bool warned_no_setting = false;
  bool warned_queue_full = false;    ///< kMaxClassifyQueue reached (warned once per episode)
  bool warned_credits_full = false;  ///< kMaxCreditsPerObject reached (warned once)
};

}  // namespace hazard
