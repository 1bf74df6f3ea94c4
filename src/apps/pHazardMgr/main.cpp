// pHazardMgr: the vehicle-side hazard manager as a MOOS application (docs/missions.md).
// main reads the command line, prints an information text or runs the app until SIGINT or
// SIGTERM (exit codes: moos::launch).

#include <memory>

#include "HazardMgr.hpp"
#include "HazardMgr_Info.hpp"
#include "moos/launch.hpp"

int main(int argc, char** argv) {
  using namespace phazard_mgr;
  moos::AppLaunch app;
  app.app_name = kAppName;
  app.texts = {help_text, example_text, interface_text, version_text};
  app.make_app = [] { return std::make_unique<HazardMgr>(); };
  return moos::launch(argc, argv, app);
}
