// Application base: CMOOSApp's main loop and core-moos AppCastingMOOSApp's reporting, following
// docs/protocol.md 6.2-6.4, 7.1 and 7.2; contract and deviations in include/moos/app.hpp.

#include "moos/app.hpp"

#include <algorithm>
#include <csignal>
#include <limits>
#include <ostream>

#include "moos/limits.hpp"
#include "moos/stop_signals.hpp"
#include "moos/tcp_client.hpp"
#include "base/text.hpp"

namespace moos {

namespace {

constexpr double kMaxTermReportInterval_s = 10.0;  // protocol.md 7.2 clamp 0-10
constexpr long long kMaxAppCastRunWarnings = 1000; // core-moos upper bound
/// libMOOS waits this many MOOS seconds for the first connection before starting up (7.1).
constexpr double kConnectWait_moos_s = 5.0;

constexpr std::string_view kAppCastKey = "APPCAST";

constexpr std::string_view kFrameworkKeys[] = {
    "APPTICK",        "IDLEAPPTICK",        "COMMSTICK",          "MAXAPPTICK",         "ITERATEMODE",
    "SORTMAILBYTIME", "CATCHCOMMANDMESSAGES", "TERM_REPORT_INTERVAL", "MAX_APPCAST_EVENTS",
    "MAX_APPCAST_RUN_WARNINGS", "MOOS_TIME_WARP"};

std::string place(const ConfigLine& line) {
  return " (" + base::log_excerpt(line.file) + ":" + std::to_string(line.line) + ")";
}

/// libMOOS booleans: TRUE in any case, or a number > 0 (protocol.md 6.2).
std::optional<bool> moos_bool(std::string_view value) {
  if (auto b = base::parse_bool(value)) return b;
  if (auto n = base::parse_number(value)) return *n > 0;
  return std::nullopt;
}

/// A whole number clipped to [lo, hi] (with a warning when clipped); nullopt and a warning when
/// the value is not a whole number.
std::optional<std::size_t> clipped_count(const ConfigLine& line, long long lo, long long hi,
                                         AppSettings& s) {
  const auto n = base::parse_integer(line.value, std::numeric_limits<long long>::min(),
                                     std::numeric_limits<long long>::max());
  if (!n) {
    s.config_warnings.push_back("Invalid " + base::to_upper(line.key) + ": " +
                                base::log_excerpt(line.value) + place(line));
    return std::nullopt;
  }
  const long long clipped = std::clamp(*n, lo, hi);
  if (clipped != *n)
    s.config_warnings.push_back(base::to_upper(line.key) + " " + base::log_excerpt(line.value) +
                                " clipped to " + std::to_string(clipped) + place(line));
  return static_cast<std::size_t>(clipped);
}

void apply_framework_line(const ConfigLine& line, AppSettings& s, bool& block_app_tick) {
  const std::string key = base::to_upper(line.key);
  const std::string& v = line.value;
  const std::string shown_value = base::log_excerpt(v);  // v as the warnings quote it
  auto warn = [&](const std::string& what) { s.config_warnings.push_back(what + place(line)); };
  // AppTick and IdleAppTick: a rate in [kMinAppTickHz, kMaxAppTickHz], else a warning.
  auto tick_rate = [&](const char* name) -> std::optional<double> {
    const auto f = base::parse_number(v);
    if (f && is_valid_app_tick(*f)) return f;
    warn(std::string("Invalid ") + name + ": " + shown_value + " (must be a number in [" +
         base::format_g(kMinAppTickHz) + ", " + base::format_g(kMaxAppTickHz) + "] Hz)");
    return std::nullopt;
  };
  if (key == "APPTICK") {
    if (const auto f = tick_rate("AppTick")) {
      s.app_tick_hz = *f;
      block_app_tick = true;
    }
  } else if (key == "IDLEAPPTICK") {
    if (const auto f = tick_rate("IdleAppTick")) s.idle_app_tick_hz = *f;
  } else if (key == "COMMSTICK") {
    if (auto t = base::parse_integer(v, 1, kMaxCommsTickHz)) s.comms_tick_hz = static_cast<int>(*t);
    else warn("Invalid CommsTick: " + shown_value + " (must be a whole number in 1..200)");
  } else if (key == "MAXAPPTICK") {
    const auto f = base::parse_number(v);
    if (!f || *f < 0) warn("Invalid MaxAppTick: " + shown_value + " (must be a number >= 0)");
  } else if (key == "ITERATEMODE") {
    const auto mode = base::parse_integer(v, 0, 2);
    if (!mode) warn("Invalid IterateMode: " + shown_value + " (must be 0, 1 or 2)");
    else if (*mode != 0) warn("IterateMode " + shown_value + " is not supported; mode 0 (AppTick) is used");
  } else if (key == "SORTMAILBYTIME") {
    if (auto b = moos_bool(v)) s.sort_mail_by_time = *b;
    else warn("Invalid SortMailByTime: " + shown_value + " (must be true or false)");
  } else if (key == "CATCHCOMMANDMESSAGES") {
    const auto b = moos_bool(v);
    if (!b) warn("Invalid CatchCommandMessages: " + shown_value + " (must be true or false)");
    else if (*b) warn("CatchCommandMessages is not supported; command messages are ordinary mail");
  } else if (key == "TERM_REPORT_INTERVAL") {
    const auto f = base::parse_number(v);
    if (!f) {
      warn("Invalid TERM_REPORT_INTERVAL: " + shown_value);
    } else {
      s.term_report_interval_s = std::clamp(*f, 0.0, kMaxTermReportInterval_s);
      if (s.term_report_interval_s != *f)
        warn("TERM_REPORT_INTERVAL " + shown_value + " clipped to " + base::format_g(s.term_report_interval_s));
    }
  } else if (key == "MAX_APPCAST_EVENTS") {
    if (auto n = clipped_count(line, 0, static_cast<long long>(AppCast::kMaxEventsLimit), s))
      s.max_appcast_events = *n;
  } else if (key == "MAX_APPCAST_RUN_WARNINGS") {
    if (auto n = clipped_count(line, 0, kMaxAppCastRunWarnings, s)) s.max_appcast_run_warnings = *n;
  } else if (key == "MOOS_TIME_WARP") {
    if (const auto w = parse_time_warp(v)) s.time_warp = *w;
    else warn("Invalid moos_time_warp: " + shown_value + " (must be a number in (0, 400])");
  }
}

void apply_block(const ProcessBlock& block, const AppTraits& traits, AppSettings& s,
                 bool& block_app_tick) {
  std::vector<const ConfigLine*> chosen;  // one framework line per key
  for (const auto& line : block.lines) {
    if (!is_framework_parameter(line.key)) {
      s.config_lines.push_back(line);
      continue;
    }
    auto same = std::find_if(chosen.begin(), chosen.end(), [&](const ConfigLine* c) {
      return base::iequals(c->key, line.key);
    });
    if (same == chosen.end()) {
      chosen.push_back(&line);
    } else if (traits.repeated_parameters == RepeatedParameter::kLastWinsWithWarning) {
      s.config_warnings.push_back(base::log_excerpt(line.key) + " repeated" + place(line) +
                                  ": the last value, " + base::log_excerpt(line.value) +
                                  ", is used");
      *same = &line;
    }
  }
  for (const ConfigLine* line : chosen) apply_framework_line(*line, s, block_app_tick);
}

void apply_globals(const MissionFile& mission, AppSettings& s) {
  if (auto community = mission.global("Community"); community && !community->empty())
    s.community = *community;
  else
    s.config_warnings.push_back("Community/Vehicle name not found in mission file");
  if (auto host = mission.global("ServerHost"); host && !host->empty()) s.server_host = *host;
  if (const ConfigLine* port = mission.global_line("ServerPort")) {
    if (auto p = base::parse_integer(base::remove_blanks(port->value), 1, kMaxPort))
      s.server_port = static_cast<int>(*p);
    else
      s.config_warnings.push_back("Invalid ServerPort: " + base::log_excerpt(port->value) +
                                  place(*port));
  }
  if (const ConfigLine* warp = mission.global_line("MOOSTimeWarp")) {
    if (const auto w = parse_time_warp(base::remove_blanks(warp->value)))
      s.time_warp = *w;
    else
      s.config_warnings.push_back("Invalid MOOSTimeWarp: " + base::log_excerpt(warp->value) +
                                  place(*warp));
  }
  if (const ConfigLine* term = mission.global_line("TERM_REPORTING")) {
    if (auto b = base::parse_bool(term->value))
      s.term_reporting = *b;
    else
      s.config_warnings.push_back("Invalid value for TERM_REPORTING: " +
                                  base::log_excerpt(term->value) + place(*term));
  }
}

}  // namespace

bool is_framework_parameter(std::string_view key) {
  for (std::string_view k : kFrameworkKeys)
    if (base::iequals(k, base::trim(key))) return true;
  return false;
}

AppSettings resolve_app_settings(const AppTraits& traits, const CommandLine& cl,
                                 const MissionFile* mission,
                                 const std::vector<MissionError>& mission_errors) {
  AppSettings s;
  s.app_name = app_name_from(cl, traits.default_name);
  s.moos_name = cl.moos_name.value_or(s.app_name);
  s.app_tick_hz = traits.default_app_tick_hz;
  s.comms_tick_hz = traits.default_comms_tick_hz;
  s.max_appcast_events = std::min(traits.default_max_appcast_events, AppCast::kMaxEventsLimit);
  s.max_appcast_run_warnings = traits.default_max_appcast_run_warnings;
  for (const auto& e : cl.errors) s.config_warnings.push_back("Command line: " + e);

  bool block_app_tick = false;
  if (mission) {
    s.mission = std::make_shared<const MissionFile>(*mission);
    s.mission_directory = mission->directory();
    for (const auto& e : mission_errors)
      if (e.concerns(s.app_name)) s.config_warnings.push_back(e.to_string());
    apply_globals(*mission, s);
    if (const ProcessBlock* block = mission->block(s.app_name)) {
      s.have_block = true;
      apply_block(*block, traits, s, block_app_tick);
    } else {
      s.config_warnings.push_back("No mission config block found for " + s.app_name);
    }
  }
  // Command line beats the mission, except that a block AppTick wins (protocol.md 6.4).
  if (cl.moos_host) s.server_host = *cl.moos_host;
  if (cl.moos_port) s.server_port = *cl.moos_port;
  if (cl.moos_time_warp) s.time_warp = *cl.moos_time_warp;
  if (cl.moos_app_tick_hz && !block_app_tick) s.app_tick_hz = *cl.moos_app_tick_hz;
  if (cl.moos_comms_tick_hz) s.comms_tick_hz = *cl.moos_comms_tick_hz;
  return s;
}

std::optional<std::string> AppSettings::global(std::string_view key) const {
  return mission ? mission->global(key) : std::nullopt;
}

std::optional<double> AppSettings::global_double(std::string_view key) const {
  return mission ? mission->global_double(key) : std::nullopt;
}

// ---- MoosApp --------------------------------------------------------------------------------

MoosApp::MoosApp(AppTraits traits) : traits_(std::move(traits)) {}

MoosApp::~MoosApp() = default;

double MoosApp::moos_time() const { return comms_ ? comms_->moos_time() : 0.0; }

double MoosApp::seconds_since_start() const { return curr_time_ - start_time_; }

std::string MoosApp::community() const {
  if (!settings_.community.empty()) return settings_.community;
  return comms_ ? comms_->community() : std::string();
}

void MoosApp::set_terminal_output(std::function<void(const std::string&)> sink) {
  terminal_output_ = std::move(sink);
  update_report_every_cycle();
}

void MoosApp::update_report_every_cycle() {
  flags_.report_every_cycle = traits_.post_iteration_timing || settings_.community.empty() ||
                              terminal_output_ || !requests_.empty();
}

bool MoosApp::start(Comms& comms, AppSettings settings) {
  comms_ = &comms;
  settings_ = std::move(settings);
  if (settings_.time_warp != comms.time_warp()) {
    settings_.config_warnings.push_back("MOOSTimeWarp " + base::format_g(settings_.time_warp) +
                                        " differs from the connection's " +
                                        base::format_g(comms.time_warp()) + ", which is used");
    settings_.time_warp = comms.time_warp();
  }
  if (!(settings_.app_tick_hz > 0)) settings_.app_tick_hz = traits_.default_app_tick_hz;
  period_moos_s_ = 1.0 / settings_.app_tick_hz;
  due_tolerance_moos_s_ = kScheduleToleranceFraction / settings_.app_tick_hz;
  flags_.sort_mail_by_time = settings_.sort_mail_by_time;
  flags_.post_status = settings_.post_status;
  flags_.post_iteration_timing = traits_.post_iteration_timing;
  flags_.idle_app_tick = settings_.idle_app_tick_hz.has_value();
  flags_.takes_fetch_promises = comms.takes_fetch_promises();
  update_report_every_cycle();
  iter_gap_var_ = base::to_upper(settings_.moos_name) + "_ITER_GAP";
  iter_len_var_ = base::to_upper(settings_.moos_name) + "_ITER_LEN";
  status_var_ = base::to_upper(settings_.app_name) + "_STATUS";
  appcast_.set_proc(settings_.app_name);
  appcast_.set_node(community());
  appcast_.set_max_events(settings_.max_appcast_events);
  appcast_.set_max_run_warnings(settings_.max_appcast_run_warnings);
  for (const auto& w : settings_.config_warnings) report_config_warning(w);

  start_time_ = curr_time_ = next_due_moos_s_ = moos_time();
  if (settings_.idle_app_tick_hz) {
    // Mail, and a new connection (whose on_connect_to_server is due), end an idle sleep.
    comms.set_on_mail([this] { note_mail(); });
    comms.set_on_connect([this] { note_mail(); });
  }
  comms.register_variable(std::string(kAppCastRequestKey), 0.0);
  return on_start_up();
}

void MoosApp::cycle_at(double now) {
  if (!comms_) return;
  // Everything this cycle posts leaves together (Comms::hold_sends).
  struct SendBatch {
    Comms& comms;
    explicit SendBatch(Comms& c) : comms(c) { comms.hold_sends(); }
    ~SendBatch() { comms.release_sends(); }
    SendBatch(const SendBatch&) = delete;
    SendBatch& operator=(const SendBatch&) = delete;
  } batch(*comms_);
  curr_time_ = now;
  schedule_next(now);
  if (flags_.idle_app_tick) {
    idle_resume_moos_s_.reset();
    mail_signal_.take();  // before the fetch: mail arriving during it still ends the next sleep
  }

  const std::uint64_t connections = comms_->connection_count();
  if (connections != seen_connections_) {
    seen_connections_ = connections;
    if (comms_->is_connected()) on_connect_to_server();
  }

  comms_->fetch_into(mail_);
  if (comms_->mail_dropped() != reported_mail_dropped_) report_dropped_mail();
  if (comms_->postings_dropped() != reported_postings_dropped_) report_dropped_postings();
  if (!mail_.empty()) handle_mail();

  if (!comms_->is_connected()) return;  // libMOOS iterates only while connected (7.1)
  if (flags_.post_status) post_status_if_due();
  ++iteration_;
  if (flags_.post_iteration_timing) {
    if (last_iterate_start_moos_s_)
      comms_->notify(iter_gap_var_, (now - *last_iterate_start_moos_s_) * settings_.app_tick_hz);
    last_iterate_start_moos_s_ = now;
  }
  iterate();
  if (report_may_be_due()) {
    post_report(now);
  } else {
    appcast_.set_iteration(iteration_);  // all post_report() would have done
  }
  if (flags_.idle_app_tick) plan_idle(now);
  if (flags_.takes_fetch_promises) promise_next_fetch();  // else no clock to read for it
}

bool MoosApp::report_may_be_due() const {
  // What post_report() looks at, cheapest first; without any of it, it only counts the
  // iteration.
  return iteration_ < 2 || flags_.report_every_cycle || flags_.new_config_warning;
}

void MoosApp::promise_next_fetch() {
  if (idle_resume_moos_s_) {
    comms_->expect_fetch_within(0.0);
    return;
  }
  comms_->expect_fetch_within((next_due_moos_s_ - moos_time()) / comms_->time_warp());
}

bool MoosApp::appcast_requested() const {
  if (flags_.new_config_warning) return true;
  for (const auto& [key, r] : requests_) {
    if (curr_time_ - r.start_moos_s >= r.request.duration_s) continue;  // expired
    if (r.request.thresh == "any") return true;
    if (r.request.thresh == "run_warning" && new_run_warning_) return true;
  }
  return false;
}

std::string MoosApp::status_string() const {
  std::string out = "AppErrorFlag=false,Uptime=" + base::format_g(moos_time() - start_time_) +
                    ",MOOSName=" + settings_.app_name + ",Publishing=\"";
  if (comms_)
    for (const auto& name : comms_->published_names()) out += name + ",";
  out += "\",Subscribing=\"";
  if (comms_)
    for (const auto& name : comms_->registered_names()) out += name + ",";
  out += "\"";
  return out;
}

void MoosApp::post_status_if_due() {
  if (last_status_moos_s_ && curr_time_ - *last_status_moos_s_ < kStatusPeriod_s) return;
  comms_->notify(status_var_, status_string());
  last_status_moos_s_ = curr_time_;
}

bool MoosApp::term_reporting_enabled() const {
  return terminal_output_ && settings_.term_reporting.value_or(true);
}

void MoosApp::post_report(double iterate_start) {
  if (traits_.post_iteration_timing)
    comms_->notify(iter_len_var_, (moos_time() - iterate_start) * settings_.app_tick_hz);
  appcast_.set_iteration(iteration_);
  // Only a node name that comes from the connection (no Community setting) can change.
  if (settings_.community.empty()) appcast_.set_node(community());

  // Nothing to report (an app nobody watches): no times to work out.
  const bool appcast_pending = appcast_requested() || iteration_ < 2;
  const bool term = term_reporting_enabled();
  if (!term && !appcast_pending) return;
  // protocol.md 7.2: real seconds since the last terminal report and the last appcast.
  const double warp = comms_->time_warp();
  auto real_since = [&](const std::optional<double>& t) {
    return t ? (curr_time_ - *t) / warp : std::numeric_limits<double>::infinity();
  };
  const double since_term = real_since(last_term_report_moos_s_);
  const double since_appcast = real_since(last_appcast_moos_s_);
  const double interval = settings_.term_report_interval_s;
  if (since_term < interval && since_appcast < interval) return;
  if (!appcast_pending && since_term < interval) return;
  if (!term && since_appcast < interval) return;

  appcast_.set_messages(build_report());
  if (term) {
    last_term_report_moos_s_ = curr_time_;
    terminal_output_(appcast_.terminal_report());
  }
  if (appcast_pending) {
    new_run_warning_ = false;
    flags_.new_config_warning = false;
    last_appcast_moos_s_ = curr_time_;
    comms_->notify(std::string(kAppCastKey), appcast_.appcast_string());
  }
}

std::string MoosApp::terminal_report() {
  appcast_.set_iteration(iteration_);
  // Only a node name that comes from the connection (no Community setting) can change.
  if (settings_.community.empty()) appcast_.set_node(community());
  appcast_.set_messages(build_report());
  return appcast_.terminal_report();
}

bool MoosApp::notify(const std::string& var, double value) { return comms_->notify(var, value); }
bool MoosApp::notify(const std::string& var, std::string value) {
  return comms_->notify(var, std::move(value));
}
bool MoosApp::notify_binary(const std::string& var, const std::string& bytes) {
  return comms_->notify_binary(var, bytes);
}
bool MoosApp::register_variable(const std::string& var, double interval_s) {
  return comms_->register_variable(var, interval_s);
}
bool MoosApp::unregister_variable(const std::string& var) { return comms_->unregister_variable(var); }
bool MoosApp::register_wildcard(const std::string& var_pattern, const std::string& app_pattern,
                                double interval_s) {
  return comms_->register_wildcard(var_pattern, app_pattern, interval_s);
}

void MoosApp::report_config_warning(const std::string& text) {
  flags_.new_config_warning = true;
  appcast_.add_config_warning(text);
}

void MoosApp::report_unhandled_config_line(const ConfigLine& line) {
  report_config_warning("Unhandled config line: " + base::log_excerpt(line.key) + "=" +
                        base::log_excerpt(line.value));
}

void MoosApp::report_run_warning(const std::string& text) {
  new_run_warning_ = true;
  appcast_.add_run_warning(text);
}

void MoosApp::retract_run_warning(const std::string& text) {
  // A successful retraction is news for run_warning subscribers too (core-moos).
  if (appcast_.retract_run_warning(text)) new_run_warning_ = true;
}

void MoosApp::report_event(const std::string& text) {
  appcast_.add_event(text, curr_time_ - start_time_);
}

// ---- run_app --------------------------------------------------------------------------------

std::optional<double> tw_delay_factor_ms(const CommandLine& cl, std::string* error) {
  static const std::string kSwitch = "moos_tw_delay_factor";
  const auto it = cl.moos_switches.find(kSwitch);
  if (it == cl.moos_switches.end()) return TcpClientOptions{}.tw_delay_factor_ms;
  const auto factor = base::parse_number(it->second);
  if (!factor || *factor < 0.0) {
    *error = "--" + kSwitch + "=" + it->second + ": the factor must be a number >= 0";
    return std::nullopt;
  }
  return *factor;
}

int run_app(MoosApp& app, const CommandLine& cl, std::ostream& out, std::ostream& err,
            bool out_is_terminal) {
  if (!cl.mission_file) {
    err << "no mission file given\n";
    return 1;
  }
  std::string factor_error;
  const std::optional<double> tw_delay_factor = tw_delay_factor_ms(cl, &factor_error);
  if (!tw_delay_factor) {
    err << factor_error << "\n";
    return 1;
  }
  MissionOptions mission_options;
  mission_options.substitutions = cl.substitutions;
  std::vector<MissionError> mission_errors;
  const auto mission = MissionFile::load(*cl.mission_file, mission_options, &mission_errors);
  if (!mission) {
    for (const auto& e : mission_errors) err << e.to_string() << "\n";
    return 1;
  }
  AppSettings settings = resolve_app_settings(app.traits(), cl, &*mission, mission_errors);

  TcpClientOptions client_options;
  client_options.host = settings.server_host;
  client_options.port = settings.server_port;
  client_options.name = settings.moos_name;
  client_options.time_warp = settings.time_warp;
  client_options.tw_delay_factor_ms = *tw_delay_factor;
  // A reader that leaves a FIFO or pipe the app writes (a log, its terminal output) makes the
  // write fail with EPIPE, which the writer reports and counts, instead of ending the app
  // without a word while it still serves its community. Sockets already send with MSG_NOSIGNAL.
  std::signal(SIGPIPE, SIG_IGN);
  // Before the comms thread starts, so that only the watcher takes SIGINT and SIGTERM.
  StopSignals stop_signals;
  TcpClient client(client_options);
  if (!client.start()) {
    err << "cannot start the MOOS client: " << client.last_error() << "\n";
    return 1;
  }
  client.wait_until_connected(kConnectWait_moos_s / settings.time_warp);
  if (client.state() == ConnectionState::kPoisoned) {
    err << client.last_error() << "\n";
    return 1;
  }
  if (!client.is_connected())
    err << "not connected to " << settings.server_host << ":" << settings.server_port << " yet ("
        << client.last_error() << "); still trying\n";

  const bool term = settings.term_reporting.value_or(out_is_terminal);
  if (term) {
    app.set_terminal_output([&out](const std::string& frame) {
      out << std::string(9, '\n') << frame << std::flush;  // libMOOS scrolls the old frame away
    });
  }
  if (!app.start(client, std::move(settings))) {
    err << app.settings().app_name << ": start-up failed\n";
    for (const auto& w : app.appcast().config_warnings()) err << "  " << w << "\n";
    return 1;
  }
  stop_signals.set_handler([&app] { app.request_stop(); });
  app.run_until_stopped();
  client.close();
  return 0;
}

}  // namespace moos
