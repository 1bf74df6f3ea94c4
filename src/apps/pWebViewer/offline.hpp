#pragma once
// pWebViewer without a MOOSDB (docs/viewer.md, "Replay"):
//   pWebViewer [mission.moos] --replay=FILE.alog
//       serves the page driven by the log (GET /replay.json) until SIGINT or SIGTERM, printing
//       `pWebViewer: serving http://HOST:PORT/?token=TOKEN (replay of ...)`;
//   pWebViewer [mission.moos] --export=FILE.alog --output=FILE.html
//       writes the page and the log's watched mail as one self-contained HTML file and exits.
// The mission file is optional: its pWebViewer block (http_port, http_bind, watch, ...) and its
// LatOrigin/LongOrigin apply as in a live run; without it, the defaults.
// Exit codes: 0 done (replay: after a signal); 1 the log or the mission cannot be read, a
// bound is exceeded, the output cannot be written, or the address cannot be bound; 2 a bad
// command line (--export without --output, --replay with --export).

#include <iosfwd>

#include "moos/command_line.hpp"

namespace web_viewer {

/// True when the command line asks for --replay or --export.
bool is_offline(const moos::CommandLine& command_line);

int run_offline(const moos::CommandLine& command_line, std::ostream& out, std::ostream& err);

}  // namespace web_viewer
