// pWebViewer: a live and replayable mission view in a browser (docs/viewer.md). main
// reads the command line: --replay / --export run without a MOOSDB (offline.hpp); otherwise it
// prints an information text or runs the app until SIGINT or SIGTERM (moos::launch).

#include <iostream>
#include <memory>

#include "WebViewer.hpp"
#include "WebViewer_Info.hpp"
#include "base/diagnostics.hpp"
#include "moos/launch.hpp"
#include "offline.hpp"

int main(int argc, char** argv) {
  using namespace web_viewer;
  const moos::CommandLine command_line = moos::parse_command_line(argc, argv);
  if (!moos::first_information_switch(command_line) && is_offline(command_line)) {
    base::install_nonblocking_diagnostics();
    return run_offline(command_line, std::cout, std::cerr);
  }
  moos::AppLaunch app;
  app.app_name = kAppName;
  app.texts = {help_text, example_text, interface_text, version_text};
  app.make_app = [] { return std::make_unique<WebViewer>(); };
  return moos::launch(argc, argv, app);
}
