#pragma once
// Engine: the simulated hazard sensor (manual 3-9, with the
// deliberate differences of docs/differences.md; its interface: docs/messages.md).
//
// Contract: pure and deterministic. Time comes in as `now_s` (seconds, any origin, non-
// decreasing); randomness comes only from Dice keyed by (seed, vehicle, object, pass, purpose);
// every output is returned as an Outputs value. Programs feed it through hazard::Driver
// (driver.hpp), which owns the time clamp and the dispatch of mail by variable name to the
// handlers below, so the app, hazard_replay and the benchmarks cannot differ. Mail stamped at
// or before an iteration's time must be delivered before step() for that time (the caller's loop).
// step(now) runs four phases in order: post the options summary when due; sense (per active
// vehicle in name order: automatic default setting, gates, swath, entry events, detection dice);
// release classification answers (per vehicle in name order, rate-limited); post the next batch
// of the field's visuals while a big field's are still going out (kFieldVisualsPerIteration).
// The pipeline is assembled at construction from the configuration and the field (Effects):
// what a scene does not use is not computed, stored or allocated. Entry events are sampled at
// each iteration's latest pose (the original), or along the track of node reports when
// sub-stepping or sweeping (sensing_track.hpp). LAT/LON-only node reports are placed through
// the setup's GeoPlacement (geodesy.hpp). Interval rules use time_rules.hpp.
// Scale: a sensing vehicle queries the spatial grid for its swath's bounding box only; per-
// (vehicle, object) state exists only for objects that vehicle has had in its swath. While
// nothing is inside, an iteration whose swath lies in a box around an earlier pose known to hold
// no object (QuietBox) builds no swath at all.
// Rejected alternative: evaluating every object per vehicle per iteration (the original;
// docs/performance.md).
// Layout: one file per rule, each named after it: engine.cpp (the vehicles, start-up and step's
// table of contents), settings.cpp (the width choice, who holds a width, configuration requests,
// the options summary), sensing.cpp, detection.cpp, classification.cpp, visuals.cpp,
// interface.cpp, invariants.cpp.

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hazard/config.hpp"
#include "hazard/dice.hpp"
#include "hazard/effects.hpp"
#include "hazard/geodesy.hpp"
#include "hazard/messages/classify_request.hpp"
#include "hazard/messages/config_request.hpp"
#include "hazard/messages/node_report.hpp"
#include "hazard/messages/sensor_clear.hpp"
#include "hazard/messages/sensor_request.hpp"
#include "hazard/outputs.hpp"
#include "hazard/swath.hpp"
#include "hazard/vehicle_state.hpp"

namespace hazard {

/// A sensor request keeps the sensor on this long (docs/differences.md D12).
inline constexpr double kSensorActiveWindow_s = 600.0;
/// A vehicle holds its width (counts against the option's `max`) from its accepted
/// configuration request until this long passes with no configuration or sensor request from
/// it (docs/differences.md D20).
inline constexpr double kWidthHoldWindow_s = 600.0;
/// Default pd of a vehicle that never chose one (manual 4.2, D4).
inline constexpr double kDefaultPd = 0.9;
/// Node reports kept between two iterations when sub-stepping or sweeping; beyond this the
/// oldest is dropped (a guard against reports arriving thousands of times per iteration).
inline constexpr std::size_t kMaxTrackPoses = 4096;

// Bounds on what outside input can make grow (docs/robustness.md "Bounds: the
// engine"). A 100-vehicle, million-object mission never reaches one; reaching one gives a run
// warning naming the bound and a counted drop (BoundDrops, shown in the report), never growth.
/// Vehicles in the table (vehicles). A new name when the table is full takes the place of the
/// vehicle silent longest if that one has had no mail for kForgetSilentAfter_s; otherwise the
/// new vehicle's mail is dropped.
inline constexpr std::size_t kMaxVehicles = 1000;
/// A vehicle with no mail for this long (s) may be forgotten to make room: longer than the
/// sensor's active window and the width hold, so a forgotten vehicle neither senses nor holds
/// a width; its pending answers and credits go with it.
inline constexpr double kForgetSilentAfter_s = 3600.0;
/// Pending classification answers per vehicle (requests); a request beyond it is refused and
/// its credit kept.
inline constexpr std::size_t kMaxClassifyQueue = 10000;
/// Unused classification credits per (vehicle, object) (detections never classified); a
/// detection beyond it is reported but grants no credit. Per vehicle the credits are then
/// bounded by this times the objects in the field (a clear may return queued credits above it:
/// at most kMaxClassifyQueue more).
inline constexpr std::size_t kMaxCreditsPerObject = 100;
/// Longest distance (m) a vehicle may move between two node reports and still have the segment
/// swept (swath_sweep, swath_substeps): beyond it the move is a teleport, warned and counted;
/// only the arrival is sensed (sensing_track.hpp). 500 s at the default speed gate; reports
/// come several times a second.
inline constexpr double kMaxSweepJump_m = 1000.0;

/// Counted drops when a bound was reached (the report shows them when any is non-zero).
struct BoundDrops {
  std::uint64_t vehicles = 0;          ///< mail from a new vehicle refused: table full
  std::uint64_t vehicles_forgotten = 0;  ///< silent vehicles forgotten to make room
  std::uint64_t classify_requests = 0;  ///< refused: the vehicle's queue was full
  std::uint64_t credits = 0;            ///< detections that granted no credit
  std::uint64_t teleports = 0;          ///< node-report jumps not swept
};

/// At most this many objects' visuals (a VIEW_MARKER and, for an aspect object, a VIEW_SEGLIST)
/// are posted by one call (start-up, PMV_CONNECT, restart_field_visuals, or an iteration); a
/// bigger field's visuals follow over successive iterations in load order, so the iteration
/// holds its tick at start-up. A field this small posts everything at once.
inline constexpr std::size_t kFieldVisualsPerIteration = 2000;

/// A MOOS variable of the interface, with an example payload (for --interface and the docs).
struct InterfaceVariable {
  std::string_view name;
  std::string_view example;
  std::string_view meaning;
};

/// One die outcome (for determinism checks and diagnostics; not an output of the app). The
/// names are valid during the observer call only.
struct Decision {
  std::string_view vehicle;
  std::string_view label;
  std::uint32_t pass = 0;
  DiePurpose purpose = DiePurpose::kDetection;
  /// Detection: true if reported. Classification: true if the answer is correct.
  bool outcome = false;
};

/// Slots of the engine's cache in front of the field's label lookup, filled by detections (the
/// slot of a label: mix64(hash_name(label)) modulo this): a classify request names an object
/// detected moments before, and in a field of a million objects the label table's lookup is a
/// cache miss or two. A hit is checked against the label, so a collision is only a miss.
inline constexpr std::size_t kRecentObjectSlots = 4096;

class Engine {
 public:
  Engine(EngineSetup setup, SeedChoice seed);

  /// This engine as built, with another seed: a study over seeds loads the field once
  /// (hazard_replay --seeds). Only before start(): the copy has no start time, vehicles or mail.
  /// `readers` (effects.hpp): a study that reads only which reports were posted passes
  /// kReportCounts, and the copy builds no visual's text.
  Engine with_seed(SeedChoice seed, PostingReaders readers = PostingReaders::kViewers) const;

  /// Start-up: the loader's config warnings and, if show_hazards, the object visuals.
  /// Records `now_s` as the start time (the report's relative times).
  Outputs start(double now_s);
  /// One iteration at `now_s`.
  Outputs step(double now_s);
  /// The field's visuals (object markers and aspect axes) again from the first object: the
  /// first batch now, the rest over the next iterations (kFieldVisualsPerIteration). Nothing
  /// without the hazard_markers effect. Used on PMV_CONNECT and by a reconnecting app.
  void restart_field_visuals(Outputs& out);
  /// Objects whose visuals are still to be posted by the coming iterations.
  std::size_t field_visuals_pending() const { return field_.size() - visuals_cursor_; }
  /// The earliest time at which step() could post anything or change any state if no mail
  /// arrives before it (quiet_time.cpp): `now_s` while a vehicle's sensor is active, an answer
  /// is queued or field visuals are pending; otherwise when UHZ_OPTIONS_SUMMARY falls due. Every
  /// step before that time does nothing, so an app may skip it (moos::MoosApp, IdleAppTick).
  double quiet_until_s(double now_s) const;

  static const std::vector<InterfaceVariable>& subscriptions();
  static const std::vector<InterfaceVariable>& publications();

  const EngineConfig& config() const { return config_; }
  const HazardField& field() const { return field_; }
  const Effects& effects() const { return effects_; }
  /// How LAT/LON-only node reports are placed (a projection only with the geodesy effect).
  const GeoPlacement& placement() const { return placement_; }
  const SeedChoice& seed() const { return seed_; }
  const std::vector<HazardFileStatus>& hazard_files() const { return hazard_files_; }
  std::optional<double> start_time_s() const { return start_time_s_; }
  /// What the bounds above have dropped so far.
  const BoundDrops& drops() const { return drops_; }

  std::optional<VehicleId> find_vehicle(std::string_view name) const;
  const VehicleState& vehicle(VehicleId id) const { return vehicles_[id]; }
  /// Vehicle ids in name order.
  const std::vector<VehicleId>& vehicles_by_name() const { return by_name_; }

  /// Checks the engine's internal invariants (run by the tests after each step): name order,
  /// sorted inside-lists of known objects with a pass each, credits in pass order not beyond the
  /// passes made, settings consistent with their option. Empty when sound.
  std::vector<std::string> invariant_violations() const;

  /// Called for every die rolled (tests pin determinism with it). Empty by default.
  void set_decision_observer(std::function<void(const Decision&)> observer) {
    observer_ = std::move(observer);
  }

 private:
  // Mail, one handler per message, already parsed: Driver::deliver, the one entry point for
  // mail, clamps its time, parses and dispatches (driver.hpp).
  friend class Driver;
  void handle_node_report(const NodeReport& report, double now_s, Outputs& out);
  void handle_sensor_request(const SensorRequest& request, double now_s, Outputs& out);
  void handle_config_request(const ConfigRequest& request, double now_s, Outputs& out);
  void handle_classify_request(const ClassifyRequest& request, double now_s, Outputs& out);
  void handle_sensor_clear(const SensorClear& request, double now_s, Outputs& out);
  /// A viewer connected: the object markers again (only with the hazard_markers effect).
  void handle_viewer_connect(Outputs& out);

  void clear_queue(std::string_view vname, double now_s, Outputs& out);
  void refuse_queue_full(VehicleState& v, std::string_view label, Outputs& out);
  /// One credit for a detection, unless the pair holds kMaxCreditsPerObject (counted drop).
  void grant_credit(VehicleState& v, ObjectId id, ObjectRecord& record, const Credit& credit,
                    Outputs& out);
  /// The next batch of at most kFieldVisualsPerIteration objects' visuals from visuals_cursor_.
  void post_field_visuals_batch(Outputs& out);
  void post_object_visuals(ObjectId id, Outputs& out) const;

  // Settings (D3, D4, D11, D20).
  void set_default_width(VehicleId id, double pd, double now_s, Outputs& out);
  void apply_default_setting(VehicleId id, double now_s, Outputs& out);
  OptionIndex option_or_smallest(std::optional<OptionIndex> choice, const VehicleState& v,
                                 Outputs& out) const;
  void record_width_setting(VehicleState& v, double now_s, bool opens_window);
  void set_option(VehicleState& v, OptionIndex option, double pd);
  bool holds_width(const VehicleState& v, double now_s) const;
  bool option_full(OptionIndex option, VehicleId asking, double now_s) const;
  std::optional<OptionIndex> choose_option(double width_m, VehicleId asking, double now_s) const;
  void post_ack(const VehicleState& v, Outputs& out) const;

  // The phases of step().
  void post_options_summary_if_due(double now_s, Outputs& out);
  void sense(VehicleId id, double now_s, Outputs& out);
  bool sensor_on(const VehicleState& v) const;
  /// True when no object of the field can be in v's swath at its pose (v.quiet_box).
  bool quiet(VehicleState& v) const;
  bool gates_pass(double speed_mps, const std::optional<HeadingHistory>& history) const;
  void post_swath(const VehicleState& v, const Swath& swath, bool on, Outputs& out) const;
  void update_entries(VehicleState& v, const Swath& swath, double now_s, Outputs& out);
  bool track_mode() const { return effects_.swept_swath || effects_.swath_substeps; }
  void add_to_track(VehicleState& v, Outputs& out);
  /// A jump beyond kMaxSweepJump_m from `from_m` to v's pose: warned and counted.
  bool is_teleport(const VehicleState& v, glm::dvec2 from_m, Outputs& out);
  void sense_track(VehicleState& v, double now_s, Outputs& out);
  static void collapse_track(VehicleState& v);
  void roll_detection(VehicleState& v, ObjectId id, double heading_deg, double now_s,
                      Outputs& out);
  void release_classifications(double now_s, Outputs& out);

  bool active(const VehicleState& v, double now_s) const;
  double degradation(const HazardField::Aspect& a, double heading_deg) const;
  /// UHZ_DETECTION_REPORT, then UHZ_DETECTION_REPORT_<V>.
  static void post_detection_report(const VehicleState& v, glm::dvec2 position,
                                    std::string_view label, const HazardField::Aspect* aspect,
                                    Outputs& out);
  /// UHZ_HAZARD_REPORT_<V>, then UHZ_HAZARD_REPORT.
  static void post_hazard_report(const VehicleState& v, glm::dvec2 position,
                                 std::string_view label, ObjectType reported,
                                 const HazardField::Aspect* aspect, Outputs& out);
  /// The id of the vehicle `name`, recorded (in name order) when first seen, its last mail time
  /// set to `now_s`; nullopt (with a warning and a counted drop) when the table is full.
  std::optional<VehicleId> vehicle_id(std::string_view name, double now_s, Outputs& out);
  /// vehicle_id past last_ids_: find_or_add_vehicle, its id then kept in last_ids_.
  std::optional<VehicleId> hashed_vehicle_id(std::string_view name, double now_s, Outputs& out);
  /// The hashed cache (recent_ids_), the name index, else a new record.
  std::optional<VehicleId> find_or_add_vehicle(std::string_view name, double now_s, Outputs& out);
  /// A slot for a new vehicle: a new one below kMaxVehicles, else the place of the vehicle
  /// silent longest if it has been silent for kForgetSilentAfter_s.
  std::optional<VehicleId> free_vehicle_slot(std::string_view name, double now_s, Outputs& out);
  /// Where `name` is or belongs in by_name_.
  std::vector<VehicleId>::const_iterator name_position(std::string_view name) const;
  /// The object labelled `label` (hash_name(label) is `hash`): recent_objects_, else the field.
  std::optional<ObjectId> find_object(std::string_view label, std::uint64_t hash) const;
  /// Remembers a detected object in recent_objects_.
  void remember_object(ObjectId id, std::uint64_t hash);
  /// The vehicle `name` from recent_ids_ when its slot still holds it; nullopt otherwise.
  std::optional<VehicleId> recent_vehicle(std::string_view name, std::size_t slot) const;
  void notify(const VehicleState& v, ObjectId id, std::uint32_t pass, DiePurpose purpose,
              bool outcome) const;

  EngineConfig config_;
  /// UHZ_OPTIONS_SUMMARY's text: the options are fixed at construction, so it is written once.
  std::string options_summary_text_;
  HazardField field_;
  std::vector<std::string> setup_warnings_;
  std::vector<HazardFileStatus> hazard_files_;
  Effects effects_;
  GeoPlacement placement_;
  SeedChoice seed_;
  Dice dice_;

  std::vector<VehicleState> vehicles_;
  std::vector<VehicleId> by_name_;  ///< ids in name order; also the name lookup
  /// A cache in front of the name lookup (mail comes ten times a second per vehicle): the id
  /// last found for a name, in the slot of the name's hash. A hit is checked against the
  /// vehicle's name, so a stale slot (a forgotten vehicle, a collision) is only a miss.
  static constexpr std::size_t kRecentIdSlots = 1024;
  static constexpr VehicleId kNoVehicleId = ~VehicleId{0};
  std::array<VehicleId, kRecentIdSlots> recent_ids_{};
  /// In front of that cache: the ids last found by hashing (mail mostly alternates among a
  /// vehicle or two), replaced in turn; checked against the name like a slot, without a hash.
  /// Filled with an id no vehicle has.
  std::array<VehicleId, 2> last_ids_{kNoVehicleId, kNoVehicleId};
  std::size_t next_last_id_ = 0;
  /// The same in front of the field's label lookup (kRecentObjectSlots).
  std::array<ObjectId, kRecentObjectSlots> recent_objects_{};
  std::optional<double> start_time_s_;
  std::optional<double> last_summary_s_;
  BoundDrops drops_;
  bool warned_vehicle_table_full_ = false;  ///< one warning per episode of a full table
  /// The next object whose visuals are due; field_.size() when none are (nothing scheduled).
  std::size_t visuals_cursor_ = 0;
  std::vector<ObjectId> scratch_inside_;          ///< reused by update_entries and sense_track
  std::vector<ObjectId> scratch_entering_;        ///< reused by update_entries
  std::vector<ObjectId> scratch_candidates_;      ///< reused by sense_track
  std::vector<std::uint32_t> scratch_event_pieces_;  ///< reused by sense_track
  std::function<void(const Decision&)> observer_;
};

}  // namespace hazard
