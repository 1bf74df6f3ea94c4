// uFldHazardSensor's information texts (manual 10.1, 11; docs/uFldHazardSensor.md) and the
// user page: --example is valid as printed and follows the parameter table; every --interface
// payload is accepted by our parsers; the docs list every parameter and message.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "HazardSensor_Info.hpp"
#include "hazard/config.hpp"
#include "hazard/driver.hpp"
#include "hazard/engine.hpp"
#include "hazard/messages/classify_request.hpp"
#include "hazard/messages/config_ack.hpp"
#include "hazard/messages/config_request.hpp"
#include "hazard/messages/detection_report.hpp"
#include "hazard/messages/hazard_report.hpp"
#include "hazard/messages/node_report.hpp"
#include "hazard/messages/options_summary.hpp"
#include "hazard/messages/sensor_clear.hpp"
#include "hazard/messages/sensor_request.hpp"
#include "hazard/messages/view_circle.hpp"
#include "hazard/messages/view_marker.hpp"
#include "hazard/messages/view_polygon.hpp"
#include "hazard/messages/view_seglist.hpp"
#include "base/text.hpp"
#include "base/version.hpp"
#include "moos/appcast.hpp"
#include "base/text.hpp"
#include "sensor_on_bus.hpp"

namespace ufld_hazard_sensor {
namespace {

using test_support::write_file;
using testing::contains;
using testing::SensorOnBus;

/// Help lines fit a classic terminal.
constexpr std::size_t kMaxHelpColumns = 80;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

/// The value of the example line `  key = value  // ...` (or `  // key = ...`), if present.
std::optional<std::string> example_value(const std::string& example, const std::string& key,
                                         bool commented_out = false) {
  for (const std::string& line : lines_of(example)) {
    std::string_view l = base::trim(line);
    if (commented_out != base::starts_with(l, "// ")) continue;
    if (commented_out) l.remove_prefix(3);
    const auto eq = l.find('=');
    if (eq == std::string_view::npos || base::trim(l.substr(0, eq)) != key) continue;
    std::string_view value = l.substr(eq + 1);
    value = value.substr(0, value.find("//"));
    return std::string(base::trim(value));
  }
  return std::nullopt;
}

// ---- --example (manual 10.1; differences.md "--example") ----------------------------------------

TEST_F(SensorOnBus, ExampleAsPrintedLoadsWithZeroConfigWarnings) {
  write_file(dir / "hazards.txt",
             "hazard = x=-52,y=-290,label=75,type=hazard\nhazard = x=41,y=-108,label=53,type=benign\n");
  start_mission("Community = shoreside\n" + example_text());
  EXPECT_TRUE(appcast().config_warnings().empty()) << appcast().config_warnings().front();
  EXPECT_EQ(engine().field().size(), 2u);
  EXPECT_EQ(engine().config().options.size(), 3u);
  EXPECT_EQ(app->settings().app_tick_hz, 4.0);
  EXPECT_EQ(app->settings().max_appcast_events, 20u);
  run_for(1.0);
  EXPECT_TRUE(appcast().config_warnings().empty());
  EXPECT_EQ(appcast().run_warning_count(), 0u);
}

TEST(Example, ListsEverySensorParameterAtItsTableDefault) {
  const std::string example = example_text();
  int listed = 0;
  for (const hazard::ParameterSpec& p : hazard::parameter_table()) {
    const std::string name(p.name);
    switch (p.kind) {
      case hazard::ParamKind::kFramework:
      case hazard::ParamKind::kNoEffect:
        continue;  // the framework's lines are checked below; dead features are not advertised
      case hazard::ParamKind::kHazardLine:
        EXPECT_TRUE(example_value(example, name, /*commented_out=*/true).has_value()) << name;
        break;
      case hazard::ParamKind::kHazardFile:
      case hazard::ParamKind::kSensorConfig:
        EXPECT_TRUE(example_value(example, name).has_value()) << name;
        break;
      default:
        if (p.default_text.empty()) {
          EXPECT_TRUE(example_value(example, name, /*commented_out=*/true).has_value()) << name;
        } else {
          EXPECT_EQ(example_value(example, name), std::string(p.default_text)) << name;
        }
    }
    ++listed;
  }
  EXPECT_GE(listed, 22);
  EXPECT_EQ(example_value(example, "AppTick"), "4");
  EXPECT_EQ(example_value(example, "CommsTick"), "4");
  EXPECT_EQ(example_value(example, "term_report_interval"), "0.4");
  EXPECT_EQ(example_value(example, "max_appcast_events"), "20");  // the original's
  EXPECT_EQ(example_value(example, "max_appcast_run_warnings"), "10");
}

TEST(Example, NamesEveryParameterOfTheManualsListing_10_3) {
  const std::string example = example_text();
  for (const char* name :
       {"AppTick", "CommsTick", "default_hazard_shape", "default_hazard_color",
        "default_hazard_width", "default_benign_shape", "default_benign_color",
        "default_benign_width", "swath_transparency", "sensor_config", "hazard_file",
        "swath_length", "seed_random", "show_hazards", "show_swath", "show_detections", "show_pd",
        "show_pfa", "min_reset_interval", "min_classify_interval", "options_summary_interval"}) {
    EXPECT_TRUE(example_value(example, name).has_value()) << name;
  }
  // Listed differences (docs/uFldHazardSensor.md): pclass= for class=, differences.md
  // "Effective defaults".
  EXPECT_EQ(example_value(example, "seed_random"), "true");    // D16 (the listing says false)
  EXPECT_EQ(example_value(example, "show_pfa"), "false");      // D15 (the listing says true)
  EXPECT_EQ(example_value(example, "show_detections"), "nolimit");
  EXPECT_TRUE(contains(example, "  sensor_config = width=10, exp=6, pclass=0.93, max=1\n"));
}

// ---- --interface (manual 11) -----------------------------------------------------------------------

/// Our parser for each variable's example payload: true if it accepts it.
const std::map<std::string, std::function<bool(const std::string&)>>& parsers() {
  static const std::map<std::string, std::function<bool(const std::string&)>> p = {
      {"NODE_REPORT", [](const std::string& v) { return bool(hazard::parse_node_report(v)); }},
      {"UHZ_SENSOR_REQUEST", [](const std::string& v) { return bool(hazard::parse_sensor_request(v)); }},
      {"UHZ_CONFIG_REQUEST", [](const std::string& v) { return bool(hazard::parse_config_request(v)); }},
      {"UHZ_CLASSIFY_REQUEST", [](const std::string& v) { return bool(hazard::parse_classify_request(v)); }},
      {"UHZ_SENSOR_CLEAR", [](const std::string& v) { return bool(hazard::parse_sensor_clear(v)); }},
      // Any value: pMarineViewer announces itself with its name.
      {"PMV_CONNECT", [](const std::string& v) { return !v.empty(); }},
      {"UHZ_DETECTION_REPORT", [](const std::string& v) { return bool(hazard::parse_detection_report(v)); }},
      {"UHZ_DETECTION_REPORT_<V>", [](const std::string& v) { return bool(hazard::parse_detection_report(v)); }},
      {"UHZ_HAZARD_REPORT", [](const std::string& v) { return bool(hazard::parse_hazard_report(v)); }},
      {"UHZ_HAZARD_REPORT_<V>", [](const std::string& v) { return bool(hazard::parse_hazard_report(v)); }},
      {"UHZ_CONFIG_ACK", [](const std::string& v) { return bool(hazard::parse_config_ack(v)); }},
      {"UHZ_CONFIG_ACK_<V>", [](const std::string& v) { return bool(hazard::parse_config_ack(v)); }},
      {"UHZ_OPTIONS_SUMMARY", [](const std::string& v) { return bool(hazard::parse_options_summary(v)); }},
      {"VIEW_POLYGON", [](const std::string& v) { return bool(hazard::parse_view_polygon(v)); }},
      {"VIEW_CIRCLE", [](const std::string& v) { return bool(hazard::parse_view_circle(v)); }},
      {"VIEW_MARKER", [](const std::string& v) { return bool(hazard::parse_view_marker(v)); }},
      {"VIEW_SEGLIST", [](const std::string& v) { return bool(hazard::parse_view_seglist(v)); }},
      {"APPCAST_REQ", [](const std::string& v) {
         return moos::parse_appcast_request(v, "shoreside", kAppName).has_value();
       }},
      {"UFLDHAZARDSENSOR_ITER_GAP", [](const std::string& v) { return base::parse_number(v).has_value(); }},
      {"UFLDHAZARDSENSOR_ITER_LEN", [](const std::string& v) { return base::parse_number(v).has_value(); }},
  };
  return p;
}

/// Framework publications that no program of ours parses (viewers read them).
bool read_only_by_viewers(const std::string& name) {
  return name == "APPCAST" || name == "UFLDHAZARDSENSOR_STATUS";
}

TEST(Interface, EveryExamplePayloadIsAcceptedByOurParsers) {
  std::vector<std::pair<std::string, std::string>> all;
  for (const auto& v : hazard::Engine::subscriptions()) all.emplace_back(v.name, v.example);
  for (const auto& v : hazard::Engine::publications()) all.emplace_back(v.name, v.example);
  for (const auto& v : framework_subscriptions()) all.emplace_back(v.name, v.example);
  for (const auto& v : framework_publications()) all.emplace_back(v.name, v.example);
  ASSERT_GE(all.size(), 22u);
  for (const auto& [name, example] : all) {
    if (read_only_by_viewers(name)) continue;
    const auto parser = parsers().find(name);
    ASSERT_NE(parser, parsers().end()) << name << ": a new interface variable needs a parser here";
    EXPECT_TRUE(parser->second(example)) << name << " = " << example;
  }
}

TEST(Interface, EverySubscriptionExampleIsHandledByTheEngineWithoutAWarning) {
  hazard::EngineSetup setup = hazard::load_configuration(
      {{"sensor_config", "width=25,exp=4,pclass=0.8", "m.moos", 1},
       {"hazard", "x=51,y=11.3,label=12,type=hazard", "m.moos", 2}},
      [](const std::string&) { return base::Result<std::string>::fail("no file"); });
  hazard::Driver driver(std::move(setup), hazard::SeedChoice{});
  driver.start(0.0);
  // archie detects object 12 for certain (pd 1), so the classify example finds its credit.
  driver.deliver(hazard::Mail{"UHZ_CONFIG_REQUEST", "vname=archie,width=25,pd=1", 0.0});
  driver.deliver(hazard::Mail{"UHZ_SENSOR_REQUEST", "vname=archie", 0.0});
  driver.deliver(hazard::Mail{"NODE_REPORT", "NAME=archie,X=51,Y=11.3,SPD=1,HDG=90", 0.0});
  ASSERT_EQ(driver.step(0.0).outputs.postings.size(), 5u);  // summary, swath, 2 detections, circle
  double t = 0.0;
  for (const auto& v : hazard::Engine::subscriptions()) {
    const auto out = driver.deliver(hazard::Mail{v.name, v.example, t += 1.0}).outputs;
    EXPECT_TRUE(out.run_warnings.empty()) << v.name << ": " << out.run_warnings.front();
  }
}

TEST(Interface, TextListsEveryVariableWithItsExampleAndMeaning) {
  const std::string text = interface_text();
  EXPECT_TRUE(base::starts_with(text, std::string(63, '=') + "\nuFldHazardSensor INTERFACE\n"));
  const auto subs = text.find("SUBSCRIPTIONS:");
  const auto pubs = text.find("PUBLICATIONS:");
  ASSERT_NE(subs, std::string::npos);
  ASSERT_NE(pubs, std::string::npos);
  for (const auto& v : hazard::Engine::subscriptions()) {
    const auto at = text.find("  " + std::string(v.name) + " = " + std::string(v.example) + "\n      " +
                              std::string(v.meaning) + "\n");
    EXPECT_TRUE(at > subs && at < pubs) << v.name;
  }
  for (const auto& v : hazard::Engine::publications()) {
    const auto at = text.find("  " + std::string(v.name) + " = " + std::string(v.example) + "\n");
    EXPECT_TRUE(at > pubs && at != std::string::npos) << v.name;
  }
  for (const auto& v : framework_subscriptions()) EXPECT_LT(text.find(v.name + " = "), pubs);
  for (const auto& v : framework_publications()) {
    const auto at = text.find(v.name + " = ");
    EXPECT_TRUE(at > pubs && at != std::string::npos) << v.name;
  }
}

// ---- --help and --version (manual listing 11.4) ---------------------------------------------------

TEST(Help, NamesEverySwitchOfTheManualAndVerbose_11_4_D29) {
  const std::string help = help_text();
  for (const char* s : {"Usage: uFldHazardSensor file.moos [OPTIONS]", "--alias=<ProcessName>",
                        "--example, -e", "--help, -h", "--interface, -i", "--version,-v",
                        "--verbose=<setting>", "a bare --verbose means true", ".alog lines",
                        "argv[2]", "pAntler launching conventions"}) {
    EXPECT_TRUE(contains(help, s)) << s;
  }
  for (const std::string& line : lines_of(help)) EXPECT_LE(line.size(), kMaxHelpColumns) << line;
}

TEST(Version, NamesTheProgramAndTheRelease) {
  EXPECT_EQ(version_text(),
            "uFldHazardSensor " + std::string(base::release_version()) + " (HazardSensor)\n");
}

// ---- the user page ----------------------------------------------------------------------------------

std::string user_page() {
  std::ifstream in(std::string(HAZARD_SOURCE_DIR) + "/docs/uFldHazardSensor.md");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(UserPage, HoldsTheParameterTableGeneratedFromTheOneTable) {
  const std::string page = user_page();
  ASSERT_FALSE(page.empty()) << "docs/uFldHazardSensor.md is missing";
  EXPECT_TRUE(contains(page, hazard::parameter_table_markdown()))
      << "regenerate the table in docs/uFldHazardSensor.md from hazard::parameter_table_markdown()";
}

TEST(UserPage, DocumentsEveryMessageAndSwitchAndLinksTheDifferences) {
  const std::string page = user_page();
  for (const auto& v : hazard::Engine::subscriptions()) EXPECT_TRUE(contains(page, "`" + std::string(v.name))) << v.name;
  for (const auto& v : hazard::Engine::publications()) EXPECT_TRUE(contains(page, "`" + std::string(v.name))) << v.name;
  for (const auto& v : framework_subscriptions()) EXPECT_TRUE(contains(page, "`" + v.name)) << v.name;
  for (const char* s : {"--example", "--interface", "--help", "--version", "--verbose", "--alias",
                        "max_appcast_events", "differences.md"}) {
    EXPECT_TRUE(contains(page, s)) << s;
  }
}

}  // namespace
}  // namespace ufld_hazard_sensor
