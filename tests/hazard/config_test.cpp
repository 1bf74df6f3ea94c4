// The configuration block: the one table, defaults, validation, repeats, seeds (differences.md
// D14-D18, D26-D28, D36, D38, "Validation", "Seeds").
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "scenario.hpp"

namespace hazard {
namespace {

using testing::contains;
using testing::setup_from;

TEST(Config, EffectiveDefaults_Rulings) {
  const EngineConfig c;
  EXPECT_EQ(c.swath_length_m, 5);
  EXPECT_EQ(c.min_reset_interval_s, 300);
  EXPECT_EQ(c.min_classify_interval_s, 30);
  EXPECT_EQ(c.options_summary_interval_s, 10);
  EXPECT_EQ(c.max_turn_rate_dps, 1.5);
  EXPECT_EQ(c.max_vehicle_speed_mps, 2.0);  // D14
  EXPECT_FALSE(c.ignore_resemblances);
  EXPECT_TRUE(c.seed_random);               // D16
  EXPECT_FALSE(c.random_seed);
  EXPECT_TRUE(c.show_hazards);
  EXPECT_TRUE(c.show_swath);
  EXPECT_TRUE(c.show_pd);
  EXPECT_FALSE(c.show_pfa);                 // D15
  EXPECT_TRUE(c.show_detections.enabled);
  EXPECT_FALSE(c.show_detections.duration_s);
  EXPECT_EQ(c.swath_transparency, 0.2);
  EXPECT_EQ(c.hazard_color, "green");       // D17
  EXPECT_EQ(c.benign_color, "light_blue");  // D18
  EXPECT_EQ(c.hazard_shape, "triangle");
  EXPECT_EQ(c.benign_shape, "triangle");
  EXPECT_EQ(c.hazard_marker_width_m, 8);
  EXPECT_EQ(c.benign_marker_width_m, 8);
  EXPECT_EQ(c.app_tick_hz, 4);
  EXPECT_TRUE(c.options.empty());
}

TEST(Config, ManualBareBonesBlockLoadsCleanly) {
  const EngineSetup s = setup_from(
      "hazard_file   = hazards.txt\n"
      "sensor_config = width=25, exp=4, pclass=0.80\n"
      "sensor_config = width=50, exp=2, pclass=0.60\n"
      "sensor_config = width=10, exp=6, pclass=0.93\n",
      {{"hazards.txt", "hazard = x=-52,y=-290,label=75,type=hazard\n"}});
  EXPECT_TRUE(s.config_warnings.empty()) << s.config_warnings[0];
  EXPECT_EQ(s.config.options.size(), 3u);
  EXPECT_EQ(s.field.size(), 1u);
  ASSERT_EQ(s.hazard_files.size(), 1u);
  EXPECT_TRUE(s.hazard_files[0].read_ok);
  EXPECT_EQ(s.hazard_files[0].counts.hazards, 1);
}

TEST(Config, EveryParameterOfTheManualIsAccepted) {
  const EngineSetup s = setup_from(
      "AppTick = 10\nCommsTick = 4\nterm_report_interval = 0.4\nmax_appcast_events = 8\n"
      "max_appcast_run_warnings = 10\nMaxAppTick = 20\nIterateMode = 0\nmoos_time_warp = 5\n"
      "default_hazard_shape = square\ndefault_hazard_color = red\ndefault_hazard_width = 6\n"
      "default_benign_shape = circle\ndefault_benign_color = white\ndefault_benign_width = 4\n"
      "swath_transparency = 0.5\nsensor_config = width=25, exp=4, class=0.80\n"
      "swath_length = 7\nseed_random = false\nshow_hazards = false\nshow_swath = false\n"
      "show_detections = 60\nshow_pd = false\nshow_pfa = true\nmin_reset_interval = 100\n"
      "min_classify_interval = 20\noptions_summary_interval = 5\nmax_turn_rate = 3\n"
      "max_vehicle_speed = 3\nignore_resemblances = true\nrandom_seed = 42\n"
      "hazard = x=1,y=2,label=a,type=hazard\n");
  // Only the two no-field warnings would be allowed; here both a field and options exist.
  EXPECT_TRUE(s.config_warnings.empty()) << s.config_warnings[0];
  const EngineConfig& c = s.config;
  EXPECT_EQ(c.app_tick_hz, 10);
  EXPECT_EQ(c.hazard_shape, "square");
  EXPECT_EQ(c.hazard_color, "red");
  EXPECT_EQ(c.hazard_marker_width_m, 6);
  EXPECT_EQ(c.benign_shape, "circle");
  EXPECT_EQ(c.benign_color, "white");
  EXPECT_EQ(c.benign_marker_width_m, 4);
  EXPECT_EQ(c.swath_transparency, 0.5);
  EXPECT_EQ(c.swath_length_m, 7);
  EXPECT_FALSE(c.seed_random);
  EXPECT_FALSE(c.show_hazards);
  EXPECT_FALSE(c.show_swath);
  EXPECT_EQ(c.show_detections.duration_s, 60);
  EXPECT_FALSE(c.show_pd);
  EXPECT_TRUE(c.show_pfa);
  EXPECT_EQ(c.min_reset_interval_s, 100);
  EXPECT_EQ(c.min_classify_interval_s, 20);
  EXPECT_EQ(c.options_summary_interval_s, 5);
  EXPECT_EQ(c.max_turn_rate_dps, 3);
  EXPECT_EQ(c.max_vehicle_speed_mps, 3);
  EXPECT_TRUE(c.ignore_resemblances);
  EXPECT_EQ(c.random_seed, 42u);
}

TEST(Config, NamesAreCaseInsensitiveAndAliasesWork_D36) {
  const EngineSetup s = setup_from(
      "SWATH_LENGTH = 8\nClassify_Period = 12\nshow_reports = nolimit\napptick = 2\n"
      "Sensor_Config = width=5,exp=2,pclass=0.9\nHAZARD = x=0,y=0,label=q,type=benign\n");
  EXPECT_TRUE(s.config_warnings.empty()) << s.config_warnings[0];
  EXPECT_EQ(s.config.swath_length_m, 8);
  EXPECT_EQ(s.config.min_classify_interval_s, 12);
  EXPECT_EQ(s.config.app_tick_hz, 2);
}

TEST(Config, RepeatedScalarTakesLastValueAndWarns_D36) {
  const EngineSetup s = setup_from(
      "swath_length = 6\nswath_length = 9\nAppTick = 4\nAPPTICK = 8\n"
      "sensor_config = width=5,exp=2,pclass=0.9\nhazard = x=0,y=0,label=q,type=benign\n");
  EXPECT_EQ(s.config.swath_length_m, 9);
  EXPECT_EQ(s.config.app_tick_hz, 8);  // framework parameters included
  ASSERT_EQ(s.config_warnings.size(), 2u);
  EXPECT_EQ(s.config_warnings[0],
            "test.moos:2: parameter 'swath_length' repeated (also at test.moos:1); the last "
            "value is used");
}

TEST(Config, OutOfRangeValuesWarnAndKeepDefault_ValidationTable_D38) {
  struct Case {
    const char* line;
    const char* expected;
  };
  const Case cases[] = {
      {"swath_transparency = 1.5", "parameter 'swath_transparency' value '1.5': outside [0, 1]"},
      {"options_summary_interval = -1", "outside [0, 604800]"},
      {"min_reset_interval = -5", "outside [0, 604800]"},
      {"min_reset_interval = 1e308", "outside [0, 604800]"},
      {"min_classify_interval = 604801", "outside [0, 604800]"},
      {"min_classify_interval = abc", "not a finite number"},
      {"max_turn_rate = 0", "outside (0, 3600] (or 'off')"},
      {"max_turn_rate = 1e308", "outside (0, 3600] (or 'off')"},
      {"max_vehicle_speed = -2", "(or 'off')"},
      {"max_vehicle_speed = 101", "outside (0, 100] (or 'off')"},
      {"show_detections = -1", "(or 'nolimit')"},
      {"swath_length = 0", "outside (0, 1000000]"},
      {"swath_length = 1e308", "value '1e308': outside (0, 1000000]"},
      {"default_hazard_width = 1e7", "outside [0, 10000]"},
      {"seed_random = maybe", "not a boolean word"},
      {"default_hazard_color = blurple", "not a known colour"},
      {"default_benign_shape = blob", "not a known shape"},
      {"random_seed = -3", "not a whole number"},
      {"AppTick = 0", "outside (0, inf)"},
      {"swath_length = nan", "not a finite number"},
      {"min_classify_interval = 1e999", "not a finite number"},
  };
  const EngineConfig defaults;
  for (const Case& c : cases) {
    const EngineSetup s = setup_from(std::string(c.line) + "\n");
    EXPECT_TRUE(contains(s.config_warnings, c.expected)) << c.line;
    EXPECT_TRUE(contains(s.config_warnings, "test.moos:1: ")) << c.line;
    EXPECT_TRUE(contains(s.config_warnings, "; ignored")) << c.line;
  }
  const EngineSetup s = setup_from("swath_transparency = 1.5\nmax_turn_rate = 0\n");
  EXPECT_EQ(s.config.swath_transparency, defaults.swath_transparency);
  EXPECT_EQ(s.config.max_turn_rate_dps, defaults.max_turn_rate_dps);
}

TEST(Config, ShortSwathIsRaisedToOneWithAWarning_ValidationTable) {
  const EngineSetup s = setup_from("swath_length = 0.5\n");
  EXPECT_EQ(s.config.swath_length_m, 1);
  EXPECT_TRUE(contains(s.config_warnings, "test.moos:1: parameter 'swath_length' value '0.5': "
                                          "raised to 1"));
}

TEST(Config, GatesSwitchOffWithOff_ValidationTable) {
  const EngineSetup s = setup_from("max_turn_rate = off\nmax_vehicle_speed = OFF\n");
  EXPECT_FALSE(s.config.max_turn_rate_dps);
  EXPECT_FALSE(s.config.max_vehicle_speed_mps);
}

TEST(Config, ShowDetectionsForms_D38) {
  EXPECT_FALSE(setup_from("show_detections = 0\n").config.show_detections.enabled);
  const auto sixty = setup_from("show_detections = 60\n").config.show_detections;
  EXPECT_TRUE(sixty.enabled);
  EXPECT_EQ(sixty.duration_s, 60);
  const auto unlimited = setup_from("show_detections = 30\nshow_reports = Unlimited\n")
                             .config.show_detections;
  EXPECT_TRUE(unlimited.enabled);
  EXPECT_FALSE(unlimited.duration_s);
}

TEST(Config, ToggleFlipsTheCurrentValue_Spec0) {
  EXPECT_TRUE(setup_from("show_pfa = toggle\n").config.show_pfa);
  EXPECT_FALSE(setup_from("show_pd = toggle\n").config.show_pd);
}

TEST(Config, UnknownParameterAndEmptyValueWarn) {
  const EngineSetup s = setup_from("swath_lenght = 5\nshow_pd =\n");
  EXPECT_TRUE(contains(s.config_warnings,
                       "test.moos:1: unknown parameter 'swath_lenght' (value '5') ignored"));
  EXPECT_TRUE(contains(s.config_warnings, "test.moos:2: parameter 'show_pd' has no value"));
}

// A mission line may hold any byte but a newline: keys, values and file names reach the
// warnings (and the terminal report) escaped, so an ESC sequence cannot repaint a terminal.
TEST(Config, ControlBytesOfTheMissionAreEscapedInWarnings_Hardening) {
  const std::string esc = "\x1b[2J";
  const EngineSetup s = setup_from("swath_length = 5" + esc + "\nbo" + esc + "gus = 1\n" +
                                   "hazard_file = gone" + esc + ".txt\n" +
                                   "hazard_file = bad" + esc + ".txt\n",
                                   {{"bad" + esc + ".txt", "junk\n"}});
  ASSERT_GE(s.config_warnings.size(), 4u);
  for (const std::string& w : s.config_warnings) EXPECT_EQ(w.find('\x1b'), std::string::npos) << w;
  EXPECT_TRUE(contains(s.config_warnings, "parameter 'swath_length' value '5\\x1B[2J'"));
  EXPECT_TRUE(contains(s.config_warnings, "unknown parameter 'bo\\x1B[2Jgus'"));
  EXPECT_TRUE(contains(s.config_warnings, "cannot read hazard file 'gone\\x1B[2J.txt'"));
  EXPECT_TRUE(contains(s.config_warnings, "bad\\x1B[2J.txt:1: unrecognised line 'junk'"));
}

TEST(Config, AnUnreadableHazardFileWarningEndsWithTheReadersReason) {
  const EngineSetup s = load_configuration(
      testing::entries("hazard_file = charts\n"),
      [](const std::string&) { return base::Result<std::string>::fail("is a directory"); });
  EXPECT_TRUE(contains(s.config_warnings,
                       "test.moos:1: cannot read hazard file 'charts': is a directory"));
  ASSERT_EQ(s.hazard_files.size(), 1u);
  EXPECT_FALSE(s.hazard_files[0].read_ok);
}

TEST(Config, DeadFeaturesWarnThatTheyHaveNoEffect) {
  const EngineSetup s = setup_from("rn_algorithm = uniform,pct=0.5\nrn_uniform_pct = 0.3\n");
  EXPECT_TRUE(contains(s.config_warnings, "test.moos:1: parameter 'rn_algorithm'"));
  EXPECT_TRUE(contains(s.config_warnings, "test.moos:2: parameter 'rn_uniform_pct'"));
  EXPECT_TRUE(contains(s.config_warnings, "has no effect"));
}

TEST(Config, MissingFieldOrOptionsWarnButLoad_D26) {
  const EngineSetup s = setup_from("swath_length = 5\n");
  EXPECT_TRUE(contains(s.config_warnings, "no hazard field"));
  EXPECT_TRUE(contains(s.config_warnings, "no sensor_config"));
}

TEST(Config, SensorConfigProblemsNameThePlace_ValidationTable) {
  const EngineSetup s = setup_from(
      "sensor_config = width=25, exp=4, pclass=0.8\n"
      "sensor_config = width=25, exp=2, pclass=0.6\n"
      "sensor_config = width=10, exp=6, pclass=0.3\n"
      "sensor_config = width=12, exp=6, pclass=0.9, colour=red\n");
  EXPECT_EQ(s.config.options.size(), 2u);
  EXPECT_TRUE(contains(s.config_warnings, "test.moos:2: parameter 'sensor_config' value "
                                          "'width=25, exp=2, pclass=0.6': width 25 is already "
                                          "configured; option rejected"));
  EXPECT_TRUE(contains(s.config_warnings, "test.moos:3: parameter 'sensor_config'"));
  EXPECT_TRUE(contains(s.config_warnings, "test.moos:4: sensor_config: unknown key 'colour'"));
}

TEST(Config, HazardFilesRepeatAndDuplicatesCrossFiles) {
  const EngineSetup s = setup_from(
      "hazard_file = a.txt\nhazard_file = b.txt\nhazard_file = missing.txt\n"
      "hazard = x=9,y=9,label=inline,type=benign\nhazard = x=9,y=9,label=one,type=benign\n",
      {{"a.txt", "hazard = x=1,y=1,label=one,type=hazard\n"},
       {"b.txt",
        "hazard = x=2,y=2,label=one,type=benign\nhazard = x=3,y=3,label=two,type=benign\n"}});
  EXPECT_EQ(s.field.size(), 3u);  // one (from a), two, inline
  EXPECT_TRUE(s.field.object(*s.field.find("one")).is_hazard());
  EXPECT_TRUE(contains(s.config_warnings, "b.txt:1: duplicate label 'one'"));
  EXPECT_TRUE(contains(s.config_warnings, "test.moos:5: duplicate label 'one'"));
  EXPECT_TRUE(contains(s.config_warnings, "test.moos:3: cannot read hazard file 'missing.txt'"));
  ASSERT_EQ(s.hazard_files.size(), 3u);
  EXPECT_FALSE(s.hazard_files[2].read_ok);
}

TEST(Seeds, PrecedenceCommandLineThenRandomSeedThenSeedRandom_Rulings) {
  int os_calls = 0;
  const auto os = [&] {
    ++os_calls;
    return std::uint64_t{987654321};
  };
  EngineConfig c;
  c.random_seed = 42;
  EXPECT_EQ(resolve_seed(7u, c, os).seed, 7u);
  EXPECT_EQ(resolve_seed(7u, c, os).source, SeedSource::kCommandLine);
  EXPECT_EQ(resolve_seed(std::nullopt, c, os).seed, 42u);
  EXPECT_EQ(resolve_seed(std::nullopt, c, os).source, SeedSource::kRandomSeed);
  c.random_seed.reset();
  EXPECT_EQ(resolve_seed(std::nullopt, c, os).seed, 987654321u);
  EXPECT_EQ(os_calls, 1);
  c.seed_random = false;
  EXPECT_EQ(resolve_seed(std::nullopt, c, os).seed, kUnseededSeed);
  EXPECT_EQ(resolve_seed(std::nullopt, c, os).source, SeedSource::kFixed);
  EXPECT_EQ(os_calls, 1);
}

TEST(ParameterTable, DefaultsParseAndEveryEntryIsDocumented) {
  for (const ParameterSpec& p : parameter_table()) {
    EXPECT_FALSE(p.help.empty()) << p.name;
    EXPECT_EQ(find_parameter(p.name), &p) << p.name;
    EXPECT_FALSE(allowed_values_text(p).empty()) << p.name;
  }
  EXPECT_EQ(find_parameter("moos_quiet")->kind, ParamKind::kFramework);
  EXPECT_EQ(find_parameter("show_reports")->name, "show_detections");
  EXPECT_EQ(find_parameter("nonsense"), nullptr);
}

// One table: the docs page holds the generated table verbatim.
TEST(ParameterTable, DocsConfigurationPageHoldsTheGeneratedTable) {
  std::ifstream in(std::string(HAZARD_SOURCE_DIR) + "/docs/configuration.md");
  ASSERT_TRUE(in) << "docs/configuration.md is missing";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find(parameter_table_markdown()), std::string::npos)
      << "regenerate the table in docs/configuration.md from parameter_table_markdown():\n"
      << parameter_table_markdown();
}

}  // namespace
}  // namespace hazard
