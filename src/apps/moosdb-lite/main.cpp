// moosdb-lite: a MOOSDB-compatible server. main reads the configuration (command line and
// mission globals, options.hpp), wires the Hub to the socket loop and the --log writer,
// and turns SIGINT/SIGTERM into a clean stop. Exit codes: 0 after a clean stop or
// --help/--version, 1 if the server cannot start (port, log file), 2 for a bad command
// line or configuration, 3 after a stop when the --log file is not whole (records were lost:
// a full disk, a stalled FIFO reader, a deleted file; alog_writer.hpp).

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

#include "MoosDBLite_Info.hpp"
#include "alog_writer.hpp"
#include "event_loop.hpp"
#include "hub.hpp"
#include "moos/clock.hpp"
#include "moos/mission.hpp"
#include "base/descriptors.hpp"
#include "base/diagnostics.hpp"
#include "base/text.hpp"
#include "options.hpp"

namespace {

using namespace moosdb_lite;

constexpr int kExitOk = 0;
constexpr int kExitCannotStart = 1;
constexpr int kExitBadConfiguration = 2;
constexpr int kExitLogNotWhole = 3;
/// Host name buffer (POSIX HOST_NAME_MAX is 255 on Linux).
constexpr std::size_t kHostNameBytes = 256;

volatile std::sig_atomic_t g_stop_requested = 0;
int g_wake_pipe[2] = {-1, -1};

// Async-signal-safe: sets a flag and wakes poll() through the pipe.
void request_stop(int) {
  g_stop_requested = 1;
  const char byte = 1;
  [[maybe_unused]] const auto ignored = ::write(g_wake_pipe[1], &byte, 1);
}

void log_line(const std::string& line) { std::fprintf(stderr, "moosdb-lite: %s\n", line.c_str()); }

bool install_signal_handlers() {
  if (!base::open_internal_pipe(g_wake_pipe)) return false;
  struct sigaction action {};
  action.sa_handler = request_stop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  std::signal(SIGPIPE, SIG_IGN);
  // A file size limit (ulimit -f) is then a write error the --log writer counts, like a full
  // disk, instead of the end of the server.
  std::signal(SIGXFSZ, SIG_IGN);
  return true;
}

std::string host_name() {
  char name[kHostNameBytes] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "localhost";
  return name;
}

bool file_exists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

// Loads the mission file named on the command line, or Mission.moos if it exists
// (docs/protocol.md 5.11). Returns false if a named file cannot be read. Parse problems are
// warnings.
bool load_mission(const CommandLine& cli, std::optional<moos::MissionFile>& mission) {
  std::string path;
  if (cli.mission_file) {
    path = *cli.mission_file;
  } else if (file_exists(kDefaultMissionFile)) {
    path = kDefaultMissionFile;
  } else {
    return true;
  }
  std::vector<moos::MissionError> problems;
  mission = moos::MissionFile::load(path, moos::MissionOptions{}, &problems);
  if (!mission) {
    log_line("cannot read mission file " + path);
    return false;
  }
  for (const auto& problem : problems) {
    // Other applications' blocks are theirs to check.
    if (problem.block.empty()) log_line("warning: " + problem.to_string());
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  const CommandLine cli = parse_command_line(args);
  if (cli.help) {
    std::fputs(help_text().c_str(), stdout);
    return kExitOk;
  }
  if (cli.version) {
    std::fputs(version_text().c_str(), stdout);
    return kExitOk;
  }
  // From here on, a standard error nobody reads must not stop the server.
  base::install_nonblocking_diagnostics();
  for (const auto& note : cli.notes) log_line("note: " + note);
  for (const auto& error : cli.errors) log_line("error: " + error);
  if (!cli.errors.empty()) return kExitBadConfiguration;

  std::optional<moos::MissionFile> mission;
  if (!load_mission(cli, mission)) return kExitBadConfiguration;
  MissionGlobalLookup lookup;
  if (mission) lookup = [&mission](std::string_view key) { return mission->global(key); };
  std::vector<std::string> errors;
  std::vector<std::string> notes;
  const ServerOptions options =
      resolve_options(cli, mission ? mission->path() : std::string(), lookup, &errors, &notes);
  for (const auto& note : notes) log_line("note: " + note);
  for (const auto& error : errors) log_line("error: " + error);
  if (!errors.empty()) return kExitBadConfiguration;

  if (!install_signal_handlers()) {
    log_line("cannot create the signal pipe");
    return kExitCannotStart;
  }

  HubConfig config;
  config.database.community = options.community;
  config.database.hostname = host_name();
  config.database.max_pending_bytes = options.max_output_bytes;
  config.database.max_stored_bytes = options.max_stored_bytes;
  config.time_warp = options.time_warp;
  config.banner_timeout_s = options.banner_timeout_s;
  config.handshake_timeout_s = options.handshake_timeout_s;
  config.client_timeout_s = options.client_timeout_s;
  config.max_packet_bytes = options.max_packet_bytes;

  const double start_real_s = moos::system_clock().unix_now_s();
  AlogWriter alog;
  if (options.log_file) {
    std::string error;
    const double warp = options.time_warp;
    const auto moos_now = [warp] { return moos::system_clock().unix_now_s() * warp; };
    if (!alog.open(*options.log_file, start_real_s * warp, log_line, &error, moos_now)) {
      log_line("error: " + error);
      return kExitCannotStart;
    }
  }
  moos::Database::NotifyObserver observer;
  if (alog.is_open()) observer = [&alog](const moos::Message& msg) { alog.write(msg); };
  Hub hub(config, start_real_s, log_line, observer);

  EventLoopConfig loop_config;
  loop_config.bind_address = options.bind_address;
  loop_config.port = options.port;
  loop_config.port_file = options.port_file;
  loop_config.max_output_bytes = options.max_output_bytes;
  loop_config.memory_budget_bytes = options.memory_budget_bytes;
  EventLoop loop(loop_config, hub, log_line);
  std::string error;
  if (!loop.listen(&error)) {
    log_line("error: " + error);
    return kExitCannotStart;
  }
  log_line("community \"" + options.community + "\" listening on " + options.bind_address + ":" +
           std::to_string(loop.bound_port()) + ", time warp " + base::format_g(options.time_warp) +
           (options.mission_file ? ", mission " + *options.mission_file : std::string()));

  loop.run(g_wake_pipe[0], g_stop_requested, [&alog] { alog.flush(); });
  const bool log_whole = alog.close();
  log_line("stopped");
  return log_whole ? kExitOk : kExitLogNotWhole;
}
