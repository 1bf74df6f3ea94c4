// uSimSurveyVehicle: a simulated survey vehicle as a MOOS application (issue 5; docs/missions.md).
// main reads the command line, prints an information text or runs the app until SIGINT or
// SIGTERM (exit codes: mission_app::run_main).

#include <memory>

#include "SimSurveyVehicle.hpp"
#include "SimSurveyVehicle_Info.hpp"
#include "mission_app.hpp"

int main(int argc, char** argv) {
  using namespace usim_survey_vehicle;
  const mission_app::InfoTexts texts{help_text, example_text, interface_text, version_text};
  return mission_app::run_main(argc, argv, kAppName, texts,
                               [] { return std::make_unique<SimSurveyVehicle>(); });
}
