#include "HazardMetric_Info.hpp"

#include "HazardMetric.hpp"
#include "mission/metric.hpp"
#include "mission_app.hpp"

namespace ufld_hazard_metric {

std::string help_text() {
  return mission_app::help_text(
      kAppName,
      "The shoreside grader of hazard searches, a drop-in for MOOS-IvP's\n"
      "uFldHazardMetric: the same parameters, messages and score formula.\n"
      "It reads the ground truth (the sensor's hazard file), grades every\n"
      "HAZARDSET_REPORT and posts HAZARD_SEARCH_SCORE and HAZARDSET_EVAL. One fix: with\n"
      "nothing to lose (no objects, or zero penalties) the score is 100 or 0, never NaN.\n"
      "See docs/mission-logic.md.\n");
}

std::string example_text() {
  return mission_app::example_text(
      kAppName, mission_app::example_body(kDefaultAppTick_hz,
                                          {{"The grader", &mission::metric_parameters()}},
                                          {{"hazard_file", "hazards.txt"}}));
}

std::string interface_text() {
  const std::vector<mission_app::InterfaceVariable> subscriptions = {
      {"HAZARDSET_REPORT", "source=archie#name=archie#x=-52,y=-290,label=75#x=41,y=-108,label=53",
       "a vehicle's reported set (graded at once; the latest per source is kept)"},
      {"HAZARD_SEARCH_START", "true", "the search clock starts (any value)"},
      {"APPCAST_REQ", "node=shoreside,app=uFldHazardMetric,duration=3.0,key=uMAC_438,thresh=any",
       "a request for AppCast reports"},
  };
  std::vector<mission_app::InterfaceVariable> publications = {
      {"HAZARD_SEARCH_SCORE", "86.666667", "the normalised score of the latest report (a double)"},
      {"HAZARDSET_EVAL, HAZARDSET_EVAL_<SRC>",
       "vname=archie,report_name=archie,total_score=20,norm_score=86.67,...",
       "the evaluation of a report"},
      {"HAZARDSET_EVAL_FULL, HAZARDSET_EVAL_FULL_<SRC>",
       "...,object_report={label=75,truth=hazard,report=hazard#...}",
       "the evaluation with one entry per ground-truth object"},
      {"UHZ_MISSION_PARAMS",
       "penalty_missed_hazard=100,penalty_nonopt_hazard=50,penalty_false_alarm=10,...",
       "the penalties, at start-up and every 50th iteration"},
      {"VIEW_POLYGON", "pts={-150,-75:-150,-400:400,-400:400,-75},label=search_region,...",
       "the search region (and the transit lane with show_xpath), at start-up"},
  };
  for (auto& v : mission_app::framework_publications(kAppName)) publications.push_back(v);
  return mission_app::interface_text(kAppName, subscriptions, publications,
                                     "<SRC> is the report's source in upper case.\n");
}

std::string version_text() { return mission_app::version_text(kAppName); }

}  // namespace ufld_hazard_metric
