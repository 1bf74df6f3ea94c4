// The application base on the in-process bus with a manual clock (docs/protocol.md 6.2-6.4,
// 7.1, 7.2).
#include <gtest/gtest.h>

#include <algorithm>

#include <sstream>

#include "moos/app.hpp"
#include "moos/bus.hpp"

namespace moos {
namespace {

constexpr double kT0 = 1700000000.0;

class EchoApp : public MoosApp {
 public:
  explicit EchoApp(AppTraits traits = AppTraits{"pEcho", 4.0}) : MoosApp(std::move(traits)) {}

  bool startup_result = true;
  std::vector<std::string> config_keys;
  std::vector<std::vector<Message>> mail_batches;
  int iterations = 0;
  int connects = 0;
  std::vector<std::string> warnings_to_raise;  // raised as run warnings at the next iterate

  using MoosApp::report_config_warning;
  using MoosApp::report_event;
  using MoosApp::report_run_warning;
  using MoosApp::retract_run_warning;

 protected:
  bool on_start_up() override {
    for (const auto& line : config_lines()) config_keys.push_back(line.key);
    register_variable("IN");
    return startup_result;
  }
  void on_connect_to_server() override { ++connects; }
  void on_new_mail(const std::vector<Message>& mail) override { mail_batches.push_back(mail); }
  void iterate() override {
    ++iterations;
    for (const auto& w : warnings_to_raise) report_run_warning(w);
    warnings_to_raise.clear();
  }
  std::string build_report() override { return "iterations: " + std::to_string(iterations); }
};

AppSettings settings_for(const std::string& name = "pEcho", double app_tick_hz = 4.0) {
  AppSettings s;
  s.app_name = name;
  s.moos_name = name;
  s.community = "alpha";
  s.app_tick_hz = app_tick_hz;
  return s;
}

class AppOnBus : public ::testing::Test {
 protected:
  explicit AppOnBus(double warp = 1.0) : bus(clock, InProcessBus::Options{"alpha", warp}) {}
  void start(AppSettings s = settings_for()) {
    s.time_warp = bus.time_warp();
    app_comms = bus.connect(s.moos_name);
    ASSERT_TRUE(app.start(*app_comms, s));
  }
  std::size_t count(const std::string& var) const { return bus.postings_of(var).size(); }

  ManualClock clock{kT0};
  InProcessBus bus;
  std::unique_ptr<BusClient> tester = bus.connect("tester");
  std::unique_ptr<BusClient> app_comms;
  EchoApp app;
};

// ---- settings (protocol.md 6.2-6.4) -------------------------------------------------------------

MissionFile mission(const std::string& text, std::vector<MissionError>* errors) {
  return MissionFile::parse(text, "m.moos", {}, errors);
}

TEST(RunApp, TwDelayFactorSwitchDefaultsToLibMoosAndRefusesBadValues_4_3) {
  std::string error;
  EXPECT_DOUBLE_EQ(*tw_delay_factor_ms(parse_command_line({"pEcho", "m.moos"}), &error), 0.2);
  EXPECT_DOUBLE_EQ(
      *tw_delay_factor_ms(parse_command_line({"pEcho", "m.moos", "--moos_tw_delay_factor=0"}), &error),
      0.0);
  EXPECT_DOUBLE_EQ(*tw_delay_factor_ms(
                       parse_command_line({"pEcho", "m.moos", "--moos_tw_delay_factor=1.5"}), &error),
                   1.5);
  EXPECT_FALSE(
      tw_delay_factor_ms(parse_command_line({"pEcho", "m.moos", "--moos_tw_delay_factor=-1"}), &error));
  EXPECT_NE(error.find("--moos_tw_delay_factor=-1"), std::string::npos);
  EXPECT_FALSE(tw_delay_factor_ms(
      parse_command_line({"pEcho", "m.moos", "--moos_tw_delay_factor=fast"}), &error));
}

TEST(AppSettingsResolve, PrecedenceOfWarpTickHostAndPort_6_4) {
  std::vector<MissionError> errors;
  const auto m = mission("Community = alpha\nServerHost = 10.0.0.9\nServerPort = 9100\n"
                         "MOOSTimeWarp = 2\nProcessConfig = pEcho\n{\n AppTick = 8\n"
                         " moos_time_warp = 3\n CommsTick = 10\n MyParam = a b\n}\n",
                         &errors);
  AppTraits traits{"pEcho", 4.0};
  const auto plain = resolve_app_settings(traits, parse_command_line({"pEcho", "m.moos"}), &m);
  EXPECT_TRUE(plain.config_warnings.empty()) << plain.config_warnings.front();
  EXPECT_EQ(plain.community, "alpha");
  EXPECT_EQ(plain.server_host, "10.0.0.9");
  EXPECT_EQ(plain.server_port, 9100);
  EXPECT_EQ(plain.time_warp, 3.0);  // the block beats the global (6.3)
  EXPECT_EQ(plain.app_tick_hz, 8.0);
  EXPECT_EQ(plain.comms_tick_hz, 10);
  ASSERT_EQ(plain.config_lines.size(), 1u);  // framework keys are not the app's
  EXPECT_EQ(plain.config_lines[0].value, "a b");

  const auto cli = resolve_app_settings(
      traits,
      parse_command_line({"pEcho", "m.moos", "--moos_time_warp=5", "--moos_app_tick=20",
                          "--moos_port=9200", "--moos_host=127.0.0.1"}),
      &m);
  EXPECT_EQ(cli.time_warp, 5.0);    // command line beats the mission
  EXPECT_EQ(cli.app_tick_hz, 8.0);  // ... except a block AppTick (6.4)
  EXPECT_EQ(cli.server_port, 9200);
  EXPECT_EQ(cli.server_host, "127.0.0.1");
}

TEST(AppSettingsResolve, AliasSelectsTheBlockAndNames_6_4) {
  std::vector<MissionError> errors;
  const auto m = mission("Community = a\nProcessConfig = pEcho_2\n{\n AppTick = 2\n}\n", &errors);
  const auto s = resolve_app_settings(AppTraits{"pEcho"},
                                      parse_command_line({"pEcho", "m.moos", "pEcho_2"}), &m);
  EXPECT_EQ(s.app_name, "pEcho_2");
  EXPECT_EQ(s.moos_name, "pEcho_2");
  EXPECT_TRUE(s.have_block);
  EXPECT_EQ(s.app_tick_hz, 2.0);
}

TEST(AppSettingsResolve, MissingCommunityAndBlockAreConfigWarnings_7_2) {
  std::vector<MissionError> errors;
  const auto m = mission("ServerPort = 9000\n", &errors);
  const auto s = resolve_app_settings(AppTraits{"pEcho"}, parse_command_line({"pEcho", "m.moos"}), &m);
  EXPECT_FALSE(s.have_block);
  EXPECT_EQ(s.config_warnings,
            (std::vector<std::string>{"Community/Vehicle name not found in mission file",
                                      "No mission config block found for pEcho"}));
}

TEST(AppSettingsResolve, BadFrameworkValuesAreWarningsNamingThePlace) {
  std::vector<MissionError> errors;
  const auto m = mission("Community = a\nMOOSTimeWarp = 0\nTERM_REPORTING = maybe\n"
                         "ProcessConfig = pEcho\n{\n AppTick = fast\n TERM_REPORT_INTERVAL = 20\n"
                         " MAX_APPCAST_EVENTS = 70\n IterateMode = 1\n}\n",
                         &errors);
  const auto s = resolve_app_settings(AppTraits{"pEcho", 4.0}, parse_command_line({"pEcho", "m.moos"}), &m);
  ASSERT_EQ(s.config_warnings.size(), 6u);
  EXPECT_EQ(s.config_warnings[0], "Invalid MOOSTimeWarp: 0 (m.moos:2)");
  EXPECT_EQ(s.config_warnings[1], "Invalid value for TERM_REPORTING: maybe (m.moos:3)");
  EXPECT_EQ(s.config_warnings[2], "Invalid AppTick: fast (must be a number in [0.001, 1000] Hz) (m.moos:6)");
  EXPECT_EQ(s.config_warnings[3], "TERM_REPORT_INTERVAL 20 clipped to 10 (m.moos:7)");
  EXPECT_EQ(s.config_warnings[4], "MAX_APPCAST_EVENTS 70 clipped to 50 (m.moos:8)");
  EXPECT_NE(s.config_warnings[5].find("IterateMode 1 is not supported"), std::string::npos);
  EXPECT_EQ(s.time_warp, 1.0);
  EXPECT_EQ(s.app_tick_hz, 4.0);
  EXPECT_EQ(s.term_report_interval_s, 10.0);
  EXPECT_EQ(s.max_appcast_events, 50u);
}

TEST(AppSettingsResolve, AppTicksThatStallOrBusyLoopAreRefused_Hardening) {
  for (const char* tick : {"1e-300", "0", "-4", "1e300", "1000.5"}) {
    std::vector<MissionError> errors;
    const auto m = mission(std::string("ProcessConfig = pEcho\n{\n AppTick = ") + tick + "\n}\n", &errors);
    const auto s = resolve_app_settings(AppTraits{"pEcho", 4.0}, parse_command_line({"pEcho", "m.moos"}), &m);
    const std::string expected = std::string("Invalid AppTick: ") + tick +
                                 " (must be a number in [0.001, 1000] Hz) (m.moos:3)";
    EXPECT_EQ(std::count(s.config_warnings.begin(), s.config_warnings.end(), expected), 1) << tick;
    EXPECT_EQ(s.app_tick_hz, 4.0) << tick;
  }
  std::vector<MissionError> errors;
  const auto m = mission("ProcessConfig = pEcho\n{\n AppTick = 1000\n}\n", &errors);
  EXPECT_EQ(resolve_app_settings(AppTraits{"pEcho", 4.0}, parse_command_line({"pEcho", "m.moos"}), &m)
                .app_tick_hz, 1000.0);
}

TEST(AppSettingsResolve, MissionTextInWarningsIsEscaped_Hardening) {
  std::vector<MissionError> errors;
  const auto m = mission("ProcessConfig = pEcho\n{\n AppTick = 4\x1b[2J\n IterateMode = 1\x7f\n}\n", &errors);
  const auto s = resolve_app_settings(AppTraits{"pEcho", 4.0}, parse_command_line({"pEcho", "m.moos"}), &m);
  const std::vector<std::string> expected = {
      "Invalid AppTick: 4\\x1B[2J (must be a number in [0.001, 1000] Hz) (m.moos:3)",
      "Invalid IterateMode: 1\\x7F (must be 0, 1 or 2) (m.moos:4)"};
  for (const auto& w : expected)
    EXPECT_EQ(std::count(s.config_warnings.begin(), s.config_warnings.end(), w), 1) << w;
  for (const auto& w : s.config_warnings) EXPECT_EQ(w.find('\x1b'), std::string::npos) << w;
}

TEST(AppSettingsResolve, RepeatedFrameworkParameterFirstWinsOrLastWithWarning_D36) {
  std::vector<MissionError> errors;
  const auto m = mission("Community = a\nProcessConfig = pEcho\n{\n AppTick = 2\n apptick = 8\n}\n", &errors);
  const auto cl = parse_command_line({"pEcho", "m.moos"});
  const auto first = resolve_app_settings(AppTraits{"pEcho"}, cl, &m);
  EXPECT_EQ(first.app_tick_hz, 2.0);  // libMOOS
  EXPECT_TRUE(first.config_warnings.empty());
  AppTraits d36{"pEcho"};
  d36.repeated_parameters = RepeatedParameter::kLastWinsWithWarning;
  const auto last = resolve_app_settings(d36, cl, &m);
  EXPECT_EQ(last.app_tick_hz, 8.0);
  ASSERT_EQ(last.config_warnings.size(), 1u);
  EXPECT_EQ(last.config_warnings[0], "apptick repeated (m.moos:5): the last value, 8, is used");
}

TEST(AppSettingsResolve, OnlyThisAppsMissionErrorsBecomeWarnings) {
  std::vector<MissionError> errors;
  const auto m = mission("Community = a\nstray line\nProcessConfig = pEcho\n{\n oops\n}\n"
                         "ProcessConfig = pOther\n{\n other oops\n}\n",
                         &errors);
  ASSERT_EQ(errors.size(), 3u);
  const auto s = resolve_app_settings(AppTraits{"pEcho"}, parse_command_line({"pEcho", "m.moos"}),
                                      &m, errors);
  ASSERT_EQ(s.config_warnings.size(), 2u);
  EXPECT_EQ(s.config_warnings[0], "m.moos:2: line has no '=' and is ignored: stray line");
  EXPECT_EQ(s.config_warnings[1], "m.moos:5: line has no '=' and is ignored: oops");
}

TEST(AppSettingsResolve, CarryTheMissionsFolderAndGlobalsForTheApp) {
  std::vector<MissionError> errors;
  const auto m = MissionFile::parse("LatOrigin = 43.825\nLongOrigin = -70.33\nRegion = a b\n"
                                    "ProcessConfig = pEcho\n{\n LatOrigin = 1\n}\n",
                                    "missions/jake/m.moos", {}, &errors);
  const auto s =
      resolve_app_settings(AppTraits{"pEcho"}, parse_command_line({"pEcho", "m.moos"}), &m);
  EXPECT_EQ(s.mission_directory, "missions/jake");
  ASSERT_NE(s.mission, nullptr);
  EXPECT_EQ(s.mission->path(), "missions/jake/m.moos");
  EXPECT_EQ(s.global_double("latorigin"), 43.825);  // the first line, as MissionFile::global
  EXPECT_EQ(s.global_double("LongOrigin"), -70.33);
  EXPECT_EQ(s.global("Region"), "ab");
  EXPECT_FALSE(s.global_double("Region").has_value());
  EXPECT_FALSE(s.global("Nothing").has_value());
  // A file in the current folder is read from ".".
  const auto here = MissionFile::parse("X = 1\n", "m.moos", {}, &errors);
  const auto s_here = resolve_app_settings(AppTraits{"pEcho"}, parse_command_line({"pEcho"}), &here);
  EXPECT_EQ(s_here.mission_directory, ".");
}

TEST(AppSettingsResolve, WithoutAMissionThereAreNoGlobals) {
  const auto s = resolve_app_settings(AppTraits{"pEcho"}, parse_command_line({"pEcho"}), nullptr);
  EXPECT_EQ(s.mission_directory, ".");
  EXPECT_EQ(s.mission, nullptr);
  EXPECT_FALSE(s.global("LatOrigin").has_value());
  EXPECT_FALSE(s.global_double("LatOrigin").has_value());
}

// ---- the main loop on the bus (protocol.md 7.1) -------------------------------------------------

TEST_F(AppOnBus, StartUpSeesConfigAndRegistersAppCastRequests_7_2) {
  AppSettings s = settings_for();
  s.config_lines.push_back(ConfigLine{"MyParam", "1", "m.moos", 3});
  start(s);
  EXPECT_EQ(app.config_keys, std::vector<std::string>{"MyParam"});
  EXPECT_EQ(app_comms->registered_names(), (std::set<std::string>{"APPCAST_REQ", "IN"}));
}

TEST_F(AppOnBus, FailedStartUpIsReported_7_1) {
  app.startup_result = false;
  app_comms = bus.connect("pEcho");
  EXPECT_FALSE(app.start(*app_comms, settings_for()));
}

struct WarpedAppOnBus : AppOnBus {
  WarpedAppOnBus() : AppOnBus(10.0) {}
};

TEST_F(WarpedAppOnBus, IterateRunsAtAppTickInMoosTime_7_1) {
  start(settings_for("pEcho", 4.0));
  const double real_before = clock.unix_now_s();
  app.run_for(10.0);  // 10 MOOS s at warp 10 = 1 real s
  EXPECT_EQ(app.iterations, 41);  // cycles at 0, 0.25, ..., 10.0 MOOS s
  EXPECT_NEAR(clock.unix_now_s() - real_before, 1.0, 1e-6);
  EXPECT_EQ(app.iteration(), 41u);
}

TEST_F(AppOnBus, CycleIfDueFollowsTheSchedule_7_1) {
  start(settings_for("pEcho", 2.0));
  EXPECT_TRUE(app.cycle_if_due());   // due at start
  EXPECT_FALSE(app.cycle_if_due());  // next at +0.5 s
  clock.advance_real_s(0.4);
  EXPECT_FALSE(app.cycle_if_due());
  clock.advance_real_s(0.1);
  EXPECT_TRUE(app.cycle_if_due());
  EXPECT_EQ(app.iterations, 2);
}

TEST_F(AppOnBus, ALateCycleKeepsTheGridAndRunsTheSlotItOverranAtOnce) {
  start(settings_for("pEcho", 4.0));  // slots at 0, 0.25, 0.5, ...
  EXPECT_TRUE(app.cycle_if_due());
  clock.advance_real_s(0.55);  // the slot at 0.25 wakes 0.3 s (1.2 periods) late
  EXPECT_TRUE(app.cycle_if_due());
  EXPECT_TRUE(app.cycle_if_due());   // the slot at 0.5, already past, runs at once
  EXPECT_FALSE(app.cycle_if_due());  // then the grid again: next at 0.75
  clock.advance_real_s(0.19);
  EXPECT_FALSE(app.cycle_if_due());
  clock.advance_real_s(0.01);
  EXPECT_TRUE(app.cycle_if_due());
  EXPECT_EQ(app.iterations, 4);
}

TEST_F(AppOnBus, ACycleTwoPeriodsLateSkipsTheMissedSlots) {
  start(settings_for("pEcho", 4.0));
  EXPECT_TRUE(app.cycle_if_due());
  clock.advance_real_s(0.8);  // the slot at 0.25 wakes 0.55 s (2.2 periods) late
  EXPECT_TRUE(app.cycle_if_due());
  EXPECT_FALSE(app.cycle_if_due());  // the slots at 0.5 and 0.75 are gone; next at 1.05
  clock.advance_real_s(0.24);
  EXPECT_FALSE(app.cycle_if_due());
  clock.advance_real_s(0.01);
  EXPECT_TRUE(app.cycle_if_due());
  EXPECT_EQ(app.iterations, 3);
}

TEST_F(AppOnBus, MailIsSortedByTimeAndFrameworkMailRemoved_7_1) {
  start();
  tester->notify("IN", 3.0, kT0 + 3);
  tester->notify("IN", 1.0, kT0 + 1);
  tester->notify("APPCAST_REQ", std::string("node=alpha,app=pEcho,duration=1,key=k,thresh=any"));
  tester->notify("IN", 2.0, kT0 + 2);
  tester->notify("_async_timing", 0.0);
  app.cycle();
  ASSERT_EQ(app.mail_batches.size(), 1u);
  const auto& mail = app.mail_batches[0];
  ASSERT_EQ(mail.size(), 3u);
  EXPECT_EQ(mail[0].dval, 1.0);
  EXPECT_EQ(mail[1].dval, 2.0);
  EXPECT_EQ(mail[2].dval, 3.0);
}

TEST_F(AppOnBus, SortMailByTimeFalseKeepsArrivalOrder_6_3) {
  AppSettings s = settings_for();
  s.sort_mail_by_time = false;
  start(s);
  tester->notify("IN", 3.0, kT0 + 3);
  tester->notify("IN", 1.0, kT0 + 1);
  app.cycle();
  ASSERT_EQ(app.mail_batches.at(0).size(), 2u);
  EXPECT_EQ(app.mail_batches[0][0].dval, 3.0);
}

TEST_F(AppOnBus, FrameworkMailAnywhereInTheBatchIsRemovedAndTheRestKeepsItsOrder_7_1) {
  AppSettings s = settings_for();
  s.sort_mail_by_time = false;
  start(s);
  tester->notify("_async_timing", 0.0);
  tester->notify("IN", 1.0);
  tester->notify("APPCAST_REQ", std::string("node=alpha,app=pEcho,duration=1,key=k,thresh=any"));
  tester->notify("IN", 2.0);
  tester->notify("_async_timing", 0.0);
  app.cycle();
  tester->notify("APPCAST_REQ", std::string("node=alpha,app=pEcho,duration=1,key=k,thresh=any"));
  app.cycle();  // framework mail alone: no on_new_mail
  ASSERT_EQ(app.mail_batches.size(), 1u);
  const auto& mail = app.mail_batches[0];
  ASSERT_EQ(mail.size(), 2u);
  EXPECT_EQ(mail[0].dval, 1.0);
  EXPECT_EQ(mail[1].dval, 2.0);
}

TEST_F(AppOnBus, ACycleWithNothingToReportStillCountsTheAppcastsIteration_7_2) {
  // A Community setting, no terminal, no request, no _ITER_LEN: nothing to report.
  AppTraits traits{"pQuiet", 4.0};
  traits.post_iteration_timing = false;
  EchoApp quiet(traits);
  AppSettings s = settings_for("pQuiet");
  s.time_warp = bus.time_warp();
  const auto comms = bus.connect("pQuiet");
  ASSERT_TRUE(quiet.start(*comms, s));
  quiet.run_for(2.0);
  EXPECT_EQ(count("APPCAST"), 1u);  // iteration 1 only
  EXPECT_GT(quiet.iteration(), 2u);
  EXPECT_EQ(quiet.appcast().iteration(), quiet.iteration());
  // A request is looked at again at once.
  tester->notify("APPCAST_REQ", std::string("node=alpha,app=pQuiet,duration=3,key=k,thresh=any"));
  quiet.run_for(1.0);
  EXPECT_GT(count("APPCAST"), 1u);
}

TEST_F(AppOnBus, StatusIsPostedAtOnceThenEveryTwoMoosSeconds_7_1) {
  start();
  app.run_for(5.0);
  const auto status = bus.postings_of("PECHO_STATUS");
  ASSERT_EQ(status.size(), 3u);  // t = 0, 2, 4
  EXPECT_EQ(status[0].sval,
            "AppErrorFlag=false,Uptime=0,MOOSName=pEcho,Publishing=\"\",Subscribing=\"APPCAST_REQ,IN,\"");
  EXPECT_DOUBLE_EQ(status[1].time - status[0].time, 2.0);
  EXPECT_NE(status[1].sval.find("Uptime=2,"), std::string::npos);
  EXPECT_NE(status[1].sval.find("Publishing=\"APPCAST,PECHO_ITER_GAP,PECHO_ITER_LEN,PECHO_STATUS,\""),
            std::string::npos)
      << status[1].sval;
}

TEST_F(AppOnBus, IterationGapAndLengthArePostedInPeriods_7_2) {
  start(settings_for("pEcho", 4.0));
  app.run_for(1.0);  // 5 iterations
  const auto gaps = bus.postings_of("PECHO_ITER_GAP");
  const auto lens = bus.postings_of("PECHO_ITER_LEN");
  EXPECT_EQ(gaps.size(), 4u);  // from the second iteration on
  EXPECT_EQ(lens.size(), 5u);
  for (const auto& g : gaps) EXPECT_NEAR(g.dval, 1.0, 1e-6);  // one period apart
  for (const auto& l : lens) EXPECT_EQ(l.dval, 0.0);         // the manual clock stood still
}

TEST_F(AppOnBus, AppCastAtFirstIterationThenOnlyWhileRequested_7_2) {
  start(settings_for("pEcho", 4.0));
  app.run_for(1.0);
  ASSERT_EQ(count("APPCAST"), 1u);  // iteration 1 only (< 2)
  EXPECT_EQ(bus.postings_of("APPCAST")[0].sval.substr(0, 33), "proc=pEcho!@#iter=1!@#node=alpha!");
  tester->notify("APPCAST_REQ", std::string("node=alpha,app=pEcho,duration=3.0,key=uMAC_1,thresh=any"));
  app.run_for(4.0);
  // Request taken at t=1.25; appcasts every 0.5 s (interval 0.4 s at 4 Hz) until it expires at 4.25.
  const auto casts = bus.postings_of("APPCAST");
  ASSERT_EQ(casts.size(), 7u);
  EXPECT_DOUBLE_EQ(casts[1].time - kT0, 1.25);
  EXPECT_DOUBLE_EQ(casts[6].time - kT0, 3.75);
  EXPECT_NE(casts[6].sval.find("messages=iterations: "), std::string::npos);
}

TEST_F(AppOnBus, RequestForAnotherNodeOrAppIsIgnored_7_2) {
  start();
  app.run_for(1.0);
  tester->notify("APPCAST_REQ", std::string("node=bravo,app=pEcho,duration=3,key=k,thresh=any"));
  tester->notify("APPCAST_REQ", std::string("node=alpha,app=pOther,duration=3,key=k,thresh=any"));
  tester->notify("APPCAST_REQ", std::string("node=alpha,app=pEcho,duration=3,thresh=any"));
  app.run_for(3.0);
  EXPECT_EQ(count("APPCAST"), 1u);
}

TEST_F(AppOnBus, RunWarningThresholdAppCastsOnlyOnNewWarnings_7_2) {
  start();
  app.run_for(1.0);
  tester->notify("APPCAST_REQ", std::string("node=all,app=all,duration=10,key=k,thresh=run_warning"));
  app.run_for(2.0);
  EXPECT_EQ(count("APPCAST"), 1u);
  app.warnings_to_raise = {"sensor lost"};
  app.run_for(2.0);
  ASSERT_EQ(count("APPCAST"), 2u);
  const std::string cast = bus.postings_of("APPCAST").back().sval;
  EXPECT_NE(cast.find("run_warning_total=1!@#run_warnings=1:sensor lost"), std::string::npos);
  app.retract_run_warning("sensor lost");  // a retraction is news too
  app.run_for(1.0);
  ASSERT_EQ(count("APPCAST"), 3u);
  EXPECT_NE(bus.postings_of("APPCAST").back().sval.find("run_warning_total=0!@#"), std::string::npos);
}

TEST_F(AppOnBus, NewConfigWarningTriggersAnAppCast_7_2) {
  start();
  app.run_for(2.0);
  EXPECT_EQ(count("APPCAST"), 1u);
  app.report_config_warning("late problem");
  app.run_for(1.0);
  ASSERT_EQ(count("APPCAST"), 2u);
  EXPECT_NE(bus.postings_of("APPCAST").back().sval.find("config_warnings=late problem!@#"),
            std::string::npos);
  app.run_for(2.0);
  EXPECT_EQ(count("APPCAST"), 2u);  // reported once
}

TEST_F(AppOnBus, TerminalReportsFollowTheInterval_7_2) {
  std::vector<std::string> frames;
  app.set_terminal_output([&](const std::string& f) { frames.push_back(f); });
  AppSettings s = settings_for("pEcho", 4.0);
  s.term_report_interval_s = 1.0;
  start(s);
  app.run_for(4.0);  // t = 0 .. 4 at 4 Hz: frames at 0, 1, 2, 3, 4
  ASSERT_EQ(frames.size(), 5u);
  EXPECT_EQ(frames[0].substr(0, 63), std::string(62, '=') + "\n");
  EXPECT_NE(frames[4].find("pEcho alpha"), std::string::npos);
  EXPECT_NE(frames[4].find("0/0(17)"), std::string::npos);
  EXPECT_EQ(count("APPCAST"), 1u);  // terminal reports do not post appcasts
}

TEST_F(AppOnBus, ATerminalSetAfterStartUpGetsFramesFromAQuietApp_7_2) {
  // A quiet app (Community set, no _ITER_LEN, no request) skips the report: a terminal attached
  // later must end the skipping.
  AppTraits traits{"pQuiet", 4.0};
  traits.post_iteration_timing = false;
  EchoApp quiet(traits);
  AppSettings s = settings_for("pQuiet");
  s.time_warp = bus.time_warp();
  s.term_report_interval_s = 1.0;
  const auto comms = bus.connect("pQuiet");
  ASSERT_TRUE(quiet.start(*comms, s));
  quiet.run_for(2.0);
  std::vector<std::string> frames;
  quiet.set_terminal_output([&](const std::string& f) { frames.push_back(f); });
  quiet.run_for(2.0);
  EXPECT_GE(frames.size(), 2u);
}

TEST_F(AppOnBus, CycleIfDueAtAGivenTimeRunsOnlyAtTheDueTimeAndUsesIt_7_1) {
  start();
  ASSERT_TRUE(app.cycle_if_due(bus.moos_time()));  // due at once after start-up
  const double due = app.next_cycle_due_moos_s();
  EXPECT_DOUBLE_EQ(due, kT0 + 0.25);
  clock.set_unix_s(kT0 + 0.1);
  EXPECT_FALSE(app.cycle_if_due(bus.moos_time()));
  EXPECT_EQ(app.iterations, 1);
  clock.set_unix_s(due);
  ASSERT_TRUE(app.cycle_if_due(bus.moos_time()));
  EXPECT_EQ(app.iterations, 2);
  EXPECT_EQ(app.cycle_time(), due);
  EXPECT_DOUBLE_EQ(app.next_cycle_due_moos_s(), kT0 + 0.5);
}

TEST_F(AppOnBus, TermReportingFalseSilencesTheTerminal_7_2) {
  std::vector<std::string> frames;
  app.set_terminal_output([&](const std::string& f) { frames.push_back(f); });
  AppSettings s = settings_for();
  s.term_reporting = false;
  start(s);
  app.run_for(3.0);
  EXPECT_TRUE(frames.empty());
}

TEST_F(AppOnBus, EventsAreStampedWithSecondsSinceStart_7_2) {
  start();
  app.run_for(1.5);
  app.report_event("something happened");
  EXPECT_EQ(app.appcast().events().back(), "[1.50]: something happened");
  EXPECT_NE(app.terminal_report().find("[1.50]: something happened"), std::string::npos);
}

TEST_F(AppOnBus, OnConnectRunsOnTheCyclingThreadAfterEachConnection_1_9) {
  start();
  app.cycle();
  EXPECT_EQ(app.connects, 1);
  app_comms->simulate_disconnect();
  app.run_for(1.0);
  const int iterations_before = app.iterations;
  app.cycle();
  EXPECT_EQ(app.iterations, iterations_before);  // no Iterate while disconnected (7.1)
  app_comms->simulate_reconnect();
  tester->notify("IN", 5.0);  // the registration came back with the reconnect
  app.cycle();
  EXPECT_EQ(app.connects, 2);
  ASSERT_FALSE(app.mail_batches.empty());
  EXPECT_EQ(app.mail_batches.back().back().dval, 5.0);
}

TEST_F(AppOnBus, WarpDifferentFromTheConnectionIsAConfigWarning) {
  AppSettings s = settings_for();
  s.time_warp = 3.0;
  app_comms = bus.connect("pEcho");
  ASSERT_TRUE(app.start(*app_comms, s));
  EXPECT_EQ(app.settings().time_warp, 1.0);
  ASSERT_EQ(app.appcast().config_warnings().size(), 1u);
  EXPECT_NE(app.appcast().config_warnings()[0].find("differs"), std::string::npos);
}

TEST(AppRun, MissingOrUnreadableMissionExitsWithOne) {
  EchoApp app;
  std::ostringstream out;
  std::ostringstream err;
  EXPECT_EQ(run_app(app, parse_command_line({"pEcho"}), out, err, false), 1);
  EXPECT_NE(err.str().find("no mission file"), std::string::npos);
  err.str("");
  EXPECT_EQ(run_app(app, parse_command_line({"pEcho", "/nonexistent/m.moos"}), out, err, false), 1);
  EXPECT_NE(err.str().find("cannot read the mission file"), std::string::npos);
}

}  // namespace
}  // namespace moos
