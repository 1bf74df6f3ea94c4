#pragma once
// The texts of pHazardMgr's information switches (--help, --example, --interface, --version).
// --example is generated from the two parameter tables (the manager's,
// mission::manager_parameters(), and the application's, app_parameters()).

#include <string>

namespace phazard_mgr {

std::string help_text();
std::string example_text();
std::string interface_text();
std::string version_text();

}  // namespace phazard_mgr
