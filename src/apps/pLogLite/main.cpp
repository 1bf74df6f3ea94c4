// pLogLite: a logger writing pLogger's .alog format (issue 5; docs/missions.md). main reads the
// command line, prints an information text or runs the app until SIGINT or SIGTERM (exit codes:
// mission_app::run_main).

#include <memory>

#include "LogLite.hpp"
#include "LogLite_Info.hpp"
#include "mission_app.hpp"

int main(int argc, char** argv) {
  using namespace plog_lite;
  const mission_app::InfoTexts texts{help_text, example_text, interface_text, version_text};
  return mission_app::run_main(argc, argv, kAppName, texts,
                               [] { return std::make_unique<LogLite>(); });
}
