#include "SimSurveyVehicle_Info.hpp"

#include "SimSurveyVehicle.hpp"
#include "mission/vehicle_config.hpp"
#include "mission_app.hpp"
#include "survey_route.hpp"

namespace usim_survey_vehicle {

namespace {

/// Example values of the parameters without a default (the Jake mission's archie).
const std::map<std::string, std::string> kExamples = {
    {"vname", "archie"},
    {"done_flag", "HAZARDSET_REQUEST_ARCHIE=true"},
    {"region", "pts={-150,-75:-150,-400:400,-400:400,-75}"},
};

}  // namespace

std::string help_text() {
  return mission_app::help_text(
      kAppName,
      "A simulated survey vehicle for hazard-search missions: a kinematic vehicle with\n"
      "a speed, a turn-rate limit and optional heading noise that flies a lawnmower over\n"
      "a convex region (lanes spaced for its sensor's swath width) or a list of\n"
      "waypoints, and posts NODE_REPORT (NAME, X, Y, SPD, HDG, LAT, LON, TIME, TYPE).\n"
      "It waits for DEPLOY, follows new routes from SURVEY_ROUTE_<V>, and posts its\n"
      "done flags when the route is finished. See docs/missions.md.\n");
}

std::string example_text() {
  return mission_app::example_text(
      kAppName, mission_app::example_body(kDefaultAppTick_hz,
                                          {{"The application", &app_parameters()},
                                           {"The vehicle and its route (docs/mission-logic.md)", &mission::survey_vehicle_parameters()}},
                                          kExamples));
}

std::string interface_text() {
  const std::vector<mission_app::InterfaceVariable> subscriptions = {
      {"DEPLOY, DEPLOY_ALL, DEPLOY_<V>", "true", "start following the route"},
      {survey_route_variable_for("<V>"), "pts={-52,-260:-52,-320:-41,-276:-41,-216}",
       "a new route, flown from where the vehicle is (pHazardMgr's reacquisition)"},
      {"APPCAST_REQ", "node=jake,app=uSimSurveyVehicle,duration=3.0,key=uMAC_438,thresh=any",
       "a request for AppCast reports"},
  };
  std::vector<mission_app::InterfaceVariable> publications = {
      {"NODE_REPORT",
       "NAME=archie,X=-52.5,Y=-290,SPD=1.5,HDG=180,LAT=43.8223,LON=-70.3309,TIME=1700000123.25,"
       "TYPE=UUV",
       "the vehicle's pose every report_interval (the variable is node_report_var)"},
      {"<done_flag variable>", "true", "each done_flag, once, when the route is finished"},
  };
  for (auto& v : mission_app::framework_publications(kAppName)) publications.push_back(v);
  return mission_app::interface_text(kAppName, subscriptions, publications,
                                     "<V> is the vehicle name in upper case (vname=betty: "
                                     "SURVEY_ROUTE_BETTY).\n");
}

std::string version_text() { return mission_app::version_text(kAppName); }

}  // namespace usim_survey_vehicle
