// Fuzz target: the command lines: the generic MOOS parser every program uses
// (src/moos/command_line.cpp) and what main does with it, moosdb-lite's own parser, and
// hazard_replay's. The input is the argument list, one argument per NUL-separated field.

#include <string>
#include <vector>

#include "fuzz_input.hpp"
#include "moos/command_line.hpp"
#include "moos/launch.hpp"
#include "args.hpp"
#include "options.hpp"
#include "replay.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args = fuzz::arguments_of(fuzz::as_text(data, size));
  std::vector<std::string> argv = {"uFldHazardSensor"};
  argv.insert(argv.end(), args.begin(), args.end());

  const moos::CommandLine generic = moos::parse_command_line(argv);
  (void)moos::app_name_from(generic, "uFldHazardSensor");
  (void)moos::decide_launch(generic, {});
  (void)moos::first_information_switch(generic);

  const moosdb_lite::CommandLine server = moosdb_lite::parse_command_line(args);
  std::vector<std::string> errors, notes;
  (void)moosdb_lite::resolve_options(server, "fuzz.moos", {}, &errors, &notes);
  (void)hazard_replay::parse_args(args);
  return 0;
}
