#pragma once
// Writing the field to --output=FILE so that FILE appears complete or not at all.
//
// Contract: the text goes to a new temporary file in FILE's folder (same file system, so the
// rename is atomic), is flushed to disk, and is then renamed over FILE. On any failure the
// temporary file is removed and FILE is left as it was (absent, or its old content). The new
// file gets the usual permissions (0666 minus the umask).

#include <optional>
#include <string>

namespace gen_hazards {

/// Returns nullopt on success, else a message that names `path` and the system's reason.
std::optional<std::string> write_file_atomically(const std::string& path, const std::string& text);

}  // namespace gen_hazards
