// uFldHazardSensor: the simulated hazard sensor as a MOOS application (manual;
// docs/uFldHazardSensor.md).
// main is moos::launch with the app's texts and its --verbose switch (launch.hpp): it prints an
// information text or runs the app until SIGINT or SIGTERM. Exit codes: see help_text() (0, 1
// from moos::run_app, moos::kExitUsageError).

#include <iostream>
#include <memory>

#include "HazardSensor.hpp"
#include "HazardSensor_Info.hpp"
#include "launch.hpp"

int main(int argc, char** argv) {
  using namespace ufld_hazard_sensor;
  bool verbose = false;
  moos::AppLaunch app;
  app.app_name = kAppName;
  app.texts = {help_text, example_text, interface_text, version_text};
  app.own_switches = verbose_switch(&verbose);
  // moos::run_app reads the mission file: the block, its folder and the origin globals reach the
  // app through its settings.
  app.make_app = [&verbose] {
    HazardSensorOptions options;
    if (verbose) options.verbose = &std::cerr;
    return std::make_unique<HazardSensor>(std::move(options));
  };
  return moos::launch(argc, argv, app);
}
