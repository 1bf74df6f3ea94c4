#pragma once
// The texts of uFldHazardSensor's information switches (manual 10.1, 11, listing
// 11.4; docs/uFldHazardSensor.md):
// --help, --example, --interface and --version. Each function returns the text; main decides
// what to print and the exit code (style.md: Info functions produce text, they never exit).
//
// --example is generated from the one parameter table (hazard::parameter_table()): every
// parameter of the sensor at its table default, plus example values for the repeatable
// parameters, framed as MOOS comments so that the whole output is a valid mission-file fragment
// that loads with no configuration warning (given a `hazards.txt` beside it).
// --interface lists Engine::subscriptions() and Engine::publications() (the engine's own
// variables with example payloads) plus the variables of the MOOS application framework.

#include <string>
#include <string_view>
#include <vector>

namespace ufld_hazard_sensor {

/// The process name without an alias (manual 11.4).
inline constexpr const char* kAppName = "uFldHazardSensor";

std::string help_text();
std::string example_text();
std::string interface_text();
/// One line: "uFldHazardSensor <release> (HazardSensor)".
std::string version_text();

/// A variable of the MOOS application framework that the app subscribes or publishes besides
/// the engine's (for --interface and the docs).
struct FrameworkVariable {
  std::string name;
  std::string example;
  std::string meaning;
};
const std::vector<FrameworkVariable>& framework_subscriptions();
const std::vector<FrameworkVariable>& framework_publications();

}  // namespace ufld_hazard_sensor
