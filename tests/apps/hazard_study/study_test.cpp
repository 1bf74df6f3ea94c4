// hazard_study's runner on the Jake mission (missions/jake/jake.moos): the same study twice is
// byte-identical; lockstep agrees event for event with an independent fixed-tick driver of the
// same app classes on the in-process bus (every Jake app ticks at 4 Hz, so their timing is
// equal); --set naming an unknown block or parameter is an error naming it; a mission that does
// not end stops at max_time with a line that says so.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "HazardMetric.hpp"
#include "HazardMgr.hpp"
#include "HazardSensor.hpp"
#include "SimSurveyVehicle.hpp"
#include "base/text.hpp"
#include "mission_plan.hpp"
#include "mission_run.hpp"
#include "moos/alog.hpp"
#include "moos/bus.hpp"
#include "scratch_files.hpp"
#include "study.hpp"
#include "study_output.hpp"

namespace hazard_study {
namespace {

const std::string kJake = std::string(HAZARD_SOURCE_DIR) + "/missions/jake/jake.moos";

Options jake_options(std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {kJake};
  args.insert(args.end(), extra.begin(), extra.end());
  auto parsed = parse_args(args);
  EXPECT_TRUE(parsed.options) << parsed.error;
  return *parsed.options;
}

MissionPlan jake_plan(const Options& options) {
  std::string error;
  auto plan = load_plan(options, error);
  EXPECT_TRUE(plan) << error;
  return *plan;
}

struct StudyRun {
  int status = 0;
  std::string out, err;
};

StudyRun study(std::vector<std::string> args) {
  auto parsed = parse_args(args);
  EXPECT_TRUE(parsed.options) << parsed.error;
  StudyRun r;
  std::ostringstream out, err;
  r.status = run(*parsed.options, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

TEST(StudyDeterminism, TheSameMissionTwiceGivesTheSameLineAndTheSameLogByteForByte) {
  const Options options = jake_options({"--seed=3"});
  const MissionPlan plan = jake_plan(options);
  std::string log1, log2;
  const MissionResult a = run_mission(plan, options.settings[0], 3, {}, &log1);
  const MissionResult b = run_mission(plan, options.settings[0], 3, {}, &log2);
  EXPECT_EQ(json_line(a), json_line(b));
  EXPECT_EQ(log1, log2);
  EXPECT_EQ(a.end, "graded");
  ASSERT_TRUE(a.score);
  EXPECT_GT(a.detections, 0);
  // Without a log the sensor builds no visuals: the outcome is the same.
  EXPECT_EQ(json_line(run_mission(plan, options.settings[0], 3, {})), json_line(a));
}

// Without a log nothing is built that only a log would read (visuals, statuses, the node
// reports' LAT and LON): each mission's line is the same as with the log.
TEST(StudyDeterminism, WithoutALogEveryMissionEndsAsWithOne) {
  const Options options = jake_options();
  const MissionPlan plan = jake_plan(options);
  for (std::uint64_t seed : {1, 2, 5}) {
    std::string log;
    const MissionResult logged = run_mission(plan, options.settings[0], seed, {}, &log);
    EXPECT_NE(log.find(",LAT=43.8"), std::string::npos) << "the log's node reports have LAT";
    EXPECT_EQ(json_line(run_mission(plan, options.settings[0], seed, {})), json_line(logged))
        << "seed " << seed;
  }
}

TEST(StudyDeterminism, AStudyOverSeedsAndSettingsTwiceIsByteIdentical) {
  const std::vector<std::string> args = {kJake, "--seeds=1..2", "--max-time=2000",
                                         "--setting=w25", "--setting=w20",
                                         "--set=pHazardMgr_archie.swath_width=20"};
  const StudyRun a = study(args), b = study(args);
  EXPECT_EQ(a.status, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_EQ(std::count(a.out.begin(), a.out.end(), '\n'), 4);
  EXPECT_NE(a.out.find("{\"setting\":\"w20\",\"seed\":2,"), std::string::npos) << a.out;
}

/// The same app classes, driven by a fixed 0.25 s tick instead of the lockstep (cycle_if_due
/// on each app in Run-line order at every tick): the log of every posting.
std::string fixed_tick_log(const MissionPlan& plan, const Setting& setting, std::uint64_t seed,
                           double deploy_s, double end_s) {
  moos::ManualClock clock;
  const double t0 = clock.unix_now_s();
  moos::InProcessBus bus(clock, moos::InProcessBus::Options{plan.community, 1.0});
  std::string log = moos::alog_header(plan.community, t0);
  auto runner = bus.connect("hazard_study");
  runner->register_wildcard("*", "*");
  std::vector<std::unique_ptr<moos::MoosApp>> apps;
  std::vector<std::unique_ptr<moos::BusClient>> clients;
  for (const Process& p : plan.processes) {
    std::unique_ptr<moos::MoosApp> app;
    if (p.program == "uFldHazardSensor") app = std::make_unique<ufld_hazard_sensor::HazardSensor>();
    else if (p.program == "uFldHazardMetric") app = std::make_unique<ufld_hazard_metric::HazardMetricApp>();
    else if (p.program == "pHazardMgr") app = std::make_unique<phazard_mgr::HazardMgr>();
    else app = std::make_unique<usim_survey_vehicle::SimSurveyVehicle>();
    auto settings = process_settings(plan, p, app->traits(), setting, seed);
    clients.push_back(bus.connect(settings.moos_name));
    app->start(*clients.back(), settings);
    apps.push_back(std::move(app));
  }
  const long ticks = static_cast<long>((deploy_s + end_s) * 4);
  for (long k = 0; k <= ticks; ++k) {
    clock.set_unix_s(t0 + k * 0.25);
    for (auto& app : apps) app->cycle_if_due();
    if (k == static_cast<long>(deploy_s * 4)) {
      runner->notify("DEPLOY_ALL", std::string("true"));
      runner->notify("HAZARD_SEARCH_START", std::string("true"));
    }
    for (const moos::Message& m : runner->fetch())
      log += moos::format_alog_line(moos::alog_entry(m, t0));
  }
  return log;
}

TEST(StudyAgreesWithLiveApps, LockstepAndAFixedTickDriverPostTheSameEventsAtTheSameTimes) {
  const Options options = jake_options();
  const MissionPlan plan = jake_plan(options);
  RunOptions run_options;
  run_options.max_time_s = 1500;  // archie's first lanes: detections and classifications
  std::string lockstep_log;
  const MissionResult r = run_mission(plan, options.settings[0], 5, run_options, &lockstep_log);
  EXPECT_EQ(r.end, "max_time");
  ASSERT_GT(r.detections, 0);
  const std::string fixed = fixed_tick_log(plan, options.settings[0], 5, 1.0, 1500);
  EXPECT_EQ(lockstep_log, fixed);
  EXPECT_NE(fixed.find("UHZ_DETECTION_REPORT"), std::string::npos);
}

TEST(StudySet, AnUnknownBlockIsAnErrorNamingItAndTheBlocksThatRun) {
  const StudyRun r = study({kJake, "--set=pHazardMgr_charlie.swath_width=10"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("--set 'pHazardMgr_charlie.swath_width=10': no process "
                       "'pHazardMgr_charlie' runs in the mission"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("pHazardMgr_archie"), std::string::npos);
}

TEST(StudySet, AnUnknownParameterIsAnErrorNamingItForEveryKindOfApp) {
  for (const char* block : {"uFldHazardSensor", "uFldHazardMetric", "pHazardMgr_archie",
                            "uSimSurveyVehicle_betty"}) {
    SCOPED_TRACE(block);
    const std::string set = std::string(block) + ".swath_widht=10";
    const StudyRun r = study({kJake, "--max-time=10", "--set=" + set});
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find("--set '" + set + "': " + block + ": unknown parameter 'swath_widht'"),
              std::string::npos)
        << r.err;
  }
}

TEST(StudySet, ABadValueAndAnUnvariedFrameworkParameterAreErrors) {
  StudyRun r = study({kJake, "--max-time=10", "--set=pHazardMgr_archie.sensor_pd=2"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--set 'pHazardMgr_archie.sensor_pd=2': pHazardMgr_archie:"),
            std::string::npos)
      << r.err;
  r = study({kJake, "--max-time=10", "--set=uFldHazardSensor.CommsTick=8"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("CommsTick is a framework parameter"), std::string::npos) << r.err;
}

TEST(StudySet, ASettingChangesWhatTheAppsDo) {
  const StudyRun r = study({kJake, "--seed=3", "--max-time=1500", "--setting=wide",
                       "--set=uFldHazardSensor.sensor_config=width=60, exp=4, pclass=0.85",
                       "--set=uFldHazardSensor.sensor_config=width=10, exp=6, pclass=0.93"});
  EXPECT_EQ(r.status, 0) << r.err;
  const StudyRun base = study({kJake, "--seed=3", "--max-time=1500"});
  EXPECT_NE(r.out.substr(r.out.find("\"end\"")), base.out.substr(base.out.find("\"end\"")));
}

TEST(StudyMaxTime, AMissionThatDoesNotEndStopsAtMaxTimeWithALineThatSaysSo) {
  const StudyRun r = study({kJake, "--seed=2", "--max-time=60"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out,
            "{\"setting\":\"mission\",\"seed\":2,\"end\":\"max_time\",\"score\":null,\"found\":null,"
            "\"missed\":null,\"false_alarms\":null,\"time_used\":null,\"detections\":0,"
            "\"classifications\":0,\"sim_s\":60}\n");
}

TEST(StudySummary, MeanSdAndIntervalPerSetting) {
  std::vector<SettingScores> s = {{"a", {80, 90, 100}, 4, 1}, {"b\tc", {}, 2, 2}};
  EXPECT_EQ(summary_table(s),
            "setting\tmissions\tscored\tmean\tsd\tci95_low\tci95_high\tmax_time\n"
            "a\t4\t3\t90.00\t10.00\t65.16\t114.84\t1\n"
            "b c\t2\t0\t-\t-\t-\t-\t2\n");
  EXPECT_NEAR(t_quantile_975(30), 2.042, 2e-3);
  EXPECT_NEAR(t_quantile_975(1000), 1.962, 1e-3);
}

TEST(StudyOutput, LabelsAreEscapedAsJson) {
  MissionResult r;
  r.setting = "a\"b\\c\x01";
  r.end = "graded";
  EXPECT_EQ(json_line(r).substr(0, 26), "{\"setting\":\"a\\\"b\\\\c\\u0001\"");
}

TEST(StudyMission, AProgramTheRunnerCannotRunIsAnErrorNamingItsLine) {
  test_support::ScratchDir dir("study");
  test_support::write_file(dir / "m.moos",
                           "Community = x\nProcessConfig = ANTLER\n{\n  Run = pShare @ NewConsole = false\n}\n");
  const StudyRun r = study({(dir / "m.moos").string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("m.moos:4: hazard_study cannot run 'pShare'"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hazard_study
