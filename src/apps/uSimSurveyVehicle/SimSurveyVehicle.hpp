#pragma once
// SimSurveyVehicle: the uSimSurveyVehicle MOOS application, a thin adapter around libmission's
// kinematic vehicle (mission/vehicle.hpp) and its survey planning (mission/vehicle_config.hpp).
//
// Contract
// - Configuration: the vehicle table (mission::survey_vehicle_parameters: speed, turn-rate limit,
//   heading noise, region + swath_width + overlap + lane_heading for a lawnmower, or waypoints,
//   start pose, report_interval) plus the application's own parameters (app_parameters():
//   vname, node_report_var, vehicle_type, deploy, done_flag). Keys are case-insensitive; a bad
//   value is a configuration warning naming file, line, parameter and value, and the default
//   stays. A region the lawnmower cannot plan is a configuration warning (no route).
// - The vehicle starts idle at the start pose at the start-up time. It follows its route once
//   deployed: at start-up with `deploy = true`, else when DEPLOY, DEPLOY_ALL or DEPLOY_<V> is
//   true (pMarineViewer's DEPLOY button, or moos-cli poke). A route without waypoints leaves it
//   idle (a reacquisition vehicle waits for SURVEY_ROUTE_<V>).
// - SURVEY_ROUTE_<V> (survey_route.hpp) replaces the route from where the vehicle is; it is flown
//   once deployed. A malformed route is a run warning and changes nothing.
// - Every iteration the vehicle advances to the cycle's MOOS time (the track does not depend on
//   the tick, mission/vehicle.hpp); a NODE_REPORT (NAME, X, Y, SPD, HDG, LAT, LON, TIME, TYPE) is
//   posted when `report_interval` has passed since the last one. LAT/LON come from
//   LatOrigin/LongOrigin through GeographicLib (mission/geodesy.hpp) and are omitted when the
//   mission has no origin.
// - When the route is finished the done flags (`done_flag = VAR=value`, like the helm's endflag)
//   are posted once; a new route re-arms them. A value that is a number is posted as a double.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hazard/messages/node_report.hpp"
#include "mission/geodesy.hpp"
#include "mission/params.hpp"
#include "mission/vehicle.hpp"
#include "mission/vehicle_config.hpp"
#include "mission_app.hpp"

namespace usim_survey_vehicle {

inline constexpr const char* kAppName = "uSimSurveyVehicle";
/// MOOS-time Hz: one NODE_REPORT per iteration at the default report_interval of 0.25 s.
inline constexpr double kDefaultAppTick_hz = 4.0;

/// The application's own parameters (the vehicle's are mission::survey_vehicle_parameters()).
const std::vector<mission::ParamInfo>& app_parameters();

moos::AppTraits sim_traits();

/// A flag posted when the route is done.
struct Flag {
  std::string variable;
  std::string value;
  std::optional<double> number;  ///< set when the value is a number (posted as a double)
};

/// Parses `VAR=value`; nullopt when there is no '=' or the variable is empty or has blanks.
std::optional<Flag> parse_flag(std::string_view text);

class SimSurveyVehicle final : public mission_app::MissionApp {
 public:
  SimSurveyVehicle();

  const std::string& vname() const { return vname_; }
  bool deployed() const { return deployed_; }
  /// nullptr until start-up has run.
  const mission::SurveyVehicle* vehicle() const { return vehicle_ ? &*vehicle_ : nullptr; }
  long node_reports_posted() const { return node_reports_posted_; }
  /// Node reports written through hazard::NodeReportMemo::this_thread().format(), which keeps
  /// their parse for the readers of this thread (hazard_study hosts the sensor and managers;
  /// the same results). Off by default: a vehicle's own process has no readers.
  void share_node_report_parses(bool share) { share_node_report_parses_ = share; }
  /// Whether node reports carry LAT and LON (with a LatOrigin/LongOrigin; on by default).
  /// hazard_study turns it off when it keeps no log: every reader it hosts reads X and Y.
  void report_lat_lon(bool report) { report_lat_lon_ = report; }

 protected:
  bool on_start_up() override;
  void on_new_mail(const std::vector<moos::Message>& mail) override;
  void on_iterate() override;
  std::string build_report() override;

 private:
  /// Applies one of the app's own parameters; nullopt if the key is not one of them.
  std::optional<std::string> apply_app_param(const moos::ConfigLine& line);
  void on_deploy(const moos::Message& m);
  void on_route(const moos::Message& m);
  void start_route_if_ready();
  void post_node_report(const mission::Pose& pose);
  void post_done_flags();

  mission::SurveyVehicleConfig config_;
  std::string vname_;
  /// SURVEY_ROUTE_<V> and DEPLOY_<V>, named once at start-up (compared with every message).
  std::string route_var_, deploy_var_;
  std::string node_report_var_ = "NODE_REPORT";
  std::string vehicle_type_ = "UUV";
  bool deployed_ = false;
  std::vector<Flag> done_flags_;
  std::optional<mission::LocalGeodesy> geodesy_;
  std::optional<mission::SurveyVehicle> vehicle_;
  std::vector<glm::dvec2> route_m_;  ///< the route to fly once deployed
  bool route_started_ = false;
  bool done_posted_ = false;
  std::optional<double> last_report_s_;
  mission::Pose last_pose_;
  long node_reports_posted_ = 0;
  bool share_node_report_parses_ = false;
  bool report_lat_lon_ = true;
  long routes_received_ = 0;
  /// The report written each iteration, its name and type set once at start-up, not ten
  /// times a second.
  hazard::NodeReport report_;
};

}  // namespace usim_survey_vehicle
