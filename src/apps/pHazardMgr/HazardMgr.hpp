#pragma once
// HazardMgr: the pHazardMgr MOOS application, the vehicle-side hazard manager (the role of the
// original uFldHazardMgr; docs/mission-logic.md), a thin adapter around libmission's HazardManager
// (mission/hazard_manager.hpp), which holds every decision: setting requests, beliefs,
// classification priorities, the reported set, the hand-over and the reacquisition route.
//
// Contract
// - Configuration: the manager table (mission::manager_parameters(): swath_width, sensor_pd,
//   prior_hazard, report_name, classify, ...) plus the application's own parameters
//   (app_parameters()). Keys are case-insensitive; a bad value is a configuration warning naming
//   file, line, parameter and value, and the default stays. The vehicle name is `vname`, else the
//   community name (the original's rule).
// - Who hears what (differences.md "Who hears what"): with `suffixed_mail = true` (default, one
//   MOOSDB for the whole mission) it reads UHZ_CONFIG_ACK_<V>, UHZ_DETECTION_REPORT_<V>,
//   UHZ_HAZARD_REPORT_<V>, HAZARD_HANDOVER_<V> and HAZARDSET_REQUEST_<V>; with `false` (a vehicle
//   community into which uFldShoreBroker / pShare bridge the per-vehicle variables) the same names
//   without the suffix. UHZ_MISSION_PARAMS is read as it is. Its own pose comes from
//   `node_report_var` (NODE_REPORT): reports whose NAME is another vehicle's are skipped silently,
//   since on one MOOSDB every vehicle's reports arrive. Malformed mail is a run warning naming
//   variable and field; the library's own warnings (mail for another vehicle, ...) are passed on.
// - Times: mail is handed over with its own time stamp, never later than the cycle's time; a
//   node report's TIME field, when present, is the pose's time. tick() runs every iteration.
// - HAZARDSET_REQUEST: the report is posted at the first iteration at least `detection_latency`
//   seconds after the request (detections of the last passes may still be on their way) at
//   which no classification answer is outstanding and a hand-over has arrived from every vehicle
//   in `await_handovers_from`; or `report_wait_max` seconds after the request, whichever comes
//   first (answers are released one per min_classify_interval, so the last ones trail the
//   survey). With `handover_to`, the hand-over to that vehicle is posted right after the report.
// - With `reacquire = true`, every hand-over received is answered with a reacquisition route
//   over the handed-over objects (HazardManager::reacquire_route), posted to SURVEY_ROUTE_<V>
//   for this vehicle's uSimSurveyVehicle, from the latest own pose (or at the first pose, if none
//   has arrived yet). A hand-over with no objects gives a one-point route at the vehicle's
//   position, so the vehicle finishes at once and its done flag still asks for the report.

#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "mission/hazard_manager.hpp"
#include "mission/params.hpp"
#include "mission_app.hpp"

namespace phazard_mgr {

inline constexpr const char* kAppName = "pHazardMgr";
inline constexpr double kDefaultAppTick_hz = 4.0;
/// Default longest wait between a HAZARDSET_REQUEST and the report (s): 20 answers at the
/// sensor's default min_classify_interval of 30 s.
inline constexpr double kDefaultReportWaitMax_s = 600.0;
/// Rows of the belief table in the AppCast report (a large field would flood the terminal).
inline constexpr std::size_t kMaxReportRows = 30;

/// The application's own parameters (the manager's are mission::manager_parameters()).
const std::vector<mission::ParamInfo>& app_parameters();

moos::AppTraits manager_traits();

/// The application's own configuration.
struct AppConfig {
  std::string vname;                      ///< "" = the community name
  std::string node_report_var = "NODE_REPORT";
  bool suffixed_mail = true;
  std::string handover_to;                ///< "" = no hand-over
  bool reacquire = false;
  double reacquire_leg_m = 30.0;          ///< ReacquireOptions::leg_half_length_m (> 0)
  std::vector<std::string> await_handovers_from;
  double report_wait_max_s = kDefaultReportWaitMax_s;  ///< >= 0
};

class HazardMgr final : public mission_app::MissionApp {
 public:
  HazardMgr();

  /// nullptr until start-up has run.
  const mission::HazardManager* manager() const { return manager_ ? &*manager_ : nullptr; }
  const AppConfig& app_config() const { return app_; }
  /// Classification requests not answered yet.
  long outstanding_answers() const;
  long reports_posted() const { return reports_posted_; }
  /// UHZ_MISSION_PARAMS texts parsed (a repeat of the text last applied is not parsed again).
  long mission_params_parsed() const { return mission_params_parsed_; }

  /// The variable this app reads for `base` (UHZ_DETECTION_REPORT -> UHZ_DETECTION_REPORT_ARCHIE
  /// with suffixed mail).
  std::string mail_variable(const std::string& base) const;

 protected:
  bool on_start_up() override;
  void on_new_mail(const std::vector<moos::Message>& mail) override;
  void on_iterate() override;
  std::string build_report() override;

 private:
  /// Applies one of the app's own parameters; nullopt if the key is not one of them.
  std::optional<std::string> apply_app_param(const moos::ConfigLine& line);
  /// Any mail but a node report's text (on_new_mail hands those to on_node_report).
  void handle(const moos::Message& m, double time_s);
  void on_node_report(const std::string& text, double time_s);
  void on_handover(const std::string& text, double time_s);
  void on_mission_params(const std::string& text);
  void post_reacquire_route();
  bool report_ready(double now_s) const;
  void post_report(double now_s);
  std::string object_table() const;

  /// The suffixed variables of the contract (mail_variable), named once at start-up: every
  /// message is compared with them.
  struct MailNames {
    std::string config_ack, detection_report, hazard_report, handover, hazardset_request;
  };

  AppConfig app_;
  MailNames mail_names_;
  mission::ManagerConfig config_;
  std::optional<mission::HazardManager> manager_;
  std::optional<glm::dvec2> last_position_m_;
  bool route_pending_ = false;
  std::set<std::string> handovers_from_;
  std::optional<double> report_requested_s_;
  long reports_posted_ = 0;
  long routes_posted_ = 0;
  long mission_params_parsed_ = 0;
  /// The UHZ_MISSION_PARAMS text last applied with nothing to report; nullopt after any other.
  std::optional<std::string> applied_mission_params_;
  double last_mail_time_s_ = 0.0;
  double last_pose_time_s_ = 0.0;
  /// What tick() produced this iteration: one Outputs kept for every tick, not one built and
  /// freed four times a second.
  mission::Outputs tick_out_;
};

}  // namespace phazard_mgr
