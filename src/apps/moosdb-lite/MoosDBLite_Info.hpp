#pragma once
// Help and version text of moosdb-lite. The text is produced here; main decides what to
// print and the exit code (style.md: Info functions produce text).

#include <string>

namespace moosdb_lite {

/// Full --help text, generated from the option table in options.cpp.
std::string help_text();
/// base::version_line("moosdb-lite").
std::string version_text();

}  // namespace moosdb_lite
