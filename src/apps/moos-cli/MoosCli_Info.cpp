#include "MoosCli_Info.hpp"

namespace moos_cli {

std::string help_text() {
  return R"(Usage:
  moos-cli poke  [OPTIONS] VAR=value ...
  moos-cli watch [OPTIONS] VAR|PATTERN ...
  moos-cli --help
  moos-cli --version

A small MOOS client for machines without MOOS. It connects to a MOOSDB (or moosdb-lite) as an
asynchronous client.

poke: posts each VAR=value in order, then exits once everything is written.
  A value that is a decimal number is posted as a double, anything else as a string.
  "VAR=\"12\"" (quotes kept by the shell) or VAR:=12 posts the string 12 (as uPokeDB).
  --string          post every value as a string

watch: registers for each VAR (a pattern with * or ? subscribes by wildcard, any app) and
  prints every message received as an .alog line:
    TIME VARIABLE SOURCE VALUE
  TIME is MOOS seconds since the watch started (3 decimals). Doubles are printed in their
  shortest exact form, strings as they are (a newline becomes a blank), binary values as
  <binary:N:HEX> (N bytes in lower-case hex), unset values (~) as <not set>.
  --count=N         exit 0 after N messages
  --timeout=S       give up after S real seconds: exit 2 if --count was not reached
                    (without --count, reaching the timeout is the normal end: exit 0)

Options for both:
  --host=H          server host (default localhost; IPv4)
  --port=P          server port (default 9000)
  --name=NAME       client name (default moos-cli-<pid>; it must be unique in the community)
  --connect-timeout=S
                    real seconds to wait for the connection (default 5)
  --moos_time_warp=W
                    time warp for time stamps (default 1)

Exit codes: 0 success; 1 bad usage; 2 watch timed out before --count messages;
            3 could not connect in time; 4 the server refused the name; 5 poke could not
            write everything before the connection was lost or timed out.
)";
}

}  // namespace moos_cli
