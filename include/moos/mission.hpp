#pragma once
// The .moos mission file: globals, ProcessConfig blocks, comments, and the nsplug habits that
// mission folders rely on (`#include FILE`, `$(NAME)` substitution).
// Behaviour: docs/protocol.md section 6, with these deliberate choices:
// - Block parameters keep the libMOOS split (key = text before the first '=', both sides
//   trimmed, interior spaces kept) and are returned in FILE ORDER with their file and line,
//   so each application applies its own rules (uFldHazardSensor: differences.md D36).
// - Globals follow libMOOS: the first line anywhere whose key matches case-insensitively wins,
//   with every blank removed from the value.
// - `$(NAME)` comes from the substitutions given (e.g. `--NAME=value` on the command line),
//   then the environment; a missing name is an error naming it, its file and line.
//   `${NAME}` follows libMOOS (`define:` lines, then the environment).
// - `#include FILE` (path relative to the including file) inserts that file's lines; errors
//   inside it name the included file and its line. Include cycles are errors.
// - The whole expansion is bounded, not only its depth: at most `max_included_files` files read
//   through `#include`, `max_expanded_lines` lines and `max_expanded_bytes` bytes in all (a
//   file that includes the next twice, 30 deep, would otherwise expand to billions of lines).
//   Past a bound, one error names it and the line where it was reached, and the rest of the
//   expansion is skipped.
// - Every problem is reported as a MissionError; parsing never throws and never stops early.
// - `ProcessConfig = X {` (brace on the header line) is NOT a block, as in libMOOS (a mission
//   that worked with us must work with the real MOOS): it is reported as an error naming the
//   line, so the user learns why the block is "missing".
// - Comments (`//`) are removed before any substitution, so a `$(NAME)` inside a comment is
//   never an error. Verbatim quoting follows libMOOS: the first pair of double quotes on a line
//   is removed and protects a `//` inside it.
// - nsplug's other directives (`#define`, `#ifdef`, ...) are reported as unsupported errors and
//   the line is skipped; a line with no `=` is reported and skipped (libMOOS skips it silently).
// - A UTF-8 byte-order mark at the start of a file and CR line ends (CRLF files) are accepted.

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace moos {

/// One `key = value` line of a ProcessConfig block, as written (after substitution).
struct ConfigLine {
  std::string key;    ///< trimmed, case preserved
  std::string value;  ///< trimmed, interior blanks kept, `//` comment removed
  std::string file;   ///< the file that holds the line (an included file names itself)
  int line = 0;       ///< 1-based line number in `file`
};

struct ProcessBlock {
  std::string app_name;          ///< as written after `ProcessConfig =`
  std::vector<ConfigLine> lines; ///< in file order
  std::string file;
  int line = 0;                  ///< line of the `ProcessConfig` header
};

struct MissionError {
  std::string file;
  int line = 0;  ///< 0 when the problem concerns the whole file
  std::string message;
  /// The ProcessConfig block the line belongs to ("" outside blocks), so a program can ignore
  /// problems in other applications' blocks.
  std::string block;
  /// "file:line: message" (or "file: message").
  std::string to_string() const;
  /// True for a problem outside any block or in `app_name`'s block (case-insensitive): the
  /// problems that program must report.
  bool concerns(std::string_view app_name) const;
};

struct MissionOptions {
  /// Values for `$(NAME)`, e.g. from `--NAME=value` command-line arguments.
  std::map<std::string, std::string> substitutions;
  /// Also look `$(NAME)` and `${NAME}` up in the process environment.
  bool use_environment = true;
  /// Bounds of the whole expansion (see the contract); the defaults are far above any mission.
  std::size_t max_included_files = 10000;
  std::size_t max_expanded_lines = 2000000;
  std::size_t max_expanded_bytes = std::size_t{512} * 1024 * 1024;
};

class MissionFile {
 public:
  /// Reads and parses a mission file. Returns nullopt only if the file itself cannot be read;
  /// every other problem is appended to `errors` and parsing continues.
  static std::optional<MissionFile> load(const std::string& path, const MissionOptions& options,
                                         std::vector<MissionError>* errors);
  /// Parses mission text; `file_name` names it in errors and anchors relative `#include`s.
  static MissionFile parse(std::string_view text, const std::string& file_name,
                           const MissionOptions& options, std::vector<MissionError>* errors);

  /// A global parameter (case-insensitive key, first occurrence, all blanks removed).
  std::optional<std::string> global(std::string_view key) const;
  /// A numeric global, or nullopt if absent or not a number.
  std::optional<double> global_double(std::string_view key) const;
  /// The line that global(key) reads (its value trimmed, interior blanks kept), to name the
  /// place in a warning; nullptr if absent.
  const ConfigLine* global_line(std::string_view key) const;

  /// The first `ProcessConfig = <app_name>` block (name compared case-insensitively).
  const ProcessBlock* block(std::string_view app_name) const;
  const std::vector<ProcessBlock>& blocks() const { return blocks_; }

  /// The mission file's path as given, and the folder that relative paths inside it
  /// (hazard_file, #include) are resolved against.
  const std::string& path() const { return path_; }
  std::string directory() const;

 private:
  std::string path_;
  std::vector<ConfigLine> globals_;  ///< every `key = value` line in file order, blocks included
  std::vector<ProcessBlock> blocks_;
};

}  // namespace moos
