#pragma once
// Help text of hazard_replay (the MOOS-IvP *_Info habit: text here, main decides what to print).

#include <string>

namespace hazard_replay {

/// The --help text.
std::string help_text();
/// One line: how to call the program (printed after a usage error).
std::string usage_line();

}  // namespace hazard_replay
