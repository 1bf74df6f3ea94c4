// pHazardMgr's app class on the in-process bus with a manual clock: which variables it hears
// (differences.md "Who hears what"), its own pose from NODE_REPORT, the setting and sensor
// requests, classification requests, when the HAZARDSET_REPORT is posted, the hand-over, and the
// reacquisition route; and that it posts exactly what libmission's HazardManager decides.
#include <gtest/gtest.h>

#include "HazardMgr.hpp"
#include "HazardMgr_Info.hpp"
#include "app_on_bus.hpp"
#include "hazard/messages/node_report.hpp"
#include "mission/messages/hazard_handover.hpp"
#include "mission/messages/hazardset_report.hpp"
#include "mission/polygon.hpp"
#include "mission/survey.hpp"

namespace phazard_mgr {
namespace {

using mission_test::any_contains;
using mission_test::Bus;
using mission_test::example_block;
using mission_test::mission_text;
using mission_test::run_warning_texts;

constexpr const char* kArchieAlias = "pHazardMgr_archie";
constexpr const char* kBettyAlias = "pHazardMgr_betty";
const char* kAck = "vname=archie,width=25,pd=0.9,pfa=0.656,pclass=0.85";
const char* kDetection = "x=10,y=50,label=75";

std::string pose(const std::string& name, double x, double y, double heading, double time_s,
                 double speed = 1.5) {
  hazard::NodeReport r;
  r.name = name;
  r.x_m = x;
  r.y_m = y;
  r.heading_deg = heading;
  r.speed_mps = speed;
  r.time_s = time_s;
  return hazard::format_node_report(r);
}

mission::Handover handover(const std::string& source, const std::string& dest,
                           std::vector<mission::HandoverObject> objects) {
  mission::Handover h;
  h.source = source;
  h.dest = dest;
  h.objects = std::move(objects);
  return h;
}

class MgrOnBus : public ::testing::Test {
 protected:
  bool start(const std::string& block, const std::string& alias = kArchieAlias) {
    app.emplace();
    alias_ = alias;
    return bus.start(*app, alias, mission_text(alias, block));
  }
  std::vector<std::string> posted(const std::string& var) const { return bus.values_of(var, alias_); }
  /// Acked archie with one detection (and so one classification request).
  void acked_with_detection() {
    bus.post("UHZ_CONFIG_ACK_ARCHIE", kAck);
    app->run_for(1.0);
    bus.post("UHZ_DETECTION_REPORT_ARCHIE", kDetection);
    app->run_for(1.0);
    ASSERT_EQ(posted("UHZ_CLASSIFY_REQUEST").size(), 1u);
  }
  /// Drives archie (or `who`) straight along x = 0 from y0 to y1 at 1.5 m/s, 4 poses a second.
  void drive(const std::string& who, double y0, double y1) {
    const double heading = y1 > y0 ? 0.0 : 180.0;
    const double step_m = 1.5 / 4.0;
    const int steps = static_cast<int>(std::abs(y1 - y0) / step_m);
    for (int i = 0; i <= steps; ++i) {
      const double y = y0 + (y1 > y0 ? 1 : -1) * step_m * i;
      bus.post("NODE_REPORT", pose(who, 0.0, y, heading, bus.bus.moos_time()));
      app->run_for(0.25);
    }
  }

  Bus bus;
  std::optional<HazardMgr> app;
  std::string alias_;
};

const std::string kArchie = "  vname = archie\n";

// ---- setting and sensor requests (docs/mission-logic.md; D12) -------------------------------

TEST_F(MgrOnBus, AsksForItsSettingThenKeepsTheSensorOnOnceAcked) {
  ASSERT_TRUE(start(kArchie + "  swath_width = 25\n  sensor_pd = 0.9\n"));
  app->run_for(2.0);
  EXPECT_EQ(posted("UHZ_CONFIG_REQUEST"), std::vector<std::string>{"vname=archie,width=25,pd=0.9"});
  EXPECT_TRUE(posted("UHZ_SENSOR_REQUEST").empty());
  bus.post("UHZ_CONFIG_ACK_ARCHIE", kAck);
  app->run_for(11.0);
  EXPECT_TRUE(app->manager()->acked());
  // sensor_request_interval 5 s: at once, then twice more in 11 s.
  EXPECT_EQ(posted("UHZ_SENSOR_REQUEST"),
            (std::vector<std::string>{"vname=archie", "vname=archie", "vname=archie"}));
}

// ---- who hears what ----------------------------------------------------------------------

TEST_F(MgrOnBus, OnOneMoosdbItReadsOnlyItsOwnSuffixedVariables_WhoHearsWhat) {
  ASSERT_TRUE(start(kArchie));
  bus.post("UHZ_CONFIG_ACK_BETTY", "vname=betty,width=10,pd=0.9,pfa=0.531,pclass=0.93");
  bus.post("UHZ_CONFIG_ACK", kAck);  // the shoreside's copy: not for vehicle-side apps
  app->run_for(1.0);
  EXPECT_FALSE(app->manager()->acked());
  bus.post("UHZ_CONFIG_ACK_ARCHIE", kAck);
  bus.post("UHZ_DETECTION_REPORT_BETTY", "x=1,y=2,label=9");
  bus.post("UHZ_DETECTION_REPORT", "vname=archie,x=1,y=2,label=8");
  app->run_for(1.0);
  EXPECT_TRUE(posted("UHZ_CLASSIFY_REQUEST").empty());
  bus.post("UHZ_DETECTION_REPORT_ARCHIE", kDetection);
  app->run_for(1.0);
  const auto requests = posted("UHZ_CLASSIFY_REQUEST");
  ASSERT_EQ(requests.size(), 1u);
  EXPECT_EQ(requests[0].rfind("vname=archie,label=75,priority=", 0), 0u) << requests[0];
  EXPECT_EQ(app->mail_variable("HAZARDSET_REQUEST"), "HAZARDSET_REQUEST_ARCHIE");
}

TEST_F(MgrOnBus, WithSuffixedMailFalseItReadsTheBridgedNamesAndChecksVname) {
  ASSERT_TRUE(start(kArchie + "  suffixed_mail = false\n"));
  bus.post("UHZ_CONFIG_ACK", kAck);
  app->run_for(1.0);
  EXPECT_TRUE(app->manager()->acked());
  bus.post("UHZ_DETECTION_REPORT", "vname=betty,x=1,y=2,label=9");  // checked: not ours
  app->run_for(1.0);
  EXPECT_TRUE(posted("UHZ_CLASSIFY_REQUEST").empty());
  EXPECT_TRUE(any_contains(run_warning_texts(app->appcast()), "for 'betty' ignored"));
  bus.post("UHZ_DETECTION_REPORT", kDetection);  // bridged from UHZ_DETECTION_REPORT_ARCHIE
  app->run_for(1.0);
  EXPECT_EQ(posted("UHZ_CLASSIFY_REQUEST").size(), 1u);
}

TEST_F(MgrOnBus, OwnPoseFromItsNodeReportsOnlyAPassWithoutDetectionIsEvidence) {
  ASSERT_TRUE(start(kArchie));
  bus.post("UHZ_CONFIG_ACK_ARCHIE", kAck);
  app->run_for(1.0);
  // Pass 1 northward: the object at (10, 50) is detected.
  drive("archie", 0.0, 45.0);
  bus.post("UHZ_DETECTION_REPORT_ARCHIE", kDetection);
  drive("archie", 45.0, 100.0);
  // Another vehicle flies back over it: its reports are not archie's pose.
  drive("betty", 100.0, 0.0);
  app->run_for(20.0);
  EXPECT_EQ(app->manager()->counters().missed_passes, 0);
  // Archie flies back over it (after a stop that lets the turn-rate window clear): no
  // detection this time, a missed pass once the detection latency has passed.
  for (int i = 0; i < 20; ++i) {
    bus.post("NODE_REPORT", pose("archie", 0.0, 100.0, 180.0, bus.bus.moos_time(), 0.0));
    app->run_for(0.25);
  }
  drive("archie", 100.0, 0.0);
  app->run_for(15.0);
  EXPECT_EQ(app->manager()->counters().missed_passes, 1);
}

TEST_F(MgrOnBus, MalformedMailIsARunWarningNamingTheVariable) {
  ASSERT_TRUE(start(kArchie));
  bus.post("UHZ_CONFIG_ACK_ARCHIE", "vname=archie,width=25");
  bus.post("UHZ_DETECTION_REPORT_ARCHIE", "x=1,label=3");
  bus.post("NODE_REPORT", "NAME=archie,X=1");
  bus.post("HAZARD_HANDOVER_ARCHIE", "dest=archie");
  bus.post("UHZ_MISSION_PARAMS", "penalty_false_alarm=lots");
  app->run_for(1.0);
  const auto w = run_warning_texts(app->appcast());
  for (const char* v : {"UHZ_CONFIG_ACK_ARCHIE ignored", "UHZ_DETECTION_REPORT_ARCHIE ignored",
                        "NODE_REPORT ignored", "HAZARD_HANDOVER_ARCHIE ignored",
                        "UHZ_MISSION_PARAMS ignored"})
    EXPECT_TRUE(any_contains(w, v)) << v << " in " << ::testing::PrintToString(w);
  EXPECT_FALSE(app->manager()->acked());
}

TEST_F(MgrOnBus, MissionParamsSetThePenalties) {
  ASSERT_TRUE(start(kArchie));
  bus.post("UHZ_MISSION_PARAMS", "penalty_missed_hazard=7,penalty_false_alarm=3,max_time=0");
  app->run_for(1.0);
  EXPECT_DOUBLE_EQ(app->manager()->penalties().missed_hazard, 7.0);
  EXPECT_DOUBLE_EQ(app->manager()->penalties().false_alarm, 3.0);
}

TEST_F(MgrOnBus, ARepeatOfTheAppliedMissionParamsIsNotParsedAgain) {
  ASSERT_TRUE(start(kArchie));
  const char* a = "penalty_missed_hazard=7,penalty_false_alarm=3,max_time=0";
  const char* b = "penalty_missed_hazard=9,penalty_false_alarm=2,max_time=0";
  for (int i = 0; i < 5; ++i) {
    bus.post("UHZ_MISSION_PARAMS", a);
    app->run_for(1.0);
  }
  EXPECT_EQ(app->mission_params_parsed(), 1);
  bus.post("UHZ_MISSION_PARAMS", b);
  app->run_for(1.0);
  EXPECT_DOUBLE_EQ(app->manager()->penalties().missed_hazard, 9.0);
  bus.post("UHZ_MISSION_PARAMS", a);  // back to a: applied again
  app->run_for(1.0);
  EXPECT_EQ(app->mission_params_parsed(), 3);
  EXPECT_DOUBLE_EQ(app->manager()->penalties().missed_hazard, 7.0);
  EXPECT_DOUBLE_EQ(app->manager()->penalties().false_alarm, 3.0);
}

TEST_F(MgrOnBus, RejectedMissionParamsAreParsedAndWarnedEveryTime) {
  ASSERT_TRUE(start(kArchie));
  for (int i = 0; i < 3; ++i) {
    bus.post("UHZ_MISSION_PARAMS", "penalty_missed_hazard=-1,penalty_false_alarm=3");
    app->run_for(1.0);
  }
  EXPECT_EQ(app->mission_params_parsed(), 3);
  EXPECT_TRUE(any_contains(run_warning_texts(app->appcast()), "negative penalty"));
}

// ---- the report --------------------------------------------------------------------------

TEST_F(MgrOnBus, ReportWaitsForTheDetectionLatencyAndTheOutstandingAnswers) {
  ASSERT_TRUE(start(kArchie + "  report_name = archie\n  detection_latency = 10\n"));
  acked_with_detection();
  bus.post("HAZARDSET_REQUEST_ARCHIE", "true");
  app->run_for(20.0);  // past the latency, but the classification answer is outstanding
  EXPECT_TRUE(posted("HAZARDSET_REPORT").empty());
  EXPECT_EQ(app->outstanding_answers(), 1);
  bus.post("UHZ_HAZARD_REPORT_ARCHIE", "x=10,y=50,label=75,type=hazard");
  app->run_for(1.0);
  const auto reports = posted("HAZARDSET_REPORT");
  ASSERT_EQ(reports.size(), 1u);
  // Exactly the library's report (the app is a thin adapter).
  EXPECT_EQ(reports[0], mission::format_hazardset_report(app->manager()->make_report()));
  EXPECT_EQ(reports[0], "source=archie#name=archie#x=10,y=50,label=75");
  app->run_for(10.0);
  EXPECT_EQ(posted("HAZARDSET_REPORT").size(), 1u);  // one request, one report
}

TEST_F(MgrOnBus, ReportWithNothingOutstandingComesOneLatencyAfterTheRequest) {
  ASSERT_TRUE(start(kArchie + "  detection_latency = 10\n"));
  app->run_for(1.0);
  const double requested_s = bus.bus.moos_time();
  bus.post("HAZARDSET_REQUEST_ARCHIE", "true");
  app->run_for(9.0);
  EXPECT_TRUE(posted("HAZARDSET_REPORT").empty());
  app->run_for(2.0);
  const auto reports = bus.bus.postings_of("HAZARDSET_REPORT");
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_NEAR(reports[0].time - requested_s, 10.0, 0.5);
  EXPECT_EQ(reports[0].sval, "source=archie");
}

TEST_F(MgrOnBus, ReportWaitMaxForcesTheReport) {
  ASSERT_TRUE(start(kArchie + "  report_wait_max = 30\n"));
  acked_with_detection();
  bus.post("HAZARDSET_REQUEST_ARCHIE", "true");
  app->run_for(29.0);
  EXPECT_TRUE(posted("HAZARDSET_REPORT").empty());
  app->run_for(2.0);
  EXPECT_EQ(posted("HAZARDSET_REPORT").size(), 1u);
  bool event = false;
  for (const auto& e : app->appcast().events())
    event = event || e.find("1 classification answers outstanding") != std::string::npos;
  EXPECT_TRUE(event);
}

TEST_F(MgrOnBus, HandOverFollowsTheReport) {
  ASSERT_TRUE(start(kArchie + "  handover_to = betty\n  detection_latency = 0\n"));
  acked_with_detection();
  bus.post("UHZ_HAZARD_REPORT_ARCHIE", "x=10,y=50,label=75,type=benign");
  bus.post("HAZARDSET_REQUEST_ARCHIE", "true");
  app->run_for(1.0);
  std::vector<std::string> order;
  for (const auto& v : bus.variables_posted_by(kArchieAlias))
    if (v == "HAZARDSET_REPORT" || v.rfind("HAZARD_HANDOVER", 0) == 0) order.push_back(v);
  EXPECT_EQ(order, (std::vector<std::string>{"HAZARDSET_REPORT", "HAZARD_HANDOVER",
                                             "HAZARD_HANDOVER_BETTY"}));
  const auto text = posted("HAZARD_HANDOVER_BETTY");
  ASSERT_EQ(text.size(), 1u);
  EXPECT_EQ(text[0], mission::format_handover(app->manager()->make_handover("betty")));
  EXPECT_EQ(posted("HAZARD_HANDOVER"), text);
}

TEST_F(MgrOnBus, TheReportWaitsForTheAwaitedHandOvers) {
  ASSERT_TRUE(start("  vname = deb\n  await_handovers_from = abe, ben\n  detection_latency = 0\n",
                    "pHazardMgr_deb"));
  bus.post("HAZARDSET_REQUEST_DEB", "true");
  bus.post("HAZARD_HANDOVER_DEB", mission::format_handover(handover(
                                      "abe", "deb", {{"7", 1.0, 2.0, {3.0, 1, 0, 1, 0}}})));
  app->run_for(5.0);
  EXPECT_TRUE(posted("HAZARDSET_REPORT").empty());
  bus.post("HAZARD_HANDOVER_DEB", mission::format_handover(handover(
                                      "ben", "deb", {{"8", 5.0, 6.0, {-3.0, 1, 0, 0, 1}}})));
  app->run_for(1.0);
  const auto reports = posted("HAZARDSET_REPORT");
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0], "source=deb#x=1,y=2,label=7");  // the fleet's answer: abe's hazard
}

// ---- reacquisition (manual 13.1: the hand-over is a real message here) --------------------

TEST_F(MgrOnBus, HandOverIsAnsweredWithTheLibrarysReacquisitionRoute) {
  ASSERT_TRUE(start("  vname = betty\n  reacquire = true\n  reacquire_leg = 20\n", kBettyAlias));
  bus.post("NODE_REPORT", pose("betty", -190, -40, 180, bus.bus.moos_time(), 0.0));
  bus.post("NODE_REPORT", pose("archie", 300, -300, 0, bus.bus.moos_time()));  // not betty's
  app->run_for(1.0);
  bus.post("HAZARD_HANDOVER_BETTY",
           mission::format_handover(handover("archie", "betty",
                                             {{"75", -52, -290, {2.8, 1, 0, 1, 0}},
                                              {"82", -41, -246, {-1.4, 1, 0, 0, 1}}})));
  app->run_for(1.0);
  const auto routes = posted("SURVEY_ROUTE_BETTY");
  ASSERT_EQ(routes.size(), 1u);
  const auto expected = mission::plan_reacquire_route(
      {-190, -40}, {{-52, -290}, {-41, -246}}, mission::ReacquireOptions{20.0});
  EXPECT_EQ(routes[0], mission::format_points(expected));
}

TEST_F(MgrOnBus, RouteWaitsForTheFirstOwnPose) {
  ASSERT_TRUE(start("  vname = betty\n  reacquire = true\n", kBettyAlias));
  bus.post("HAZARD_HANDOVER_BETTY", mission::format_handover(handover(
                                        "archie", "betty", {{"75", -52, -290, {2.8, 1, 0, 1, 0}}})));
  app->run_for(2.0);
  EXPECT_TRUE(posted("SURVEY_ROUTE_BETTY").empty());
  bus.post("NODE_REPORT", pose("betty", 0, 0, 180, bus.bus.moos_time(), 0.0));
  app->run_for(1.0);
  EXPECT_EQ(posted("SURVEY_ROUTE_BETTY").size(), 1u);
}

TEST_F(MgrOnBus, EmptyHandOverGivesAOnePointRouteSoTheVehicleFinishes) {
  ASSERT_TRUE(start("  vname = betty\n  reacquire = true\n", kBettyAlias));
  bus.post("NODE_REPORT", pose("betty", -190, -40, 180, bus.bus.moos_time(), 0.0));
  bus.post("HAZARD_HANDOVER_BETTY", mission::format_handover(handover("archie", "betty", {})));
  app->run_for(1.0);
  EXPECT_EQ(posted("SURVEY_ROUTE_BETTY"), std::vector<std::string>{"pts={-190,-40}"});
}

TEST_F(MgrOnBus, WithoutReacquireAHandOverPostsNoRoute) {
  ASSERT_TRUE(start("  vname = betty\n", kBettyAlias));
  bus.post("NODE_REPORT", pose("betty", -190, -40, 180, bus.bus.moos_time(), 0.0));
  bus.post("HAZARD_HANDOVER_BETTY", mission::format_handover(handover(
                                        "archie", "betty", {{"75", -52, -290, {2.8, 1, 0, 1, 0}}})));
  app->run_for(1.0);
  EXPECT_TRUE(posted("SURVEY_ROUTE_BETTY").empty());
  EXPECT_EQ(app->manager()->beliefs().size(), 1u);
}

// ---- configuration -----------------------------------------------------------------------

TEST_F(MgrOnBus, BadValuesAreConfigWarningsNamingFileLineAndValue) {
  ASSERT_TRUE(start(kArchie + "  sensor_pd = 1.5\n  reacquire_leg = 0\n  handover_to = a b\n"
                              "  mystery = 1\n"));
  const auto& w = app->appcast().config_warnings();
  const std::string at = (bus.dir / "m.moos").string() + ":";
  const int first = mission_test::first_block_line();
  EXPECT_TRUE(any_contains(w, at + std::to_string(first + 1) + ": parameter sensor_pd=1.5"));
  EXPECT_TRUE(any_contains(w, at + std::to_string(first + 2) + ": parameter reacquire_leg='0'"));
  EXPECT_TRUE(any_contains(w, at + std::to_string(first + 3) + ": parameter handover_to='a b'"));
  EXPECT_TRUE(any_contains(w, at + std::to_string(first + 4) + ": unknown parameter 'mystery'"));
  EXPECT_EQ(app->manager()->config().pd, 0.9);
}

TEST_F(MgrOnBus, VehicleNameDefaultsToTheCommunity_Spec13) {
  ASSERT_TRUE(start(""));
  EXPECT_EQ(app->manager()->config().vname, "jake");
}

TEST(MgrInfo, ExampleBlockLoadsWithoutWarnings_Practice5) {
  const auto block = example_block(example_text());
  ASSERT_TRUE(block);
  HazardMgr app;
  Bus bus;
  ASSERT_TRUE(bus.start(app, kAppName, mission_text(kAppName, *block)));
  EXPECT_TRUE(app.appcast().config_warnings().empty())
      << ::testing::PrintToString(app.appcast().config_warnings());
  EXPECT_EQ(app.app_config().handover_to, "betty");
}

TEST(MgrInfo, InterfaceNamesEveryVariableTheAppUses) {
  const std::string text = interface_text();
  for (const char* v : {"UHZ_CONFIG_ACK_<V>", "UHZ_DETECTION_REPORT_<V>", "UHZ_HAZARD_REPORT_<V>",
                        "UHZ_MISSION_PARAMS", "HAZARD_HANDOVER_<V>", "HAZARDSET_REQUEST_<V>",
                        "UHZ_CONFIG_REQUEST", "UHZ_SENSOR_REQUEST", "UHZ_CLASSIFY_REQUEST",
                        "HAZARDSET_REPORT", "SURVEY_ROUTE_<V>", "NODE_REPORT"})
    EXPECT_NE(text.find(v), std::string::npos) << v;
  EXPECT_NE(help_text().find("Usage: pHazardMgr file.moos"), std::string::npos);
}

}  // namespace
}  // namespace phazard_mgr
