// uFldHazardMetric: the shoreside grader as a MOOS application (docs/mission-logic.md,
// docs/missions.md).
// main reads the command line, prints an information text or runs the app until SIGINT or
// SIGTERM (exit codes: moos::launch).

#include <memory>

#include "HazardMetric.hpp"
#include "HazardMetric_Info.hpp"
#include "moos/launch.hpp"

int main(int argc, char** argv) {
  using namespace ufld_hazard_metric;
  moos::AppLaunch app;
  app.app_name = kAppName;
  app.texts = {help_text, example_text, interface_text, version_text};
  app.make_app = [] { return std::make_unique<HazardMetricApp>(); };
  return moos::launch(argc, argv, app);
}
