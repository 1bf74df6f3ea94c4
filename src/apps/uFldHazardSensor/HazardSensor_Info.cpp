#include "HazardSensor_Info.hpp"

#include <algorithm>

#include "HazardSensor.hpp"
#include "app_support.hpp"
#include "hazard/config.hpp"
#include "hazard/engine.hpp"
#include "base/version.hpp"
#include "base/text.hpp"

namespace ufld_hazard_sensor {

namespace {

/// The '=' rules of the MOOS-IvP information screens (manual listings 10.3 and 11.4).
constexpr std::size_t kRuleWidth = 63;
/// Indent of the lines inside the example block.
constexpr std::size_t kExampleIndent = 2;
/// Widths the example's framework lines are aligned to: the longest key of each group
/// ("CommsTick", "max_appcast_run_warnings") and the longest value ("0.4").
constexpr std::size_t kTickKeyWidth = 9;
constexpr std::size_t kAppCastKeyWidth = 24;
constexpr std::size_t kAppCastValueWidth = 3;
/// The dashes under SUBSCRIPTIONS: and PUBLICATIONS: (MOOS-IvP's --interface layout).
constexpr std::size_t kSectionRuleWidth = 36;

std::string rule() { return std::string(kRuleWidth, '=') + "\n"; }

std::string banner(const std::string& title) { return rule() + title + "\n" + rule(); }

/// Example values of the framework lines of --example (manual listing 10.3;
/// docs/protocol.md 6.3, 7.2).
constexpr const char* kExampleCommsTick = "4";
/// core-moos AppCasting's default (docs/protocol.md 7.2).
constexpr const char* kExampleTermReportInterval = "0.4";

/// Example values of the repeatable parameters, which have no default (manual 2.2, 4.5, 5).
constexpr const char* kExampleHazardFile = "hazards.txt";
constexpr const char* kExampleHazardLine = "x=-52,y=-290,label=75,type=hazard";
constexpr const char* kExampleSensorConfigs[] = {
    "width=25, exp=4, pclass=0.80", "width=50, exp=2, pclass=0.60",
    "width=10, exp=6, pclass=0.93, max=1"};
constexpr const char* kExampleRandomSeed = "7";

std::string number_text(double v) { return base::format_g(v); }

/// `text` followed by blanks up to `width` columns.
std::string padded(std::string_view text, std::size_t width) {
  return std::string(text) + std::string(width > text.size() ? width - text.size() : 0, ' ');
}

/// `  key = value  // comment`, with `=` after `key_width` columns and the comment after
/// `value_width` more.
std::string example_line(std::string_view key, const std::string& value, std::size_t key_width,
                         const std::string& comment = {}, bool commented_out = false,
                         std::size_t value_width = 0) {
  std::string out(kExampleIndent, ' ');
  if (commented_out) out += "// ";
  out += padded(key, key_width) + " = ";
  if (comment.empty()) return out + value + "\n";
  return out + padded(value, value_width) + "  // " + comment + "\n";
}

bool is_repeatable(hazard::ParamKind kind) {
  return kind == hazard::ParamKind::kHazardFile || kind == hazard::ParamKind::kHazardLine ||
         kind == hazard::ParamKind::kSensorConfig;
}

/// The sensor's own scalar parameters (not framework, not the original's dead features).
std::vector<const hazard::ParameterSpec*> scalar_parameters() {
  std::vector<const hazard::ParameterSpec*> out;
  for (const hazard::ParameterSpec& p : hazard::parameter_table()) {
    if (p.kind == hazard::ParamKind::kFramework || p.kind == hazard::ParamKind::kNoEffect ||
        is_repeatable(p.kind)) {
      continue;
    }
    out.push_back(&p);
  }
  return out;
}

std::string example_framework_section() {
  const moos::AppTraits traits = hazard_sensor_traits();
  std::string out;
  out += example_line("AppTick", number_text(traits.default_app_tick_hz), kTickKeyWidth);
  out += example_line("CommsTick", kExampleCommsTick, kTickKeyWidth);
  out += "\n  // AppCasting (the MOOS application framework)\n";
  out += example_line("term_report_interval", kExampleTermReportInterval, kAppCastKeyWidth, "default",
                      false, kAppCastValueWidth);
  out += example_line("max_appcast_events", std::to_string(traits.default_max_appcast_events),
                      kAppCastKeyWidth, "default", false, kAppCastValueWidth);
  out += example_line("max_appcast_run_warnings",
                      std::to_string(traits.default_max_appcast_run_warnings), kAppCastKeyWidth,
                      "default", false, kAppCastValueWidth);
  return out;
}

std::string example_field_and_options_section() {
  std::string out;
  out += "\n  // The hazard field (manual 5): files, relative to the mission file, and/or lines\n";
  out += example_line("hazard_file", kExampleHazardFile, 0);
  out += example_line("hazard", kExampleHazardLine, 0, {}, /*commented_out=*/true);
  out += "\n  // Sensor options (manual 4): width=W,exp=E,pclass=P[,max=N]\n";
  for (const char* option : kExampleSensorConfigs) out += example_line("sensor_config", option, 0);
  return out;
}

std::string example_defaults_section() {
  const auto params = scalar_parameters();
  std::size_t width = 0, value_width = 0;
  for (const auto* p : params) {
    width = std::max(width, p->name.size());
    value_width = std::max(value_width, p->default_text.size());
  }
  std::string out = "\n  // Every other parameter at its default (manual 10; docs/uFldHazardSensor.md)\n";
  for (const hazard::ParameterSpec* p : params) {
    const std::string unit = p->unit.empty() ? "" : ", " + std::string(p->unit);
    if (p->default_text.empty()) {
      // No default (random_seed): shown commented out, with an example value.
      out += example_line(p->name, kExampleRandomSeed, width > 3 ? width - 3 : 0,
                          "uncomment to fix the dice seed", /*commented_out=*/true, value_width);
    } else {
      out += example_line(p->name, std::string(p->default_text), width, "default" + unit, false,
                          value_width);
    }
  }
  return out;
}

std::string interface_entry(std::string_view name, std::string_view example,
                            std::string_view meaning) {
  return "  " + std::string(name) + " = " + std::string(example) + "\n      " +
         std::string(meaning) + "\n";
}

std::string interface_section(const std::string& title,
                              const std::vector<hazard::InterfaceVariable>& engine_variables,
                              const std::vector<FrameworkVariable>& framework_variables) {
  std::string out = title + "\n" + std::string(kSectionRuleWidth, '-') + "\n";
  for (const auto& v : engine_variables) out += interface_entry(v.name, v.example, v.meaning);
  for (const auto& v : framework_variables) out += interface_entry(v.name, v.example, v.meaning);
  return out;
}

}  // namespace

std::string help_text() {
  std::string out = banner(std::string("Usage: ") + kAppName + " file.moos [OPTIONS]");
  out +=
      "\n"
      "Simulates a side-looking hazard sensor for the vehicles of a MOOS community\n"
      "(normally the shoreside one): detections and classifications of the objects\n"
      "of a hazard file, as the vehicles' node reports and requests ask for them.\n"
      "\n"
      "Options:\n";
  out += app_support::information_switches_help(kAppName);
  out +=
      "  --verbose=<setting>\n"
      "      Set verbosity. true or false (default)\n"
      "      (a bare --verbose means true). Verbose writes every\n"
      "      posting, event and warning to standard error as\n"
      "      .alog lines; the terminal report is unchanged.\n";
  out += app_support::generic_switches_help();
  out +=
      "Exit codes: 0 after SIGINT/SIGTERM or an information switch; 1 if the\n"
      "mission file cannot be read or the MOOSDB refuses the name; 2 for a bad\n"
      "--verbose value.\n";
  return out;
}

std::string example_text() {
  std::string out;
  for (const std::string& line : {rule(), std::string(kAppName) + " Example MOOS Configuration\n", rule()}) {
    out += "// " + line;
  }
  out += "\nProcessConfig = " + std::string(kAppName) + "\n{\n";
  out += example_framework_section();
  out += example_field_and_options_section();
  out += example_defaults_section();
  out += "}\n";
  return out;
}

const std::vector<FrameworkVariable>& framework_subscriptions() {
  static const std::vector<FrameworkVariable> v = {
      {"APPCAST_REQ", "node=shoreside,app=uFldHazardSensor,duration=3.0,key=uMAC_438,thresh=any",
       "a request for AppCast reports (uMAC, pMarineViewer)"},
  };
  return v;
}

const std::vector<FrameworkVariable>& framework_publications() {
  static const std::vector<FrameworkVariable> v = {
      {"APPCAST",
       "proc=uFldHazardSensor!@#iter=12!@#node=shoreside!@#iter=12!@#messages=...!@#...",
       "the AppCast report (the terminal report's content), while requested"},
      {"UFLDHAZARDSENSOR_STATUS",
       "AppErrorFlag=false,Uptime=12.3,MOOSName=uFldHazardSensor,Publishing=\"...\",Subscribing=\"...\"",
       "<APPNAME>_STATUS: the process status, every 2 s"},
      {"UFLDHAZARDSENSOR_ITER_GAP", "1.02",
       "<APPNAME>_ITER_GAP: time between iterations / (1/AppTick)"},
      {"UFLDHAZARDSENSOR_ITER_LEN", "0.01",
       "<APPNAME>_ITER_LEN: time spent iterating / (1/AppTick)"},
  };
  return v;
}

std::string interface_text() {
  std::string out = banner(std::string(kAppName) + " INTERFACE");
  out += "\n";
  out += interface_section("SUBSCRIPTIONS:", hazard::Engine::subscriptions(),
                           framework_subscriptions());
  out += "\n";
  out += interface_section("PUBLICATIONS:", hazard::Engine::publications(),
                           framework_publications());
  out +=
      "\n"
      "<V> is the vehicle name in upper case: vname=archie posts UHZ_DETECTION_REPORT_ARCHIE.\n"
      "<APPNAME> is the process name in upper case (the alias, if one is given).\n";
  return out;
}

std::string version_text() {
  return base::version_line(kAppName);
}

}  // namespace ufld_hazard_sensor
