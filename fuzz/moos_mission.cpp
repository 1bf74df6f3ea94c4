// Fuzz target: the .moos mission reader with its substitutions ($(NAME) from the command line,
// ${NAME} from `define:` lines), then every lookup a program makes on the result.
// The environment is not consulted (the run must not depend on it); the file is named inside a
// folder that does not exist, so a relative `#include` is an unreadable-file error.

#include <vector>

#include "fuzz_input.hpp"
#include "moos/mission.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  moos::MissionOptions options;
  options.substitutions = {{"WARP", "10"}, {"VNAME", "archie"}, {"EMPTY", ""}};
  options.use_environment = false;
  std::vector<moos::MissionError> errors;
  const moos::MissionFile mission = moos::MissionFile::parse(
      fuzz::as_text(data, size), "/nonexistent-fuzz-folder/fuzz.moos", options, &errors);
  for (const auto& e : errors) (void)e.to_string();
  (void)mission.global_double("MOOSTimeWarp");
  (void)mission.global("ServerHost");
  (void)mission.global_line("LatOrigin");
  for (const auto& block : mission.blocks()) (void)mission.block(block.app_name);
  (void)mission.directory();
  return 0;
}
