// uFldHazardMetric's app class on the in-process bus with a manual clock: the hazard file read
// relative to the mission, start-up postings (kept until connected), grading a report with the
// original's outputs in the original's order, HAZARD_SEARCH_START, the periodic
// UHZ_MISSION_PARAMS, and configuration warnings that name their place.
#include <gtest/gtest.h>

#include "HazardMetric.hpp"
#include "HazardMetric_Info.hpp"
#include "app_on_bus.hpp"
#include "mission/messages/hazardset_eval.hpp"
#include "mission/messages/hazardset_report.hpp"

namespace ufld_hazard_metric {
namespace {

using mission_test::any_contains;
using mission_test::Bus;
using mission_test::example_block;
using mission_test::mission_text;
using mission_test::run_warning_texts;
using test_support::write_file;

const char* kTruth =
    "// two hazards, two benign objects\n"
    "region = pts={0,0:100,0:100,-100:0,-100}\n"
    "hazard = x=10,y=-10,label=h1,type=hazard\n"
    "hazard = x=20,y=-20,label=h2,type=hazard\n"
    "hazard = x=30,y=-30,label=b1,type=benign\n"
    "hazard = x=40,y=-40,label=b2,type=benign\n";

class MetricOnBus : public ::testing::Test {
 protected:
  bool start(const std::string& block, const std::string& truth = kTruth) {
    write_file(bus.dir / "fields/truth.txt", truth);
    app.emplace();  // the hazard file is read from the mission's folder, bus.dir
    return bus.start(*app, kAppName, mission_text(kAppName, block));
  }
  std::vector<std::string> posted(const std::string& var) const { return bus.values_of(var, kAppName); }
  Bus bus;
  std::optional<HazardMetricApp> app;
};

const std::string kBlock = "  hazard_file = fields/truth.txt\n";

TEST_F(MetricOnBus, StartupPostsTheRegionAndTheMissionParams_Spec14_2) {
  ASSERT_TRUE(start(kBlock + "  penalty_false_alarm = 25\n"));
  app->run_for(1.0);
  const auto region = posted("VIEW_POLYGON");
  ASSERT_EQ(region.size(), 1u);
  EXPECT_NE(region[0].find("label=search_region"), std::string::npos);
  const auto params = posted("UHZ_MISSION_PARAMS");
  ASSERT_GE(params.size(), 1u);
  EXPECT_NE(params[0].find("penalty_false_alarm=25"), std::string::npos);
  EXPECT_NE(params[0].find("search_region=pts={0,0:100,0:100,-100:0,-100}"), std::string::npos);
  EXPECT_EQ(app->metric().truth().size(), 4u);
  EXPECT_TRUE(app->appcast().config_warnings().empty());
}

TEST_F(MetricOnBus, StartupPostingsWaitForTheConnection) {
  write_file(bus.dir / "fields/truth.txt", kTruth);
  HazardMetricApp late;
  bus.comms = bus.bus.connect(kAppName);
  bus.comms->simulate_disconnect();
  moos::AppSettings settings;
  settings.app_name = settings.moos_name = kAppName;
  settings.config_lines = {{"hazard_file", "fields/truth.txt", "m.moos", 6}};
  settings.mission_directory = bus.dir.path().string();
  ASSERT_TRUE(late.start(*bus.comms, settings));
  EXPECT_TRUE(bus.bus.postings_of("UHZ_MISSION_PARAMS").empty());
  ASSERT_TRUE(bus.comms->simulate_reconnect());
  late.run_for(0.25);
  EXPECT_EQ(bus.bus.postings_of("VIEW_POLYGON").size(), 1u);
  EXPECT_GE(bus.bus.postings_of("UHZ_MISSION_PARAMS").size(), 1u);
}

TEST_F(MetricOnBus, GradesAReportWithTheOriginalsOutputsInOrder_Spec14_2) {
  ASSERT_TRUE(start(kBlock));
  app->run_for(1.0);
  bus.post("HAZARDSET_REPORT", "source=archie#name=arch#x=10,y=-10,label=h1#x=30,y=-30,label=b1");
  app->run_for(1.0);
  std::vector<std::string> order;
  for (const auto& v : bus.variables_posted_by(kAppName))
    if (v.rfind("HAZARD", 0) == 0) order.push_back(v);
  EXPECT_EQ(order, (std::vector<std::string>{"HAZARD_SEARCH_SCORE", "HAZARDSET_EVAL_FULL",
                                             "HAZARDSET_EVAL_FULL_ARCHIE", "HAZARDSET_EVAL",
                                             "HAZARDSET_EVAL_ARCHIE"}));
  // By hand: h2 missed (100), b1 a false alarm (10); worst = 2 x 100 + 2 x 10 = 220;
  // norm = 100 (220 - 110) / 220 = 50.
  const auto score = bus.bus.postings_of("HAZARD_SEARCH_SCORE");
  ASSERT_EQ(score.size(), 1u);
  EXPECT_TRUE(score[0].is_double());
  EXPECT_DOUBLE_EQ(score[0].dval, 50.0);
  const auto eval = mission::parse_hazardset_eval(posted("HAZARDSET_EVAL_ARCHIE")[0]);
  ASSERT_TRUE(eval) << eval.error;
  EXPECT_EQ(eval.value->vname, "archie");
  EXPECT_EQ(eval.value->report_name, "arch");
  EXPECT_DOUBLE_EQ(eval.value->total_score, 110.0);
  EXPECT_EQ(eval.value->missed_hazards, 1);
  EXPECT_EQ(eval.value->false_alarms, 1);
  EXPECT_EQ(eval.value->correct_hazards, 1);
  EXPECT_EQ(posted("HAZARDSET_EVAL"), posted("HAZARDSET_EVAL_ARCHIE"));
  EXPECT_NE(posted("HAZARDSET_EVAL_FULL")[0].find("object_report={label=h1,truth=hazard,report=hazard"),
            std::string::npos);
  EXPECT_NE(app->terminal_report().find("archie"), std::string::npos);
}

TEST_F(MetricOnBus, SearchStartSetsTheStartTimeOfTheEvaluation) {
  ASSERT_TRUE(start(kBlock));
  app->run_for(10.0);
  bus.post("HAZARD_SEARCH_START", "true");
  app->run_for(30.0);
  bus.post("HAZARDSET_REPORT", "source=archie#x=10,y=-10,label=h1");
  app->run_for(1.0);
  const auto eval = *mission::parse_hazardset_eval(posted("HAZARDSET_EVAL")[0]).value;
  EXPECT_NEAR(eval.start_time_s, 10.0, 0.5);
  EXPECT_NEAR(eval.total_time_s, 30.0, 0.5);
}

TEST_F(MetricOnBus, MissionParamsAgainEvery50thIteration) {
  ASSERT_TRUE(start(kBlock + "  AppTick = 4\n"));
  app->run_for(100.0);  // 400 iterations
  const auto params = posted("UHZ_MISSION_PARAMS");
  EXPECT_EQ(params.size(), 1u + 400u / 50u);
}

TEST_F(MetricOnBus, RejectedSourcesAreRunWarnings) {
  ASSERT_TRUE(start(kBlock));
  bus.post("HAZARDSET_REPORT", "source=actual#x=10,y=-10,label=h1");
  app->run_for(1.0);
  EXPECT_TRUE(posted("HAZARDSET_EVAL").empty());
  EXPECT_EQ(app->appcast().run_warning_count(), 1u);
}

TEST_F(MetricOnBus, MissingHazardFileIsTheOriginalsRunWarningAndAConfigWarning) {
  ASSERT_TRUE(start("  hazard_file = nowhere.txt\n"));
  EXPECT_TRUE(any_contains(run_warning_texts(app->appcast()),
                           mission::HazardMetric::hazard_file_missing("nowhere.txt")));
  EXPECT_TRUE(any_contains(app->appcast().config_warnings(),
                           ":" + std::to_string(mission_test::first_block_line()) +
                               ": cannot read hazard_file 'nowhere.txt': cannot be opened: "));
}

TEST_F(MetricOnBus, WarningsNameTheirPlace) {
  ASSERT_TRUE(start(kBlock + "  penalty_false_alarm = -3\n  colour = red\n",
                    std::string(kTruth) + "hazard = x=1,y=1,label=z,type=rock\n"));
  const auto& w = app->appcast().config_warnings();
  const std::string at = (bus.dir / "m.moos").string() + ":";
  const int first = mission_test::first_block_line();
  EXPECT_TRUE(any_contains(w, at + std::to_string(first + 1) + ": parameter penalty_false_alarm=-3"));
  EXPECT_TRUE(any_contains(w, at + std::to_string(first + 2) + ": unknown parameter 'colour'"));
  EXPECT_TRUE(any_contains(w, "fields/truth.txt:7"));  // the bad hazard line, by the loader
  EXPECT_EQ(app->metric().truth().size(), 4u);
}

TEST(MetricInfo, ExampleBlockLoadsWithoutWarnings_Practice5) {
  const auto block = example_block(example_text());
  ASSERT_TRUE(block);
  Bus bus;
  write_file(bus.dir / "hazards.txt", kTruth);
  HazardMetricApp app;
  ASSERT_TRUE(bus.start(app, kAppName, mission_text(kAppName, *block)));
  EXPECT_TRUE(app.appcast().config_warnings().empty())
      << ::testing::PrintToString(app.appcast().config_warnings());
  EXPECT_EQ(app.metric().truth().size(), 4u);
}

TEST(MetricInfo, InterfaceNamesEveryVariableTheAppUses) {
  const std::string text = interface_text();
  for (const char* v : {"HAZARDSET_REPORT", "HAZARD_SEARCH_START", "HAZARD_SEARCH_SCORE",
                        "HAZARDSET_EVAL_<SRC>", "HAZARDSET_EVAL_FULL_<SRC>", "UHZ_MISSION_PARAMS",
                        "VIEW_POLYGON"})
    EXPECT_NE(text.find(v), std::string::npos) << v;
}

}  // namespace
}  // namespace ufld_hazard_metric
