#include "HazardMgr_Info.hpp"

#include "HazardMgr.hpp"
#include "mission/hazard_manager.hpp"
#include "mission_app.hpp"
#include "survey_route.hpp"

namespace phazard_mgr {

namespace {

/// Example values of the parameters without a default (the Jake mission's archie).
const std::map<std::string, std::string> kExamples = {
    {"vname", "archie"},
    {"handover_to", "betty"},
    {"report_name", "archie"},
};

}  // namespace

std::string help_text() {
  return mission_app::help_text(
      kAppName,
      "The vehicle-side hazard manager (the role of uFldHazardMgr, done properly): it\n"
      "requests its sensor setting, keeps the sensor on, requests a classification of\n"
      "every detection with a priority from the value of the answer, keeps a Bayesian\n"
      "belief per object, and answers HAZARDSET_REQUEST with the HAZARDSET_REPORT that\n"
      "minimises the expected penalty under UHZ_MISSION_PARAMS. It can hand its\n"
      "detections to another vehicle and plan the receiver's reacquisition route.\n"
      "See docs/missions.md and docs/mission-logic.md.\n");
}

std::string example_text() {
  return mission_app::example_text(
      kAppName, mission_app::example_body(kDefaultAppTick_hz,
                                          {{"The application", &app_parameters()},
                                           {"The manager (docs/mission-logic.md)", &mission::manager_parameters()}},
                                          kExamples));
}

std::string interface_text() {
  const std::vector<mission_app::InterfaceVariable> subscriptions = {
      {"NODE_REPORT", "NAME=archie,X=-52.5,Y=-290,SPD=1.5,HDG=180,TIME=1700000123.25",
       "own pose (node_report_var; other vehicles' reports are skipped)"},
      {"UHZ_CONFIG_ACK_<V>", "vname=archie,width=25,pd=0.9,pfa=0.656,pclass=0.85",
       "the sensor setting in force"},
      {"UHZ_DETECTION_REPORT_<V>", "x=-52,y=-290,label=75", "a detection"},
      {"UHZ_HAZARD_REPORT_<V>", "x=-52,y=-290,label=75,type=hazard", "a classification answer"},
      {"UHZ_MISSION_PARAMS",
       "penalty_missed_hazard=100,penalty_false_alarm=10,...,search_region=pts={...}",
       "the grader's penalties"},
      {"HAZARD_HANDOVER_<V>",
       "source=archie#dest=betty#prior=0.5#label=75,x=-52,y=-290,evidence=2.8414,det=1,...",
       "another vehicle's evidence"},
      {"HAZARDSET_REQUEST_<V>", "true", "post the HAZARDSET_REPORT (see report_wait_max)"},
      {"APPCAST_REQ", "node=jake,app=pHazardMgr,duration=3.0,key=uMAC_438,thresh=any",
       "a request for AppCast reports"},
  };
  std::vector<mission_app::InterfaceVariable> publications = {
      {"UHZ_CONFIG_REQUEST", "vname=archie,width=25,pd=0.9", "the setting wanted, until acked"},
      {"UHZ_SENSOR_REQUEST", "vname=archie", "keeps the sensor on"},
      {"UHZ_CLASSIFY_REQUEST", "vname=archie,label=75,priority=19.2",
       "one per detection, priority = value of the answer"},
      {"HAZARDSET_REPORT", "source=archie#name=archie#x=-52,y=-290,label=75#...",
       "the reported set"},
      {"HAZARD_HANDOVER, HAZARD_HANDOVER_<DEST>",
       "source=archie#dest=betty#prior=0.5#label=75,x=-52,y=-290,evidence=2.8414,...",
       "the hand-over after the report (handover_to)"},
      {usim_survey_vehicle::survey_route_variable_for("<V>"), "pts={-52,-260:-52,-320:...}",
       "the reacquisition route for this vehicle's uSimSurveyVehicle (reacquire)"},
  };
  for (auto& v : mission_app::framework_publications(kAppName)) publications.push_back(v);
  return mission_app::interface_text(
      kAppName, subscriptions, publications,
      "<V> is this vehicle's name in upper case. With suffixed_mail = false the\n"
      "UHZ_*_<V>, HAZARD_HANDOVER_<V> and HAZARDSET_REQUEST_<V> variables are read\n"
      "without the suffix (a vehicle community fed by uFldShoreBroker / pShare).\n");
}

std::string version_text() { return mission_app::version_text(kAppName); }

}  // namespace phazard_mgr
