#pragma once
// Help and version text of gen_hazards. The text is produced here from the option table
// (options.hpp); main decides what to print and the exit code (style.md: Info functions
// produce text).

#include <string>

namespace gen_hazards {

/// Full --help text: usage, what is written, every option with its default and range (from
/// option_docs()), an example and the exit codes.
std::string help_text();

/// One line: "gen_hazards <release> (HazardSensor)".
std::string version_text();

}  // namespace gen_hazards
