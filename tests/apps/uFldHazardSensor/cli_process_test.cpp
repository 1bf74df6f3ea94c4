// The uFldHazardSensor binary's command line (manual 10.1, 11, listing 11.4;
// docs/uFldHazardSensor.md; D29):
// golden --help/--example/--interface/--version texts (golden/, checked by hand against the
// manual's listings), exit codes, the launch line, --verbose on a live server.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <set>

#include "HazardSensor.hpp"
#include "HazardSensor_Info.hpp"
#include "sensor_process.hpp"

namespace ufld_hazard_sensor {
namespace {

using test_support::Alog;
using test_support::alog_entries;
using test_support::read_file;
using test_support::RunResult;
using testing::kPatience_s;
using testing::SensorProcess;

RunResult run(const std::vector<std::string>& args) {
  return test_support::run_program(UFLD_HAZARD_SENSOR_PATH, args, kPatience_s);
}

std::string golden(const std::string& name) {
  return read_file(std::string(UFLD_GOLDEN_DIR) + "/" + name);
}

void expect_golden(const std::vector<std::string>& args, const std::string& file) {
  const RunResult r = run(args);
  EXPECT_EQ(r.exit_code, 0) << args.front();
  EXPECT_EQ(r.err, "") << args.front();
  const std::string expected = golden(file);
  ASSERT_FALSE(expected.empty()) << "golden file " << file << " is missing";
  EXPECT_EQ(r.out, expected) << args.front();
}

TEST(UfldHazardSensorCli, HelpMatchesItsGoldenInEveryForm_11_4) {
  for (const char* a : {"--help", "-h", "-help"}) expect_golden({a}, "help.txt");
}

TEST(UfldHazardSensorCli, ExampleMatchesItsGoldenInEveryForm_10_1) {
  for (const char* a : {"--example", "-e", "-example"}) expect_golden({a}, "example.txt");
}

TEST(UfldHazardSensorCli, InterfaceMatchesItsGolden_11) {
  for (const char* a : {"--interface", "-i"}) expect_golden({a}, "interface.txt");
}

TEST(UfldHazardSensorCli, VersionMatchesItsGolden_Spec2) {
  for (const char* a : {"--version", "-v", "-version"}) expect_golden({a}, "version.txt");
}

TEST(UfldHazardSensorCli, GoldensAreTheInfoTexts) {
  EXPECT_EQ(golden("help.txt"), help_text());
  EXPECT_EQ(golden("example.txt"), example_text());
  EXPECT_EQ(golden("interface.txt"), interface_text());
  EXPECT_EQ(golden("version.txt"), version_text());
}

TEST(UfldHazardSensorCli, NoMissionFileShowsTheHelpAndExitsZero_Spec2) {
  const RunResult r = run({});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, golden("help.txt"));
}

TEST(UfldHazardSensorCli, AnUnreadableMissionFileExitsOneNamingIt) {
  const RunResult r = run({"/nonexistent/folder/m.moos"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("/nonexistent/folder/m.moos"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cannot read"), std::string::npos) << r.err;
}

TEST(UfldHazardSensorCli, ABadVerboseValueExitsTwoNamingIt_D29) {
  const RunResult r = run({"m.moos", "--verbose=loud"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "uFldHazardSensor: '--verbose=loud': the verbosity must be true or false (see --help)\n");
  EXPECT_EQ(r.out, "");
}

// ---- on a live server -------------------------------------------------------------------------------

const char* kSmallBlock =
    "  random_seed = 5\n"
    "  sensor_config = width=20, exp=2, pclass=1.0\n"
    "  hazard = x=5,y=1,label=h1,type=hazard\n"
    "  bogus_param = 1\n";  // line 11 of the mission (process_mission): one config warning
const std::string kSmallAck = "vname=alpha,width=20,pd=1,pfa=1,pclass=1";

TEST_F(SensorProcess, VerboseWritesAlogLinesToStandardErrorAndNothingElseChanges_D29) {
  ASSERT_NO_FATAL_FAILURE(start(kSmallBlock, {"--verbose"}));
  post("UHZ_CONFIG_REQUEST", "vname=alpha,width=20,pd=1");
  ASSERT_TRUE(wait_for_value("UHZ_CONFIG_ACK_ALPHA", kSmallAck));
  sleep_ticks(2);
  const Alog log = stop_and_read_log();
  EXPECT_EQ(app_exit, 0);
  EXPECT_EQ(app->stdout_text(), "uFldHazardSensor launching as uFldHazardSensor\n\n");
  const std::string err = app->stderr_text();
  EXPECT_EQ(err.rfind("%% LOG FILE:", 0), 0u) << err;
  const auto lines = alog_entries(err);
  auto has = [&](const std::string& var, const std::string& value_part) {
    return std::any_of(lines.begin(), lines.end(), [&](const moos::AlogEntry& e) {
      return e.variable == var && e.source == "uFldHazardSensor" && e.value.find(value_part) != std::string::npos;
    });
  };
  EXPECT_TRUE(has("UHZ_CONFIG_ACK_ALPHA", kSmallAck)) << err;
  EXPECT_TRUE(has("UHZ_OPTIONS_SUMMARY", "width=20,exp=2,pclass=1.0")) << err;
  EXPECT_TRUE(has("VIEW_MARKER", "label=h1")) << err;
  EXPECT_TRUE(has("EVENT", "Setting sensor settings for: alpha")) << err;
  EXPECT_TRUE(has("CONFIG_WARNING", "m.moos:11: unknown parameter 'bogus_param'")) << err;
  // Every posting the server logged from the app is on standard error too, in order (the
  // verbose stream may hold a few more: postings still unsent when SIGTERM came).
  const std::set<std::string> pseudo = {kVerboseEvent, kVerboseRunWarning, kVerboseRetracted,
                                        kVerboseConfigWarning};
  std::vector<std::pair<std::string, std::string>> logged, written;
  for (const auto& e : log.entries) {
    if (e.source == "uFldHazardSensor" && e.variable != "APPCAST" && e.variable.rfind("UFLDHAZARDSENSOR_", 0) != 0)
      logged.emplace_back(e.variable, e.value);
  }
  for (const auto& e : lines) {
    if (!pseudo.count(e.variable)) written.emplace_back(e.variable, e.value);
  }
  ASSERT_GE(written.size(), logged.size());
  ASSERT_GT(logged.size(), 3u);
  EXPECT_TRUE(std::equal(logged.begin(), logged.end(), written.begin()));
}

TEST_F(SensorProcess, ArgvTwoIsTheRunAliasThatNamesTheProcess_Spec2) {
  ASSERT_NO_FATAL_FAILURE(start(kSmallBlock, {"uHZ_2"}));
  sleep_ticks(4);
  const Alog log = stop_and_read_log();
  EXPECT_EQ(app_exit, 0);
  EXPECT_EQ(app->stdout_text(), "uFldHazardSensor launching as uHZ_2\n\n");
  EXPECT_TRUE(std::any_of(log.entries.begin(), log.entries.end(), [](const moos::AlogEntry& e) {
    return e.variable == "UHZ_2_STATUS" && e.source == "uHZ_2";
  }));
}

TEST_F(SensorProcess, TerminalReportWhenAskedAndSigtermExitsZero_12) {
  ASSERT_NO_FATAL_FAILURE(start(kSmallBlock, {}, "TERM_REPORTING = true\n"));
  post("UHZ_CONFIG_REQUEST", "vname=alpha,width=20,pd=1");
  ASSERT_TRUE(wait_for_value("UHZ_CONFIG_ACK_ALPHA", kSmallAck));
  sleep_ticks(48);  // 0.6 s: more than term_report_interval (0.4 real s) after the first frame
  stop_all();
  EXPECT_EQ(app_exit, 0);
  const std::string out = app->stdout_text();
  // The terminal frame: title, warnings, the body with the seed, the events.
  EXPECT_NE(out.find("uFldHazardSensor shoreside"), std::string::npos) << out;
  EXPECT_NE(out.find("Configuration Warnings: 1"), std::string::npos) << out;
  EXPECT_NE(out.find("unknown parameter 'bogus_param'"), std::string::npos) << out;
  EXPECT_NE(out.find("       Seed: 5 (random_seed)"), std::string::npos) << out;
  EXPECT_NE(out.find("Setting sensor settings for: alpha"), std::string::npos) << out;
  EXPECT_EQ(app->stderr_text(), "");  // not verbose
}

}  // namespace
}  // namespace ufld_hazard_sensor

namespace ufld_hazard_sensor {
namespace {

// IdleAppTick (opt-in): a quiet sensor sleeps for long stretches, and still answers mail at once
// and stops at once on SIGTERM (a stop signal wakes the sleep; it once polled every 0.1 s).
TEST_F(SensorProcess, AnIdleSensorAnswersMailAndStopsAtOnce_IdleAppTick) {
  // Quiet for 1,000 MOOS s at a time (50 real s at warp 20); no options summary for an hour.
  ASSERT_NO_FATAL_FAILURE(start(std::string(kSmallBlock) + "  IdleAppTick = 0.001\n" +
                                "  options_summary_interval = 3600\n"));
  const auto before_request = std::chrono::steady_clock::now();
  post("UHZ_CONFIG_REQUEST", "vname=alpha,width=20,pd=1");
  ASSERT_TRUE(wait_for_value("UHZ_CONFIG_ACK_ALPHA", kSmallAck));
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - before_request).count(),
            kPatience_s);
  sleep_ticks(8);  // asleep again
  const auto before_stop = std::chrono::steady_clock::now();
  stop_all();
  const double stop_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - before_stop).count();
  EXPECT_EQ(app_exit, 0);
  EXPECT_LT(stop_s, 5.0);  // the sleep would have lasted about 50 s
}

}  // namespace
}  // namespace ufld_hazard_sensor
