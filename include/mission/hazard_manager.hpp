#pragma once
// The vehicle-side hazard manager (the role of uFldHazardMgr, done properly;
// docs/mission-logic.md): asks for
// its sensor setting, keeps the sensor on, asks for a classification of every detection with a
// priority it can justify, keeps a belief per object, reports the set that minimises expected
// penalty, and hands its objects to another vehicle.
//
// Contract
// - Pure: the application parses mail (libhazard's message parsers, mission's own) and feeds
//   typed values with `now`; every call returns the postings to make (in order) and texts for the
//   report. No clock, no I/O, deterministic.
// - Sensor setting: posts UHZ_CONFIG_REQUEST (width, pd from the configuration) on the first tick
//   and again every `config_retry_interval_s` until an ack for this vehicle arrives; the acked
//   width, pd, pfa and pclass are what the belief uses. After the first ack it posts
//   UHZ_SENSOR_REQUEST every `sensor_request_interval_s` (one keeps the sensor on 600 s, D12).
// - Beliefs (belief.hpp): per object, logit(prior) + own evidence + the evidence handed over by
//   each other vehicle (latest hand-over per sender).
//   Detection: ln(pd/pfa). Classification answer: +-ln(pclass/(1-pclass)) with the pclass in force
//   when the request was made (the sensor decides the answer then; differences.md "Credits").
//   Missed pass: ln((1-pd)/(1-pfa)) when the manager, replaying the sensor's rules on its own
//   poses, is sure the sensor looked at a known object and said nothing (see "Passes").
// - Passes: the sensor rolls a detection die when an object enters the swath (W to each side,
//   swath_length along, D1/D2) while it is on (turn rate over 2 s <= max_turn_rate and speed <=
//   max_speed; state frozen while off). The manager tracks the same inside/outside state
//   for the objects it knows, from its own poses. A pass counts as missed only when, with no
//   detection within `detection_latency_s` after it ended, (a) the object came within W - margin
//   of the track (not a graze the sensor may have sampled differently) and (b) the turn rate at
//   entry was at most `clear_turn_fraction` of the sensor's limit (not a blackout the two
//   estimates may disagree on). Doubtful passes are dropped, which is not free: a detection on a
//   doubtful pass still counts, so dropping its misses leans toward "hazard". With a 1 m margin
//   that bias showed at 4 standard deviations over 100,000 simulated objects; a straight track
//   keeps its across-track offset at every pose, so 0.1 m suffices, and turns (b) are rare inside
//   a lawnmower's region (tested). When an object is first detected, the passes over its
//   position earlier in the manager's own track are replayed the same way, so its belief includes
//   the misses before the first detection (only observable in hindsight).
// - Classification requests: one per detection (each detection grants the sensor's credit, D7),
//   `priority` = classification_priority(p, pclass, lookahead) of belief.hpp (VOI of this answer
//   and `classify_lookahead - 1` more, mapped to [0, 100]), rounded to 2 decimals.
// - HAZARDSET_REPORT (on request): source = vehicle, name = report_name if set, optionally the
//   minimum-hazard lane (`report_xpath`; off by default because the grader counts the part as an
//   object, see hazardset_report.hpp), then every object with should_report(p) in the order the
//   objects became known.

#include <glm/vec2.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "base/result.hpp"
#include "hazard/heading_history.hpp"
#include "hazard/messages/config_ack.hpp"
#include "hazard/messages/detection_report.hpp"
#include "hazard/messages/hazard_report.hpp"
#include "hazard/quiet_box.hpp"
#include "mission/belief.hpp"
#include "mission/cell_index.hpp"
#include "mission/messages/hazard_handover.hpp"
#include "mission/messages/hazardset_report.hpp"
#include "mission/messages/mission_params.hpp"
#include "mission/outputs.hpp"
#include "mission/params.hpp"
#include "mission/polygon.hpp"
#include "mission/survey.hpp"

namespace mission {

struct ManagerConfig {
  std::string vname;                        ///< this vehicle (its community name), non-empty
  double swath_width_m = 25.0;              ///< requested W (> 0); default 25 as uFldHazardMgr
  double pd = 0.9;                          ///< requested pd, [0, 1]; default 0.9 as uFldHazardMgr
  double prior_hazard = kDefaultPriorHazard;  ///< (0, 1), see belief.hpp
  std::string report_name;                  ///< HAZARDSET_REPORT name= part ("" = none)
  std::optional<ConvexPolygon> region;      ///< for the transit lane; else the grader's
  bool report_xpath = false;                ///< add the xpath= part (counts as an object!)
  bool classify = true;                     ///< ask for classifications
  int classify_lookahead = 2;               ///< answers valued together, [1, 20] (belief.hpp)
  bool count_missed_passes = true;          ///< use passes without a detection as evidence
  // What the manager assumes about the shoreside sensor (its defaults: manual 7.5, 8, D14).
  double sensor_swath_length_m = 5.0;       ///< > 0, total along-track (D1)
  double sensor_max_turn_rate_dps = 1.5;    ///< > 0
  double sensor_max_speed_mps = 2.0;        ///< > 0
  // Pass bookkeeping.
  double pass_margin_m = 0.1;               ///< >= 0, shrink of W for a missed pass
  double clear_turn_fraction = 0.5;         ///< (0, 1], of the sensor's turn-rate limit
  double detection_latency_s = 10.0;        ///< >= 0, mail delay allowed for a detection
  double track_sample_spacing_m = 1.0;      ///< > 0, own-track memory resolution for hindsight
  // Timing.
  double sensor_request_interval_s = 5.0;   ///< > 0
  double config_retry_interval_s = 30.0;    ///< > 0
};

/// The manager's parameter table (params.hpp).
const std::vector<ParamInfo>& manager_parameters();

/// Applies one `key = value` configuration line (key case-insensitive), or fails with a warning
/// naming the parameter and value (the configuration is then unchanged).
base::Result<void> apply_manager_param(ManagerConfig& config, std::string_view key,
                                       std::string_view value);
/// Whole-configuration check: fails with the first problem (names the field and value).
base::Result<void> validate(const ManagerConfig& config);

/// What the manager knows about one object (for reports, pictures and tests).
struct ObjectBelief {
  std::string label;
  glm::dvec2 position_m{0.0, 0.0};
  double p_hazard = 0.0;
  Evidence own;                    ///< this vehicle's observations
  double imported_log_lr = 0.0;    ///< sum over the hand-overs received
  bool handed_over = false;        ///< came in a hand-over
  bool reported = false;           ///< would be in the HAZARDSET_REPORT now
  double classify_priority = 0.0;  ///< priority a request would get now
};

class HazardManager {
 public:
  /// `config` must pass validate() (asserted).
  explicit HazardManager(ManagerConfig config);

  /// Periodic work: config request until acked, sensor requests, resolving finished passes.
  Outputs tick(double now_s);
  /// The same, appended to `out`: a caller that ticks every cycle keeps one Outputs (cleared
  /// between ticks) instead of building and freeing one per tick.
  void tick(double now_s, Outputs& out);
  /// UHZ_CONFIG_ACK(_<V>): acks for another vehicle are ignored with a warning.
  Outputs on_config_ack(const hazard::ConfigAck& ack, double now_s);
  /// The vehicle's own pose (its NODE_REPORT or navigation). It posts nothing: the passes it
  /// ends are resolved by tick() (one call per report, so no empty Outputs to build and publish).
  void on_pose(glm::dvec2 position_m, double heading_deg, double speed_mps, double now_s);
  /// UHZ_DETECTION_REPORT(_<V>): belief update and a classification request.
  Outputs on_detection(const hazard::DetectionReport& report, double now_s);
  /// UHZ_HAZARD_REPORT(_<V>): a classification answer.
  Outputs on_classification(const hazard::HazardReport& report, double now_s);
  /// UHZ_MISSION_PARAMS: penalties (and the region, if none configured).
  Outputs on_mission_params(const MissionParams& params);
  /// HAZARD_HANDOVER(_<V>): evidence from another vehicle; ignored (warning) if not for us.
  Outputs on_handover(const Handover& handover, double now_s);
  /// HAZARDSET_REQUEST: posts HAZARDSET_REPORT.
  Outputs on_hazardset_request(double now_s);

  /// The hand-over of everything this vehicle knows, posted as HAZARD_HANDOVER and
  /// HAZARD_HANDOVER_<DEST>.
  Outputs handover_to(std::string_view dest) const;
  Handover make_handover(std::string_view dest) const;
  /// The reported set now (what on_hazardset_request would post).
  HazardsetReport make_report() const;

  /// A route over the handed-over objects (all known objects when none were handed over).
  std::vector<glm::dvec2> reacquire_route(glm::dvec2 start_m,
                                          const ReacquireOptions& options) const;

  std::vector<ObjectBelief> beliefs() const;
  std::optional<ObjectBelief> belief(std::string_view label) const;
  const Penalties& penalties() const { return penalties_; }
  bool acked() const { return setting_.has_value(); }
  const ManagerConfig& config() const { return config_; }

  struct Counters {
    long detections = 0;
    long classify_requests = 0;
    long classify_answers = 0;
    long missed_passes = 0;      ///< counted as evidence
    long doubtful_passes = 0;    ///< ended without a detection but not counted
    long hindsight_passes = 0;   ///< missed passes found in the track on a first detection
  };
  const Counters& counters() const { return counters_; }

 private:
  struct Setting {
    double width_m;
    double pd;
    double pfa;
    double pclass;
  };
  struct Pass {
    double entered_s = 0.0;
    std::optional<double> exited_s;
    bool reached_core = false;
    bool clear = false;
    bool detected = false;
  };
  struct Record {
    std::string label;
    glm::dvec2 position_m{0.0, 0.0};
    std::optional<double> aspect_deg;          ///< from the detection report, when it has them
    std::optional<double> aspect_min_deg;
    std::optional<double> aspect_max_deg;
    Evidence own;
    std::map<std::string, Evidence> imported;  ///< by sender
    bool handed_over = false;
    bool inside = false;                       ///< the sensor's inside state, as estimated
    std::optional<Pass> pass;                  ///< current or awaiting resolution
    std::optional<double> unmatched_detection_s;  ///< a detection that no pass has claimed
    std::vector<double> pending_pclass;        ///< pclass of each outstanding request, oldest first
  };
  struct TrackSample {
    double time_s;
    glm::dvec2 position_m;
    double heading_deg;
    bool sensor_on;   ///< the sensor's rule, as estimated (and a setting is known)
    bool clear;       ///< turn rate well below the limit (see "Passes")
    double half_width_m;  ///< the acked W then (0 before the first ack)
    double pd;
    double pfa;
  };
  using Id = std::uint32_t;

  double log_odds(const Record& r) const;
  Id find_or_add(std::string_view label, glm::dvec2 position_m);
  std::optional<Id> find(std::string_view label) const;
  void add_track_sample(const TrackSample& sample);
  void update_passes(const TrackSample& sample);
  /// True when no record can be in the footprint of a pose at `position_m` (quiet_).
  bool no_record_near(glm::dvec2 position_m, double half_width_m);
  void resolve_passes(double now_s, Outputs& out);
  void resolve(Record& r, Outputs& out);
  /// (pd, pfa) of each clear pass over r's position that ended before `before_s`.
  std::vector<std::pair<double, double>> hindsight_misses(const Record& r, double before_s) const;
  Outputs request_classification(Record& r);
  ObjectBelief view(const Record& r) const;

  ManagerConfig config_;
  Penalties penalties_;
  std::optional<Setting> setting_;
  std::optional<double> last_config_request_s_;
  std::optional<double> last_sensor_request_s_;
  std::optional<ConvexPolygon> params_region_;  ///< from UHZ_MISSION_PARAMS
  double transit_half_width_m_ = 20.0;          ///< from UHZ_MISSION_PARAMS (docs/mission-logic.md)
  hazard::HeadingHistory headings_;
  std::vector<TrackSample> track_;            ///< thinned own track (hindsight passes)
  std::optional<TrackSample> last_pose_;      ///< the latest pose, always
  std::vector<std::uint32_t> on_prefix_;      ///< sensor-on samples in track_[0, i)
  CellIndex track_cells_;                     ///< track_ indices by cell
  double track_max_half_width_m_ = 0.0;
  std::vector<Record> records_;
  std::unordered_map<std::string, Id> by_label_;
  CellIndex grid_;                            ///< record ids by cell
  /// Around a recent pose: whether grid_ holds no record near it (no_record_near).
  hazard::QuietBox quiet_;
  std::vector<Id> inside_;      ///< ids whose `inside` is true
  std::vector<Id> unresolved_;  ///< ids with a pass that has ended but is not resolved
  Counters counters_;
};

}  // namespace mission
