#pragma once
// hazard_replay's command line, read with libmoos's switch table (moos::parse_switches).
//
// Contract: `CONFIG.moos INPUT.alog` and the switches of switch_table(); --help or -h anywhere
// wins over every problem beside it (as in moosdb-lite, moos-cli and gen_hazards), then
// --version (-v, -version). Otherwise the
// first problem in argument order is the error, naming the argument: a refused value
// ("--seed needs a whole number in [0, 2^64): '--seed=x'"), an unknown switch or one without
// its value ("unknown option '--seed'"), then missing or extra files. `--NAME=value` with NAME
// starting with a capital letter is no switch: it gives `$(NAME)` in CONFIG.moos, as a MOOS
// app's command line does (missions/jake/jake.moos needs --PORT, --WARP, --SEED, --VIEW_PORT).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "moos/command_line.hpp"
#include "replay.hpp"

namespace hazard_replay {

/// The switches of hazard_replay.
const moos::SwitchTable& switch_table();

struct ParsedArgs {
  std::optional<Options> options;
  std::string error;  ///< names the offending argument
};

/// `A..B` (both whole numbers, A <= B, at most kMaxSeedsPerRun seeds), or nullopt.
std::optional<SeedRange> parse_seed_range(std::string_view text);

/// Arguments after the program name.
ParsedArgs parse_args(const std::vector<std::string>& args);

}  // namespace hazard_replay
