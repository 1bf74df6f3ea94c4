#pragma once
// The texts of uSimSurveyVehicle's information switches (--help, --example, --interface,
// --version). --example is generated from the two parameter tables (the vehicle's,
// mission::survey_vehicle_parameters(), and the application's, app_parameters()), so it cannot
// disagree with what the application accepts. Each function returns text; main prints it.

#include <string>

namespace usim_survey_vehicle {

std::string help_text();
std::string example_text();
std::string interface_text();
std::string version_text();

}  // namespace usim_survey_vehicle
