#pragma once
// moos-cli's option parsing and its two commands, poke and watch. The options are documented in
// MoosCli_Info.cpp and are a stable interface.

#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "moos/command_line.hpp"
#include "moos/message.hpp"

namespace moos_cli {

enum ExitCode {
  kExitOk = 0,
  kExitUsage = 1,
  kExitWatchTimeout = 2,
  kExitNoConnection = 3,
  kExitRefused = 4,
  kExitNotWritten = 5,
};

enum class Command { kHelp, kVersion, kPoke, kWatch };

struct Options {
  Command command = Command::kHelp;
  std::string host = "localhost";
  int port = 9000;
  std::string name;                   ///< "" = moos-cli-<pid>
  double connect_timeout_s = 5.0;     ///< real seconds
  double time_warp = 1.0;
  bool all_strings = false;           ///< poke --string
  std::optional<long long> count;     ///< watch --count
  std::optional<double> timeout_s;    ///< watch --timeout, real seconds
  std::vector<std::string> arguments; ///< poke: VAR=value; watch: VAR or PATTERN
};

/// The switches of a command (kPoke or kWatch), read with libmoos's moos::parse_switches.
const moos::SwitchTable& switch_table(Command command);

/// Parses the arguments after argv[0]: the command, then its switches and arguments. --help
/// anywhere wins over every problem; else the first problem (in argument order) is the usage
/// error, set in `error` with nullopt returned.
std::optional<Options> parse_options(const std::vector<std::string>& args, std::string* error);

/// One poke: `VAR=value` (a decimal number becomes a double unless `all_strings`),
/// `VAR="value"` or `VAR:=value` (always a string).
struct Poke {
  std::string var;
  bool is_double = false;
  double dval = 0.0;
  std::string sval;
};
std::optional<Poke> parse_poke(std::string_view assignment, bool all_strings, std::string* error);

/// One .alog line (newline-terminated) for a received message; time relative to `start_moos_s`.
/// A message time that is not finite or beyond a log reader's ±1e10 s of `now_moos_s`
/// (moos-cli's clock) is printed as `now_moos_s` (moos/alog_file.hpp), so the line stays one a
/// reader can place.
std::string format_watch_line(const moos::Message& m, double start_moos_s, double now_moos_s);

int run_poke(const Options& options, std::ostream& out, std::ostream& err);
int run_watch(const Options& options, std::ostream& out, std::ostream& err);

}  // namespace moos_cli
