// hazard_study: whole missions in lockstep, over seeds and settings (docs/study.md).
#include <iostream>

#include "HazardStudy_Info.hpp"
#include "base/diagnostics.hpp"
#include "base/version.hpp"
#include "study.hpp"
#include "study_args.hpp"

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  base::install_nonblocking_diagnostics();
  const std::vector<std::string> args(argv + 1, argv + argc);
  const hazard_study::ParsedArgs parsed = hazard_study::parse_args(args);
  if (!parsed.options) {
    std::cerr << "hazard_study: " << parsed.error << "\n" << hazard_study::usage_line() << "\n";
    return 2;
  }
  if (parsed.options->help) {
    std::cout << hazard_study::help_text();
    return 0;
  }
  if (parsed.options->version) {
    std::cout << base::version_line("hazard_study");
    return 0;
  }
  return hazard_study::run(*parsed.options, std::cout, std::cerr);
}
