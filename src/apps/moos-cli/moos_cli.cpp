// moos-cli commands. poke: connect, post, flush, close. watch: connect, register, print each
// message as an .alog line until --count messages or --timeout seconds.

#include "moos_cli.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <ostream>

#include "moos/alog.hpp"
#include "moos/alog_file.hpp"
#include "moos/limits.hpp"
#include "moos/mail_signal.hpp"
#include "moos/tcp_client.hpp"
#include "base/text.hpp"
#include "moos/wildcard.hpp"

namespace moos_cli {

namespace {

/// How long poke waits for its posts to reach the socket, real seconds.
constexpr double kFlushTimeout_s = 10.0;
/// --count: messages, at least 1.
constexpr moos::Range kCountRange{1, static_cast<double>(std::numeric_limits<long long>::max())};

using base::parse_number;

std::string default_name() { return "moos-cli-" + std::to_string(::getpid()); }

moos::TcpClientOptions client_options(const Options& o) {
  moos::TcpClientOptions c;
  c.host = o.host;
  c.port = o.port;
  c.name = o.name.empty() ? default_name() : o.name;
  c.time_warp = o.time_warp;
  return c;
}

/// Connects; on failure prints why and returns the exit code to use.
std::optional<int> connect(moos::TcpClient& client, const Options& o, std::ostream& err) {
  if (!client.start()) {
    err << "moos-cli: " << client.last_error() << "\n";
    return kExitUsage;
  }
  if (client.wait_until_connected(o.connect_timeout_s)) return std::nullopt;
  if (client.state() == moos::ConnectionState::kPoisoned) {
    err << "moos-cli: " << client.last_error() << "\n";
    return kExitRefused;
  }
  err << "moos-cli: no connection to " << o.host << ":" << o.port << " within "
      << o.connect_timeout_s << " s (" << client.last_error() << ")\n";
  return kExitNoConnection;
}

}  // namespace

const moos::SwitchTable& switch_table(Command command) {
  using moos::SwitchKind;
  using moos::switch_rule;
  auto make = [](Command c) {
    const std::string command_name = c == Command::kPoke ? "poke" : "watch";
    moos::SwitchTable t;
    t.rules = {switch_rule("--host", SwitchKind::kText, "host"),
               switch_rule("--port", SwitchKind::kInteger, "port", moos::kConnectPortRange),
               switch_rule("--name", SwitchKind::kText, "name"),
               switch_rule("--connect-timeout", SwitchKind::kNumber, "timeout",
                           moos::kRealWaitRange),
               switch_rule("--moos_time_warp", SwitchKind::kNumber, "time warp",
                           moos::kTimeWarpRange),
               moos::help_switch_rule()};
    if (c == Command::kPoke) {
      t.rules.push_back(switch_rule("--string", SwitchKind::kFlag, ""));
    } else {
      t.rules.push_back(switch_rule("--count", SwitchKind::kInteger, "count", kCountRange));
      t.rules.push_back(
          switch_rule("--timeout", SwitchKind::kNumber, "timeout", moos::kRealWaitRange));
    }
    // "--host= needs a host" for an empty text, "bad port: --port=0" for a refused number.
    t.bad_value = [](const std::string& arg, const moos::SwitchRule& r) {
      return r.kind == SwitchKind::kText ? arg + " needs a " + r.problem
                                         : "bad " + r.problem + ": " + arg;
    };
    t.unknown = [command_name](const std::string& arg) {
      return "unknown option for " + command_name + ": " + arg;
    };
    return t;
  };
  static const moos::SwitchTable poke = make(Command::kPoke);
  static const moos::SwitchTable watch = make(Command::kWatch);
  return command == Command::kWatch ? watch : poke;
}

std::optional<Options> parse_options(const std::vector<std::string>& args, std::string* error) {
  Options o;
  auto fail = [&](const std::string& why) -> std::optional<Options> {
    *error = why;
    return std::nullopt;
  };
  if (args.empty()) return fail("no command given");
  const std::string& command = args[0];
  if (command == "--help" || command == "-h" || command == "help") return o;
  if (command == "--version" || command == "-v" || command == "-version") {
    o.command = Command::kVersion;
    return o;
  }
  if (command == "poke") o.command = Command::kPoke;
  else if (command == "watch") o.command = Command::kWatch;
  else return fail("unknown command: " + command);

  const moos::SwitchValues v =
      moos::parse_switches({args.begin() + 1, args.end()}, switch_table(o.command));
  if (v.has("--help")) {  // the help wins over every problem beside it
    o.command = Command::kHelp;
    return o;
  }
  if (!v.errors.empty()) return fail(v.errors.front());
  o.host = v.text("--host").value_or(o.host);
  o.port = static_cast<int>(v.integer("--port").value_or(o.port));
  o.name = v.text("--name").value_or(o.name);
  o.connect_timeout_s = v.number("--connect-timeout").value_or(o.connect_timeout_s);
  o.time_warp = v.number("--moos_time_warp").value_or(o.time_warp);
  o.all_strings = v.has("--string");
  o.count = v.integer("--count");
  o.timeout_s = v.number("--timeout");
  o.arguments = v.free;
  if (o.arguments.empty())
    return fail(o.command == Command::kPoke ? "poke needs at least one VAR=value"
                                            : "watch needs at least one variable or pattern");
  return o;
}

std::optional<Poke> parse_poke(std::string_view assignment, bool all_strings, std::string* error) {
  const auto eq = assignment.find('=');
  if (eq == std::string_view::npos || eq == 0) {
    *error = "not a VAR=value assignment: " + std::string(assignment);
    return std::nullopt;
  }
  Poke p;
  bool force_string = all_strings;
  std::string_view var = assignment.substr(0, eq);
  if (var.back() == ':') {  // uPokeDB's VAR:=value
    var.remove_suffix(1);
    force_string = true;
  }
  if (var.empty()) {
    *error = "no variable name in: " + std::string(assignment);
    return std::nullopt;
  }
  p.var = std::string(var);
  std::string_view value = assignment.substr(eq + 1);
  if (value.size() >= 2 && value.front() == '"' && value.back() == '"') {
    value = value.substr(1, value.size() - 2);
    force_string = true;
  }
  const auto number = force_string ? std::nullopt : parse_number(value);
  if (number) {
    p.is_double = true;
    p.dval = *number;
  } else {
    p.sval = std::string(value);
  }
  return p;
}

std::string format_watch_line(const moos::Message& m, double start_moos_s, double now_moos_s) {
  moos::AlogEntry entry = moos::alog_entry(m, start_moos_s);
  if (!moos::alog_time_is_sane(m.time, now_moos_s)) entry.time_s = now_moos_s - start_moos_s;
  return moos::format_alog_line(entry);
}

int run_poke(const Options& o, std::ostream& out, std::ostream& err) {
  std::vector<Poke> pokes;
  for (const auto& a : o.arguments) {
    std::string error;
    auto p = parse_poke(a, o.all_strings, &error);
    if (!p) {
      err << "moos-cli: " << error << "\n";
      return kExitUsage;
    }
    pokes.push_back(std::move(*p));
  }
  moos::TcpClient client(client_options(o));
  if (auto code = connect(client, o, err)) return *code;
  for (const auto& p : pokes) {
    const bool ok = p.is_double ? client.notify(p.var, p.dval) : client.notify(p.var, p.sval);
    if (!ok) {  // refused: too large, or the outbox is full (the reason names the variable)
      err << "moos-cli: " << client.last_post_error() << "\n";
      return kExitNotWritten;
    }
  }
  if (!client.flush(kFlushTimeout_s)) {
    err << "moos-cli: could not write every posting (" << client.last_error() << ")\n";
    return kExitNotWritten;
  }
  client.close();
  for (const auto& p : pokes)
    out << p.var << " = " << (p.is_double ? moos::alog_value(moos::make_double_notify(p.var, p.dval, "", 0))
                                          : "\"" + p.sval + "\"")
        << "\n";
  return kExitOk;
}

int run_watch(const Options& o, std::ostream& out, std::ostream& err) {
  // Declared before the client so that it outlives it: the client's thread calls on_mail until
  // the client is destroyed.
  moos::MailSignal mail;
  moos::TcpClient client(client_options(o));
  client.set_on_mail([&mail] { mail.notify(); });
  const auto started = std::chrono::steady_clock::now();
  if (auto code = connect(client, o, err)) return *code;
  const double start_moos_s = client.moos_time();
  for (const auto& a : o.arguments) {
    const bool ok = moos::has_wildcards(a) ? client.register_wildcard(a, "*") : client.register_variable(a);
    if (!ok) {
      err << "moos-cli: cannot subscribe to " << a << "\n";
      return kExitUsage;
    }
  }
  const auto deadline = started + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>(o.timeout_s.value_or(0.0)));
  long long received = 0;
  while (true) {
    mail.take();  // before the fetch: mail arriving from now on ends the next wait at once
    for (const auto& m : client.fetch()) {
      out << format_watch_line(m, start_moos_s, client.moos_time()) << std::flush;
      if (o.count && ++received >= *o.count) return kExitOk;
    }
    // Without --timeout the watch never ends by itself: wait in steps of a second.
    const auto wait_end = o.timeout_s ? deadline : std::chrono::steady_clock::now() + std::chrono::seconds(1);
    if (mail.wait_until(wait_end) || !o.timeout_s) continue;
    if (!o.count) return kExitOk;
    err << "moos-cli: timed out after " << *o.timeout_s << " s with " << received << " of "
        << *o.count << " messages";
    // A connection that kept dropping is the likelier reason than silence: say so.
    if (const std::uint64_t connections = client.connection_count(); connections > 1)
      err << "; the connection was lost " << connections - 1 << " times, the last problem: "
          << client.last_error();
    err << "\n";
    return kExitWatchTimeout;
  }
}

}  // namespace moos_cli
