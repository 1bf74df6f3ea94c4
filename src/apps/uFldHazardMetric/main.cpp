// uFldHazardMetric: the shoreside grader as a MOOS application (issue 5; spec 14; docs/missions.md).
// main reads the command line, prints an information text or runs the app until SIGINT or
// SIGTERM (exit codes: mission_app::run_main).

#include <memory>

#include "HazardMetric.hpp"
#include "HazardMetric_Info.hpp"
#include "mission_app.hpp"

int main(int argc, char** argv) {
  using namespace ufld_hazard_metric;
  const mission_app::InfoTexts texts{help_text, example_text, interface_text, version_text};
  return mission_app::run_main(argc, argv, kAppName, texts,
                               [] { return std::make_unique<HazardMetricApp>(); });
}
