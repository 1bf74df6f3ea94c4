// pHazardMgr: the vehicle-side hazard manager as a MOOS application (issue 5; docs/missions.md).
// main reads the command line, prints an information text or runs the app until SIGINT or
// SIGTERM (exit codes: mission_app::run_main).

#include <memory>

#include "HazardMgr.hpp"
#include "HazardMgr_Info.hpp"
#include "mission_app.hpp"

int main(int argc, char** argv) {
  using namespace phazard_mgr;
  const mission_app::InfoTexts texts{help_text, example_text, interface_text, version_text};
  return mission_app::run_main(argc, argv, kAppName, texts,
                               [] { return std::make_unique<HazardMgr>(); });
}
