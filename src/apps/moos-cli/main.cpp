// moos-cli: poke and watch a MOOS community from the command line. main decides what to print
// and which exit code to return; the text lives in MoosCli_Info, the work in moos_cli.
#include <iostream>
#include <string>
#include <vector>

#include "MoosCli_Info.hpp"
#include "base/diagnostics.hpp"
#include "base/version.hpp"
#include "moos_cli.hpp"

int main(int argc, char** argv) {
  base::install_nonblocking_diagnostics();
  const std::vector<std::string> args(argv + 1, argv + argc);
  std::string error;
  const auto options = moos_cli::parse_options(args, &error);
  if (!options) {
    std::cerr << "moos-cli: " << error << "\n\n" << moos_cli::help_text();
    return moos_cli::kExitUsage;
  }
  switch (options->command) {
    case moos_cli::Command::kHelp:
      std::cout << moos_cli::help_text();
      return moos_cli::kExitOk;
    case moos_cli::Command::kVersion:
      std::cout << base::version_line("moos-cli");
      return moos_cli::kExitOk;
    case moos_cli::Command::kPoke:
      return moos_cli::run_poke(*options, std::cout, std::cerr);
    case moos_cli::Command::kWatch:
      return moos_cli::run_watch(*options, std::cout, std::cerr);
  }
  return moos_cli::kExitUsage;
}
