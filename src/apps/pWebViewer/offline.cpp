#include "offline.hpp"

#include <csignal>
#include <iostream>

#include "WebViewer.hpp"
#include "base/output_file.hpp"
#include "export_html.hpp"
#include "replay_log.hpp"
#include "web_files.hpp"

namespace web_viewer {

namespace {

/// The value of `--name=value` (libmoos reads every such switch as a `$(name)` substitution).
std::optional<std::string> switch_value(const moos::CommandLine& command_line, const std::string& name) {
  const auto it = command_line.substitutions.find(name);
  if (it == command_line.substitutions.end()) return std::nullopt;
  return it->second;
}

struct OfflineSetup {
  ViewerConfig config;
  Hello hello;
};

/// The block of the mission file (when one is given) and the hello of a replay.
std::optional<OfflineSetup> setup(const moos::CommandLine& cl, std::ostream& err) {
  OfflineSetup s;
  const auto for_replay = [&s] {
    s.hello = configured_hello(s.config);
    s.hello.buttons.clear();  // no MOOSDB to post to
    s.hello.replay = true;
    s.hello.community = "replay";
  };
  for_replay();
  if (!cl.mission_file) return s;
  std::vector<moos::MissionError> errors;
  const auto mission = moos::MissionFile::load(*cl.mission_file, {cl.substitutions, true}, &errors);
  if (!mission) {
    err << kAppName << ": cannot read the mission file " << *cl.mission_file << "\n";
    return std::nullopt;
  }
  const moos::AppSettings settings = moos::resolve_app_settings(viewer_traits(), cl, &*mission, errors);
  std::vector<std::string> warnings = settings.config_warnings;
  s.config = read_viewer_config(settings.config_lines, &warnings);
  for (const std::string& w : warnings) err << kAppName << ": warning: " << w << "\n";
  for_replay();
  if (!settings.community.empty()) s.hello.community = settings.community;
  set_datum(settings, s.hello);
  return s;
}

std::optional<ReplayLog> read_log(const std::string& path, const OfflineSetup& s, std::ostream& err) {
  std::string error;
  auto log = read_replay_log(path, s.config.watch, ReplayLimits{}, &error);
  if (!log) err << kAppName << ": " << error << "\n";
  if (log) for (const std::string& w : log->warnings) err << kAppName << ": warning: " << w << "\n";
  return log;
}

int export_file(const std::string& log_path, const std::string& output, OfflineSetup& s,
                std::ostream& out, std::ostream& err) {
  const auto log = read_log(log_path, s, err);
  if (!log) return 1;
  if (!log->mail.empty()) s.hello.time_s = log->mail.front().time_s;
  std::string error;
  const auto html = export_html(web_files(), replay_json(s.hello, log->mail), &error);
  if (!html) {
    err << kAppName << ": " << error << "\n";
    return 1;
  }
  // The rule of every user-named output: a regular file replaced atomically, a device or FIFO
  // written through, a link followed (base/output_file.hpp).
  if (const auto written = base::write_output_file(output, *html); !written) {
    err << kAppName << ": --output: " << written.error << "\n";
    return 1;
  }
  out << kAppName << ": wrote " << output << " (" << log->mail.size() << " postings of "
      << log_path << ")" << std::endl;
  return 0;
}

int serve_replay(const std::string& log_path, OfflineSetup& s, std::ostream& out, std::ostream& err) {
  const auto log = read_log(log_path, s, err);
  if (!log) return 1;
  if (!log->mail.empty()) s.hello.time_s = log->mail.front().time_s;
  // Block the stop signals before any thread starts, so that only sigwait below receives them.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  const std::string hello = hello_json(s.hello);
  LiveFeed feed(s.config.limits, [hello] { return hello; });
  HttpServer server(feed.hub(), [](int) { return false; });  // no MOOSDB: no buttons
  server.set_replay_json(replay_json(s.hello, log->mail));
  std::string error;
  if (!server.start(s.config.http, &error)) {
    err << kAppName << ": " << error << "\n";
    return 1;
  }
  // The token as in a live run, so that the printed URL is the same kind (a replay has no buttons).
  out << kAppName << ": serving " << server_url(s.config.http.bind_address, server.port())
      << "?token=" << server.token() << " (replay of " << log_path << ", " << log->mail.size() << " postings)" << std::endl;
  int signal = 0;
  sigwait(&stop_signals, &signal);
  server.stop();
  return 0;
}

}  // namespace

bool is_offline(const moos::CommandLine& command_line) {
  return switch_value(command_line, "replay") || switch_value(command_line, "export");
}

int run_offline(const moos::CommandLine& cl, std::ostream& out, std::ostream& err) {
  const auto replay = switch_value(cl, "replay");
  const auto exported = switch_value(cl, "export");
  const auto output = switch_value(cl, "output");
  if (replay && exported) {
    err << kAppName << ": --replay and --export cannot be combined\n";
    return 2;
  }
  if (exported && (!output || output->empty())) {
    err << kAppName << ": --export needs --output=FILE.html\n";
    return 2;
  }
  auto s = setup(cl, err);
  if (!s) return 1;
  return exported ? export_file(*exported, *output, *s, out, err) : serve_replay(*replay, *s, out, err);
}

}  // namespace web_viewer
