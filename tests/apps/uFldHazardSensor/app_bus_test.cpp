// uFldHazardSensor's app class on the in-process bus with a manual clock (no sockets): start-up
// visuals, options summary timing, PMV_CONNECT, AppCast, config and run warnings, verbose
// output, seeds, hazard files, mail times, and that the app posts exactly what the engine
// decides.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "app_support.hpp"
#include "hazard/driver.hpp"
#include "hazard/config.hpp"
#include "hazard/engine.hpp"
#include "base/text.hpp"
#include "moos/alog.hpp"
#include "base/text.hpp"
#include "sensor_on_bus.hpp"

namespace ufld_hazard_sensor {
namespace {

using test_support::write_file;
using testing::contains;
using testing::is_framework_posting;
using testing::kFirstBlockLine;
using testing::SensorOnBus;

/// Seconds per iteration at the default AppTick of 4 Hz.
constexpr double kTick_s = 0.25;

const char* kField =
    "  hazard = x=5,y=31,label=h1,type=hazard\n"
    "  hazard = x=-12.3456,y=61,label=b1,type=benign,hr=0.3\n"
    "  hazard = x=40,y=0,label=a1,type=benign,aspect=0,aspect_min=20,aspect_max=70\n";

const char* kOptions =
    "  sensor_config = width=20, exp=2, pclass=1.0\n"
    "  sensor_config = width=10, exp=4, pclass=0.90\n";

/// The config warnings that contain `part`.
int warnings_with(const moos::AppCast& cast, const std::string& part) {
  const auto& w = cast.config_warnings();
  return static_cast<int>(std::count_if(w.begin(), w.end(), [&](const std::string& s) {
    return contains(s, part);
  }));
}

// ---- start-up visuals (manual 7.6, docs/messages.md) ------------------------------------------

TEST_F(SensorOnBus, StartupPostsOneMarkerPerObjectInLoadOrder_7_6) {
  start(std::string(kField) + kOptions);
  // Hand-built: x/y FMT(.,2) (-12.3456 -> -12.35), width FMT(8,2) = 8, hazards green and
  // benign light_blue (D17, D18), triangles; benign fill 1 - hr (0.7), or 0.5 without hr.
  EXPECT_EQ(values_of("VIEW_MARKER"),
            (std::vector<std::string>{
                "x=5,y=31,width=8,primary_color=green,type=triangle,label=h1",
                "x=-12.35,y=61,width=8,primary_color=light_blue,type=triangle,label=b1,"
                "fill_transparency=0.7",
                "x=40,y=0,width=8,primary_color=light_blue,type=triangle,label=a1,"
                "fill_transparency=0.5"}));
  // The aspect axis of a1 (aspect 0, so north-south): 5 + 25 * ((20 + 70) / 2) / 90 = 17.5 m
  // each way from (40, 0).
  EXPECT_EQ(values_of("VIEW_SEGLIST"),
            (std::vector<std::string>{"pts={40,17.5:40,-17.5},edge_color=gray70,vertex_size=0,edge_size=1"}));
  EXPECT_EQ(app->iteration(), 0u);  // posted at start-up, before the first iteration
}

TEST_F(SensorOnBus, ShowHazardsFalsePostsNoMarkersEvenOnPmvConnect_7_6) {
  start(std::string(kField) + kOptions + "  show_hazards = false\n");
  post("PMV_CONNECT", "pMarineViewer");
  run_for(1.0);
  EXPECT_TRUE(values_of("VIEW_MARKER").empty());
  EXPECT_TRUE(values_of("VIEW_SEGLIST").empty());
}

TEST_F(SensorOnBus, PmvConnectRepostsTheObjectVisuals_5_1) {
  start(std::string(kField) + kOptions);
  const auto first = values_of("VIEW_MARKER");
  ASSERT_EQ(first.size(), 3u);
  run_for(1.0);
  EXPECT_EQ(values_of("VIEW_MARKER").size(), 3u);  // not re-posted by iterations
  post("PMV_CONNECT", "pMarineViewer");
  run_for(kTick_s);
  auto all = values_of("VIEW_MARKER");
  ASSERT_EQ(all.size(), 6u);
  EXPECT_EQ(std::vector<std::string>(all.begin() + 3, all.end()), first);
  EXPECT_EQ(values_of("VIEW_SEGLIST").size(), 2u);
}

// ---- options summary (manual 4.5, D21) ----------------------------------------------------------

TEST_F(SensorOnBus, OptionsSummaryOnTheFirstIterationThenEveryInterval_4_5_D21) {
  start(std::string(kField) +
        "  sensor_config = width=25, exp=4, pclass=0.80\n"
        "  sensor_config = width=50, exp=2, pclass=0.60\n"
        "  sensor_config = width=10, exp=6, pclass=0.93\n"
        "  options_summary_interval = 5\n");
  EXPECT_TRUE(values_of("UHZ_OPTIONS_SUMMARY").empty());  // nothing before the first iteration
  run_for(12.0);  // iterations at t0, t0 + 0.25, ..., t0 + 12
  const auto posts = bus.postings_of("UHZ_OPTIONS_SUMMARY");
  ASSERT_EQ(posts.size(), 3u);
  // First iteration, then whenever 5 s have passed since the last posting.
  EXPECT_EQ(posts[0].time, kT0);
  EXPECT_EQ(posts[1].time, kT0 + 5.0);
  EXPECT_EQ(posts[2].time, kT0 + 10.0);
  // T3 (differences.md): file order, pclass= keys, the values as written.
  for (const auto& p : posts) {
    EXPECT_EQ(p.sval, "width=25,exp=4,pclass=0.80:width=50,exp=2,pclass=0.60:width=10,exp=6,pclass=0.93");
  }
}

TEST_F(SensorOnBus, OptionsSummaryIntervalZeroPostsEveryIteration_4_5) {
  start(std::string(kField) + kOptions + "  options_summary_interval = 0\n");
  run_for(2.0);  // 9 iterations: t0 .. t0 + 2
  EXPECT_EQ(app->iteration(), 9u);
  EXPECT_EQ(values_of("UHZ_OPTIONS_SUMMARY").size(), 9u);
  EXPECT_EQ(values_of("UHZ_OPTIONS_SUMMARY").front(), "width=20,exp=2,pclass=1.0:width=10,exp=4,pclass=0.90");
}

// ---- AppCast (docs/uFldHazardSensor.md, docs/protocol.md 7.2) --------------------------------

TEST_F(SensorOnBus, AppCastOnTheFirstIterationThenOnlyOnRequest_11) {
  start(std::string(kField) + kOptions + "  random_seed = 7\n");
  run_for(3.0);
  ASSERT_EQ(values_of("APPCAST").size(), 1u);  // the first iteration (iteration < 2)
  post("APPCAST_REQ", "node=shoreside,app=uFldHazardSensor,duration=2,key=tester,thresh=any");
  const double asked = clock.unix_now_s();
  run_for(5.0);
  const auto casts = bus.postings_of("APPCAST");
  // While the 2 s request lasts, one appcast per term_report_interval (0.4 s, so every second
  // iteration at 4 Hz): 4 or 5; none after it expired.
  ASSERT_GE(casts.size(), 1u + 4u);
  EXPECT_LE(casts.size(), 1u + 5u);
  EXPECT_LE(casts.back().time, asked + 2.0);
  const std::string& cast = casts.back().sval;
  EXPECT_TRUE(base::starts_with(cast, "proc=uFldHazardSensor!@#iter="));
  EXPECT_TRUE(contains(cast, "!@#node=shoreside!@#"));
  EXPECT_TRUE(contains(cast, "!@#messages=Hazard File: (None provided.) !@     Hazard: 1!@     Benign: 2!@"));
  EXPECT_TRUE(contains(cast, "!@       Seed: 7 (random_seed)!@"));
  EXPECT_TRUE(contains(cast, "Sensor Configuration Options!@"));
}

TEST_F(SensorOnBus, TerminalReportHasTheSeedAndEffectsInItsHeaderBlock_11) {
  start(std::string(kField) + kOptions + "  random_seed = 7\n");
  run_for(1.0);
  const std::string report = app->terminal_report();
  EXPECT_TRUE(base::starts_with(report, std::string(62, '=') + "\nuFldHazardSensor shoreside"));
  EXPECT_TRUE(contains(report, "0/0(5)\n"));  // no warnings, five iterations
  EXPECT_TRUE(contains(report, "\n       Seed: 7 (random_seed)\n"));
  EXPECT_TRUE(contains(report, "\n    Effects: speed_gate, turn_blackout, resemblance, aspect,"));
  EXPECT_TRUE(contains(report, "Width  Exp  Classify  Max\n-----  ---  --------  ---\n"
                               "10.0   4.0  0.900     0\n20.0   2.0  1.000     0\n"));
}

// ---- configuration warnings (D26, D36, D38) --------------------------------------------------------

TEST_F(SensorOnBus, ConfigWarningsNameFileAndLineAndTheAppKeepsRunning_D36_D38) {
  start("  swath_transparency = 2\n"                       // line 6: outside [0, 1]
        "  bogus_param = 1\n"                              // line 7: unknown
        "  sensor_config = width=0, exp=2, pclass=0.8\n"   // line 8: width must be > 0
        "  hazard_file = missing.txt\n"                    // line 9: cannot be read
        "  min_classify_interval = 5\n"                    // line 10
        "  min_classify_interval = 7\n"                    // line 11: repeated, last wins
        "  AppTick = 4\n"                                  // line 12
        "  AppTick = 8\n"                                  // line 13: repeated framework key
        "  hazard = x=1,y=2,label=a,type=hazard\n"
        "  sensor_config = width=10, exp=2, pclass=0.8\n");
  const std::string file = (dir / "m.moos").string() + ":";
  auto line = [&](int offset) { return file + std::to_string(kFirstBlockLine + offset); };
  EXPECT_EQ(warnings_with(appcast(), line(0) + ": parameter 'swath_transparency' value '2'"), 1);
  EXPECT_EQ(warnings_with(appcast(), line(1) + ": unknown parameter 'bogus_param'"), 1);
  EXPECT_EQ(warnings_with(appcast(), line(2) + ": parameter 'sensor_config'"), 1);
  EXPECT_EQ(warnings_with(appcast(), line(3) + ": cannot read hazard file 'missing.txt': cannot be opened: "),
            1);  // the reader's reason reaches the user
  EXPECT_EQ(warnings_with(appcast(), line(5) + ": parameter 'min_classify_interval' repeated"), 1);
  EXPECT_EQ(warnings_with(appcast(), "AppTick repeated (" + line(7) + ")"), 1);
  EXPECT_EQ(appcast().config_warnings().size(), 6u);
  // Rejected values keep the default; repeated ones take the last value (D36).
  EXPECT_EQ(engine().config().swath_transparency, 0.2);
  EXPECT_EQ(engine().config().min_classify_interval_s, 7.0);
  EXPECT_EQ(app->settings().app_tick_hz, 8.0);
  run_for(1.0);
  EXPECT_EQ(app->iteration(), 9u);  // 8 Hz
  EXPECT_EQ(values_of("APPCAST").size(), 1u);
  const std::string cast = values_of("APPCAST").front();
  EXPECT_TRUE(contains(cast, "!@#config_warnings=")) << cast;
  EXPECT_TRUE(contains(cast, line(0) + ": parameter 'swath_transparency'")) << cast;
  EXPECT_TRUE(contains(app->terminal_report(), "6/0(9)"));
}

TEST_F(SensorOnBus, WithoutAFieldOrOptionsTheAppStaysUpWithWarnings_D26) {
  start("  show_pd = true\n");
  EXPECT_EQ(warnings_with(appcast(), "no hazard field"), 1);
  EXPECT_EQ(warnings_with(appcast(), "no sensor_config"), 1);
  post("UHZ_SENSOR_REQUEST", "vname=alpha");
  post("NODE_REPORT", "NAME=alpha,X=0,Y=0,SPD=1,HDG=0");
  run_for(1.0);
  EXPECT_EQ(values_of("UHZ_OPTIONS_SUMMARY").size(), 1u);
  EXPECT_TRUE(values_of("UHZ_DETECTION_REPORT").empty());
  EXPECT_EQ(bus.postings_of("UFLDHAZARDSENSOR_STATUS").size(), 1u);
}

TEST_F(SensorOnBus, AliasSelectsTheBlockAndAMissingBlockIsAWarning_D26) {
  start(std::string(kField) + kOptions, {}, {"--alias=uHZ_2"});
  EXPECT_EQ(app->settings().app_name, "uHZ_2");
  EXPECT_EQ(warnings_with(appcast(), "No mission config block found for uHZ_2"), 1);
  EXPECT_EQ(engine().field().size(), 0u);  // the uFldHazardSensor block is not ours
  run_for(0.5);
  EXPECT_EQ(bus.postings_of("UHZ_2_STATUS").size(), 1u);
  EXPECT_EQ(values_of("UHZ_OPTIONS_SUMMARY"), std::vector<std::string>{""});
}

// ---- mail (docs/messages.md: bad mail is warned, the app keeps serving) -------------------------

TEST_F(SensorOnBus, BadMailGivesARunWarningNamingItAndTheAppKeepsServing) {
  start(std::string(kField) + kOptions);
  post("NODE_REPORT", "NAME=alpha,X=oops,Y=0,SPD=1,HDG=0");
  post("UHZ_CONFIG_REQUEST", "vname=alpha,width=10,pd=7");
  post("UHZ_CLASSIFY_REQUEST", "label=h1");
  ASSERT_TRUE(vehicle->notify("UHZ_SENSOR_REQUEST", 3.0));  // a double where text belongs
  run_for(kTick_s);
  const auto& warnings = appcast().run_warnings();
  auto count_with = [&](const std::string& part) {
    return std::count_if(warnings.begin(), warnings.end(),
                         [&](const auto& w) { return contains(w.first, part); });
  };
  EXPECT_EQ(count_with("NODE_REPORT: "), 1);
  EXPECT_EQ(count_with("'NAME=alpha,X=oops,Y=0,SPD=1,HDG=0'"), 1);
  EXPECT_EQ(count_with("UHZ_CONFIG_REQUEST: "), 1);
  EXPECT_EQ(count_with("UHZ_CLASSIFY_REQUEST: "), 1);
  EXPECT_EQ(count_with("UHZ_SENSOR_REQUEST: "), 1);
  EXPECT_EQ(appcast().run_warning_count(), 4u);
  EXPECT_TRUE(values_of("UHZ_CONFIG_ACK").empty());

  post("UHZ_CONFIG_REQUEST", "vname=alpha,width=15,pd=0.9");
  run_for(kTick_s);
  // D3: 15 is not an option; the next lower one is 10 (exp 4, pclass 0.90).
  // pfa = 0.9^4 = 0.6561 -> FMT(., 3) = 0.656; width FMT(10, 1) = 10; pclass FMT(0.9, 3) = 0.9.
  const std::string ack = "vname=alpha,width=10,pd=0.9,pfa=0.656,pclass=0.9";
  EXPECT_EQ(values_of("UHZ_CONFIG_ACK"), std::vector<std::string>{ack});        // D22
  EXPECT_EQ(values_of("UHZ_CONFIG_ACK_ALPHA"), std::vector<std::string>{ack});  // D22
}

TEST_F(SensorOnBus, MailTimesAreClampedBetweenTheLastEngineTimeAndTheCycle) {
  std::ostringstream verbose;
  HazardSensorOptions options;
  options.verbose = &verbose;
  start(std::string(kField) + kOptions + "  min_reset_interval = 0\n", std::move(options));
  // A vehicle whose clock runs 1000 s ahead, and one 1000 s behind: both count as "now".
  ASSERT_TRUE(vehicle->notify("UHZ_CONFIG_REQUEST", std::string("vname=ahead,width=10,pd=0.9"), kT0 + 1000));
  ASSERT_TRUE(vehicle->notify("UHZ_CONFIG_REQUEST", std::string("vname=behind,width=10,pd=0.9"), kT0 - 1000));
  run_for(0.25);  // iterations at t0, t0 + 0.25
  // A time stamp that is not a number counts as the last time given to the engine.
  ASSERT_TRUE(vehicle->notify("UHZ_CONFIG_REQUEST", std::string("vname=nan,width=10,pd=0.9"),
                              std::numeric_limits<double>::quiet_NaN()));
  run_for(0.25);  // t0 + 0.5  // iterations at t0, t0 + 0.25, t0 + 0.5
  // Stamped between the iterations at t0 + 0.5 and t0 + 0.75: handled at its own time.
  ASSERT_TRUE(vehicle->notify("UHZ_CONFIG_REQUEST", std::string("vname=exact,width=10,pd=0.9"), kT0 + 0.625));
  clock.set_unix_s(kT0 + 0.75);
  app->cycle();
  std::vector<std::pair<std::string, double>> acks;
  std::istringstream in(verbose.str());
  for (std::string line; std::getline(in, line);) {
    const auto p = moos::parse_alog_line(line);
    if (p.kind == moos::AlogLineKind::kEntry && base::starts_with(p.entry.variable, "UHZ_CONFIG_ACK_"))
      acks.emplace_back(p.entry.variable, p.entry.time_s);
  }
  EXPECT_EQ(acks, (std::vector<std::pair<std::string, double>>{
                      {"UHZ_CONFIG_ACK_BEHIND", 0.0}, {"UHZ_CONFIG_ACK_AHEAD", 0.0},
                      {"UHZ_CONFIG_ACK_NAN", 0.25}, {"UHZ_CONFIG_ACK_EXACT", 0.625}}));
}

// ---- verbose (D29) ---------------------------------------------------------------------------------

TEST_F(SensorOnBus, VerboseWritesEveryPostingAndEventAsAlogLines_D29) {
  std::ostringstream verbose;
  HazardSensorOptions options;
  options.verbose = &verbose;
  start(std::string(kField) + kOptions + "  random_seed = 7\n", std::move(options));
  post("UHZ_CONFIG_REQUEST", "vname=alpha,width=20,pd=1");
  post("UHZ_SENSOR_REQUEST", "vname=alpha");
  post("NODE_REPORT", "NAME=alpha,X=0,Y=30,SPD=1,HDG=0");
  post("NODE_REPORT", "NAME=alpha,X=oops,Y=30,SPD=1,HDG=0");
  run_for(1.0);

  std::istringstream in(verbose.str());
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_TRUE(base::starts_with(line, "%% LOG FILE:")) << line;
  EXPECT_TRUE(base::ends_with(line, " uFldHazardSensor")) << line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(moos::alog_logstart(line), kT0);
  std::vector<moos::AlogEntry> postings;
  std::vector<std::string> events, run_warnings;
  while (std::getline(in, line)) {
    const auto p = moos::parse_alog_line(line);
    if (p.kind != moos::AlogLineKind::kEntry) continue;
    EXPECT_EQ(p.entry.source, "uFldHazardSensor") << line;
    if (p.entry.variable == kVerboseEvent) {
      events.push_back(p.entry.value);
    } else if (p.entry.variable == kVerboseRunWarning) {
      run_warnings.push_back(p.entry.value);
    } else {
      postings.push_back(p.entry);
    }
  }
  // Every posting the app made (the framework's own aside), in order, with its time.
  std::vector<moos::Message> bus_posts;
  for (const auto& m : bus.postings()) {
    if (m.source == "uFldHazardSensor" && !is_framework_posting(m.key)) bus_posts.push_back(m);
  }
  ASSERT_EQ(postings.size(), bus_posts.size());
  ASSERT_GT(postings.size(), 6u);
  for (std::size_t i = 0; i < postings.size(); ++i) {
    EXPECT_EQ(postings[i].variable, bus_posts[i].key) << i;
    EXPECT_EQ(postings[i].value, bus_posts[i].sval) << i;
    EXPECT_NEAR(postings[i].time_s, bus_posts[i].time - kT0, 5e-4) << i;
  }
  EXPECT_NE(std::find(events.begin(), events.end(), "Setting sensor settings for: alpha"), events.end());
  EXPECT_NE(std::find(events.begin(), events.end(),
                      "Detection report sent to vehicle: alpha (label h1)"), events.end());
  ASSERT_EQ(run_warnings.size(), 1u);
  EXPECT_TRUE(base::starts_with(run_warnings[0], "NODE_REPORT: ")) << run_warnings[0];
}

// ---- seeds (differences.md "Seeds") -------------------------------------------------------------

TEST_F(SensorOnBus, RandomSeedFixesTheSeedAndBeatsSeedRandom) {
  start(std::string(kField) + kOptions + "  seed_random = false\n  random_seed = 99\n");
  EXPECT_EQ(engine().seed().seed, 99u);
  EXPECT_EQ(engine().seed().source, hazard::SeedSource::kRandomSeed);
  EXPECT_TRUE(contains(app->terminal_report(), "       Seed: 99 (random_seed)\n"));
}

TEST_F(SensorOnBus, SeedRandomFalseMeansSeedOne_D16) {
  start(std::string(kField) + kOptions + "  seed_random = false\n");
  EXPECT_EQ(engine().seed().seed, 1u);
  EXPECT_TRUE(contains(app->terminal_report(), "       Seed: 1 (seed_random = false)\n"));
}

TEST_F(SensorOnBus, SeedRandomByDefaultTakesTheOperatingSystemsSeed_D16) {
  HazardSensorOptions options;
  int asked = 0;
  options.os_seed = [&asked] {
    ++asked;
    return std::uint64_t{8675309};
  };
  start(std::string(kField) + kOptions, std::move(options));
  EXPECT_EQ(asked, 1);
  EXPECT_EQ(engine().seed().seed, 8675309u);
  EXPECT_TRUE(contains(app->terminal_report(), "       Seed: 8675309 (operating system)\n"));
}

TEST(OperatingSystemSeed, TwoDrawsDiffer) {
  // 64-bit draws from std::random_device: equal only with probability 2^-64.
  EXPECT_NE(app_support::operating_system_seed(), app_support::operating_system_seed());
}

// ---- hazard files (manual 5) -------------------------------------------------------------------

TEST_F(SensorOnBus, HazardFilesAreReadRelativeToTheMissionFile_5) {
  write_file(dir / "fields/h.txt",
             "// test field\nregion = pts={0,0:10,0:10,10}\n"
             "hazard = x=1,y=2,label=p,type=hazard\nhazard = x=3,y=4,label=q,type=benign\n");
  write_file(dir / "abs.txt", "hazard = x=5,y=6,label=r,type=benign\n");
  start("  hazard_file = fields/h.txt\n  hazard_file = " + (dir / "abs.txt").string() + "\n" + kOptions);
  EXPECT_EQ(engine().field().size(), 3u);
  EXPECT_EQ(appcast().config_warnings().size(), 0u) << appcast().config_warnings().front();
  EXPECT_TRUE(contains(app->terminal_report(),
                       "Hazard File: (fields/h.txt, " + (dir / "abs.txt").string() +
                           ") \n     Hazard: 1\n     Benign: 2\n"));
}

// ---- geodesy: the mission's LatOrigin/LongOrigin ----------------------------------------------

TEST_F(SensorOnBus, TheMissionsOriginPlacesLatLonOnlyNodeReports) {
  start_mission("LatOrigin = 42.358436\nLongOrigin = -71.087448\n" +
                testing::mission_text(std::string("  hazard = x=0,y=0,label=a,type=hazard\n") + kOptions));
  EXPECT_TRUE(engine().effects().geodesy);
  post("NODE_REPORT", "NAME=alpha,LAT=42.358436,LON=-71.087448,SPD=1,HDG=0");
  run_for(0.5);
  ASSERT_TRUE(engine().find_vehicle("alpha"));
  const auto& pose = engine().vehicle(*engine().find_vehicle("alpha")).pose;
  ASSERT_TRUE(pose.has_value());
  EXPECT_LT(std::hypot(pose->position_m.x, pose->position_m.y), 1e-6);  // at the origin
  EXPECT_EQ(appcast().run_warning_count(), 0u);
}

TEST_F(SensorOnBus, WithoutAnOriginLatLonOnlyNodeReportsAreARunWarningSayingWhy_T9) {
  start(std::string("  hazard = x=0,y=0,label=a,type=hazard\n") + kOptions);
  EXPECT_FALSE(engine().effects().geodesy);
  post("NODE_REPORT", "NAME=alpha,LAT=42.358436,LON=-71.087448,SPD=1,HDG=0");
  run_for(0.5);
  EXPECT_FALSE(engine().find_vehicle("alpha"));
  EXPECT_TRUE(contains(app->terminal_report(),
                       "LAT/LON without X/Y cannot be placed (the mission file gives no "
                       "LatOrigin and LongOrigin)"));
}

// ---- the app adds nothing (design: one engine entry point) ------------------------------------------

TEST_F(SensorOnBus, PostsExactlyWhatTheEngineDecidesWhenDrivenTheSameWay) {
  std::string block =
      "  sensor_config = width=20, exp=2, pclass=0.7\n  random_seed = 11\n  min_classify_interval = 1\n";
  for (int i = 0; i < 30; ++i) {
    const std::string type = i % 3 == 0 ? "hazard" : "benign";
    block += "  hazard = x=" + std::to_string(i % 2 == 0 ? 8 : -6) + ",y=" + std::to_string(3 * i + 1) +
             ",label=o" + std::to_string(i) + ",type=" + type + (i % 4 == 1 ? ",hr=0.4" : "") + "\n";
  }
  start(block);

  // The reference: the same block through the engine alone, driven as hazard_replay drives it.
  hazard::EngineSetup setup = hazard::load_configuration(
      app_support::to_config_entries(mission->block("uFldHazardSensor")->lines),
      [](const std::string&) { return base::Result<std::string>::fail("no file"); });
  const hazard::SeedChoice seed = hazard::resolve_seed(std::nullopt, setup.config, nullptr);
  hazard::Driver reference(std::move(setup), seed);
  std::vector<hazard::Posting> expected = reference.start(kT0).outputs.postings;

  struct Mail {
    std::string var, value;
  };
  for (int k = 0; k <= 400; ++k) {
    const double t = kT0 + k * kTick_s;
    clock.set_unix_s(t);
    std::vector<Mail> mail;
    if (k == 2) mail = {{"UHZ_CONFIG_REQUEST", "vname=alpha,width=20,pd=0.7"}, {"UHZ_SENSOR_REQUEST", "vname=alpha"}};
    if (k >= 4 && k % 2 == 0) {
      mail.push_back({"NODE_REPORT", "NAME=alpha,X=0,Y=" + std::to_string(k / 2 - 2) + ",SPD=1,HDG=0"});
    }
    if (k > 4 && k % 10 == 0) {
      for (int i = 0; i < 30; ++i) mail.push_back({"UHZ_CLASSIFY_REQUEST", "vname=alpha,label=o" + std::to_string(i)});
    }
    for (const Mail& m : mail) {
      post(m.var, m.value);
      const auto out = reference.deliver(hazard::Mail{m.var, m.value, t}).outputs;
      expected.insert(expected.end(), out.postings.begin(), out.postings.end());
    }
    app->cycle();
    const auto out = reference.step(t).outputs;
    expected.insert(expected.end(), out.postings.begin(), out.postings.end());
  }

  std::vector<hazard::Posting> actual;
  for (const auto& m : bus.postings()) {
    if (m.source == "uFldHazardSensor" && !is_framework_posting(m.key)) actual.push_back({m.key, m.sval});
  }
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    EXPECT_EQ(actual[i].variable, expected[i].variable) << i;
    EXPECT_EQ(actual[i].value, expected[i].value) << i;
  }
  // The dice mattered (pd 0.7, pfa 0.49, pclass 0.7): some objects were missed, some answers
  // were right and some wrong.
  const auto detections = values_of("UHZ_DETECTION_REPORT_ALPHA").size();
  EXPECT_GT(detections, 3u);
  EXPECT_LT(detections, 30u);
  int right = 0, wrong = 0;
  for (const std::string& answer : values_of("UHZ_HAZARD_REPORT_ALPHA")) {
    const int i = std::stoi(answer.substr(answer.find("label=o") + 7));
    const bool truth_hazard = i % 3 == 0;
    ++(contains(answer, truth_hazard ? "type=hazard" : "type=benign") ? right : wrong);
  }
  EXPECT_GT(right, 0);
  EXPECT_GT(wrong, 0);
}

}  // namespace
}  // namespace ufld_hazard_sensor
