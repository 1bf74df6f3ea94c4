#pragma once
// The application base (docs/protocol.md 7.1 CMOOSApp and 7.2 AppCastingMOOSApp, core-moos
// flavour), designed so that applications stay thin and can be stepped deterministically in tests.
//
// Contract:
// - An app derives from MoosApp and overrides on_start_up / on_connect_to_server / on_new_mail /
//   iterate / build_report. It never calls base versions and never posts its own APPCAST: the
//   base does the AppCasting bookkeeping around the hooks (libMOOS's "call the base Iterate
//   first and PostReport last" rule is built in).
// - The base runs on any Comms: TcpClient with the system clock, or a BusClient with a
//   ManualClock. Time is always comms().moos_time() (= unix x warp + skew, protocol.md 1.10), and
//   the warp is the comms's own.
// - One cycle (libMOOS DoRunWork without the sleep, protocol.md 7.1):
//     1. if the comms connected (again) since the last cycle: on_connect_to_server();
//     2. fetch mail, sort it by time (stable; unless SortMailByTime = false), consume
//        APPCAST_REQ and `_async_timing`, hand the rest to on_new_mail() if any is left;
//     3. only while connected: post `<APPNAME>_STATUS` (first cycle, then every 2 MOOS s),
//        iteration += 1, post `<MOOSNAME>_ITER_GAP` (from the 2nd iteration), iterate(),
//        post `<MOOSNAME>_ITER_LEN`, then the report decision of protocol.md 7.2 (terminal frame
//        and/or APPCAST).
// - Cycles are due every 1/AppTick MOOS seconds (AppTick in MOOS-time Hz, so warp W gives
//   W x AppTick real cycles per second). run_for() and run_until() sleep on the comms clock, so
//   a ManualClock makes them instant and exact.
// - on_connect_to_server() runs on the thread that calls cycle(), never on a comms thread.
//   Subscriptions are remembered by the comms and re-sent after a reconnect, so an app may
//   register once in on_start_up().
// - An app reads its mission through its settings: the block lines (config_lines), the folder of
//   the mission file (mission_directory) and the globals it needs itself (global, global_double,
//   e.g. LatOrigin). The file is read once, by whoever resolves the settings (run_app or a test).
// - IdleAppTick (ours, opt-in; docs/differences.md): an app that can tell until when its
//   iterate() would do nothing (quiet_until_moos_s) may skip cycles while it is quiet: with
//   IdleAppTick = F it cycles at least every 1/F MOOS s and whenever it stops being quiet, and mail
//   ends the skipping at once. Every cycle still falls on the AppTick grid (start + k / AppTick),
//   so mail is handled at the same cycle as without the option; only the framework's postings
//   (_ITER_GAP, _ITER_LEN, _STATUS, the iteration count) see fewer cycles. Without the option
//   every slot of the grid is a cycle, as in libMOOS.
// - Iterate modes 1 and 2, command messages (`<APP>_CMD`) and cpu/memory in the status are not
//   implemented: their configuration keys produce a configuration warning when enabled.

#include <atomic>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "moos/appcast.hpp"
#include "moos/command_line.hpp"
#include "moos/comms.hpp"
#include "moos/mail_signal.hpp"
#include "moos/mission.hpp"

namespace moos {

/// What to do when a framework parameter appears twice in the block.
enum class RepeatedParameter {
  kFirstWins,            ///< libMOOS: the first line wins, silently
  kLastWinsWithWarning,  ///< the last line wins, with a warning (the sensor: differences.md D36)
};

/// What an application says about itself (defaults that differ between apps).
struct AppTraits {
  std::string default_name;             ///< process name without an alias, e.g. "uFldHazardSensor"
  double default_app_tick_hz = 5.0;     ///< CMOOSApp default (protocol.md 6.3)
  int default_comms_tick_hz = 5;
  std::size_t default_max_appcast_events = AppCast::kDefaultMaxEvents;
  std::size_t default_max_appcast_run_warnings = AppCast::kDefaultMaxRunWarnings;
  RepeatedParameter repeated_parameters = RepeatedParameter::kFirstWins;
  bool post_iteration_timing = true;    ///< `<MOOSNAME>_ITER_GAP` / `_ITER_LEN` (protocol.md 7.2)
};

/// The framework's settings after mission file and command line (protocol.md 6.2-6.4).
struct AppSettings {
  std::string app_name;                  ///< selects the block; names _STATUS and the appcast
  std::string moos_name;                 ///< registration name (default: app_name)
  std::string server_host = "localhost";
  int server_port = 9000;
  std::string community;                 ///< mission `Community` ("" if absent)
  double time_warp = 1.0;                ///< 0 < W <= 400
  double app_tick_hz = 5.0;              ///< > 0, MOOS-time Hz
  int comms_tick_hz = 5;                 ///< accepted for compatibility; the async client ignores it
  double term_report_interval_s = 0.4;   ///< real seconds, [0, 10]
  std::size_t max_appcast_events = AppCast::kDefaultMaxEvents;
  std::size_t max_appcast_run_warnings = AppCast::kDefaultMaxRunWarnings;
  std::optional<bool> term_reporting;    ///< mission TERM_REPORTING; nullopt when absent
  bool sort_mail_by_time = true;
  /// IdleAppTick (ours, opt-in): MOOS-time Hz of the cycles of a quiet app (see the contract);
  /// nullopt: every AppTick slot is a cycle (libMOOS).
  std::optional<double> idle_app_tick_hz;
  /// `<APP>_STATUS` every 2 s (protocol.md 7.2). Not a mission-file key: only a program that
  /// hosts the app and knows nobody reads the status (hazard_study without a log) turns it off.
  bool post_status = true;
  /// The application's own lines of its block (framework keys removed), in file order.
  std::vector<ConfigLine> config_lines;
  bool have_block = false;
  /// Problems found while resolving, already worded for the appcast.
  std::vector<std::string> config_warnings;
  /// The folder of the mission file (MissionFile::directory()): relative paths in the block,
  /// such as a hazard file, are read from there. "." without a mission file.
  std::string mission_directory = ".";
  /// The mission file the settings were resolved from; nullptr without one. Shared, so that
  /// copies of the settings do not copy the file.
  std::shared_ptr<const MissionFile> mission;

  /// A global of the mission file (MissionFile::global); nullopt without a mission file.
  std::optional<std::string> global(std::string_view key) const;
  /// A numeric global (MissionFile::global_double); nullopt without a mission file.
  std::optional<double> global_double(std::string_view key) const;
};

/// True for the block keys the base handles (AppTick, IdleAppTick, CommsTick, MaxAppTick, IterateMode,
/// SortMailByTime, CatchCommandMessages, TERM_REPORT_INTERVAL, MAX_APPCAST_EVENTS,
/// MAX_APPCAST_RUN_WARNINGS, moos_time_warp), compared case-insensitively.
bool is_framework_parameter(std::string_view key);

/// Resolves the settings. Precedence (protocol.md 6.3, 6.4): warp = --moos_time_warp, else block
/// moos_time_warp, else global MOOSTimeWarp, else 1; AppTick = block, else --moos_app_tick,
/// else the trait default; host/port = --moos_host/--moos_port, else ServerHost/ServerPort,
/// else localhost:9000. `mission_errors` in this app's block or outside any block become
/// configuration warnings; errors in other apps' blocks are not this app's business. The
/// settings keep a copy of `mission` and its folder (mission, mission_directory).
AppSettings resolve_app_settings(const AppTraits& traits, const CommandLine& command_line,
                                 const MissionFile* mission,
                                 const std::vector<MissionError>& mission_errors = {});

class MoosApp {
 public:
  /// MOOS seconds between `<APPNAME>_STATUS` postings (protocol.md 7.1).
  static constexpr double kStatusPeriod_s = 2.0;

  explicit MoosApp(AppTraits traits);
  virtual ~MoosApp();
  MoosApp(const MoosApp&) = delete;
  MoosApp& operator=(const MoosApp&) = delete;

  const AppTraits& traits() const { return traits_; }

  // ---- driving (main or a test) ----------------------------------------------------------------
  /// Binds the app to `comms` (which must outlive it), applies the settings, registers
  /// APPCAST_REQ, records the start time and calls on_start_up(); returns its result.
  bool start(Comms& comms, AppSettings settings);
  /// One main-loop pass now (see the contract above).
  void cycle() { cycle_at(moos_time()); }
  /// MOOS time at which the next cycle is due (later while the app is quiet, IdleAppTick).
  double next_cycle_due_moos_s() const { return due_moos_s(); }
  /// Runs a cycle if it is due; true if it ran.
  bool cycle_if_due() { return cycle_if_due(moos_time()); }
  /// The same for a driver that has just read the time itself (Lockstep, which sets the clock
  /// and cycles several apps at one instant): `now_moos_s` must be comms().moos_time().
  bool cycle_if_due(double now_moos_s);
  /// Sleeps on the comms clock from cycle to cycle until `moos_s` MOOS seconds have passed.
  void run_for(double moos_s);
  /// The real main loop: cycles until request_stop() or `external_stop` becomes true.
  void run_until_stopped(const std::atomic<bool>* external_stop = nullptr);
  /// Ends run_until_stopped / run_for at once, even in an idle sleep; any thread may call it.
  void request_stop() {
    stop_ = true;
    mail_signal_.notify();
  }

  /// Where terminal reports go (main: standard output when it is a terminal). None: no
  /// terminal reports.
  void set_terminal_output(std::function<void(const std::string&)> sink);

  // ---- inspection --------------------------------------------------------------------------------
  const AppSettings& settings() const { return settings_; }
  const AppCast& appcast() const { return appcast_; }
  std::uint64_t iteration() const { return iteration_; }
  double moos_time() const;
  double start_time() const { return start_time_; }
  /// The MOOS time of the running cycle: sampled once when the cycle starts, so mail handling
  /// and iterate() in one cycle see the same time (libMOOS m_curr_time).
  double cycle_time() const { return curr_time_; }
  /// The current `<APPNAME>_STATUS` text (protocol.md 7.1).
  std::string status_string() const;
  /// Builds the report now (calls build_report) and returns the terminal frame.
  std::string terminal_report();

 protected:
  // ---- hooks -------------------------------------------------------------------------------------
  /// Configuration: settings().config_lines; false ends the program.
  virtual bool on_start_up() { return true; }
  virtual void on_connect_to_server() {}
  /// Mail of this cycle, sorted by time, framework mail removed; never empty.
  virtual void on_new_mail(const std::vector<Message>& mail) { (void)mail; }
  virtual void iterate() {}
  /// The report body (the appcast `messages`): text lines separated by '\n'.
  virtual std::string build_report() { return {}; }
  /// Until when (MOOS s) iterate() would do nothing if no mail arrived: cycles before it may be
  /// skipped when IdleAppTick is set. The default, `now_moos_s`, means "never quiet".
  virtual double quiet_until_moos_s(double now_moos_s) const { return now_moos_s; }

  // ---- services ----------------------------------------------------------------------------------
  Comms& comms() const { return *comms_; }
  const std::string& app_name() const { return settings_.app_name; }
  /// The appcast node: the mission community, else the one the server announced.
  std::string community() const;
  const std::vector<ConfigLine>& config_lines() const { return settings_.config_lines; }
  /// MOOS seconds since start().
  double seconds_since_start() const;

  bool notify(const std::string& var, double value);
  bool notify(const std::string& var, std::string value);  ///< the value moved on, uncopied
  bool notify_binary(const std::string& var, const std::string& bytes);
  bool register_variable(const std::string& var, double interval_s = 0.0);
  bool unregister_variable(const std::string& var);
  bool register_wildcard(const std::string& var_pattern, const std::string& app_pattern = "*",
                         double interval_s = 0.0);

  void report_config_warning(const std::string& text);
  /// `Unhandled config line: <key>=<value>` for a line the app did not accept.
  void report_unhandled_config_line(const ConfigLine& line);
  void report_run_warning(const std::string& text);
  void retract_run_warning(const std::string& text);
  void report_event(const std::string& text);

 private:
  struct Request {
    double start_moos_s = 0.0;
    AppCastRequest request;
  };

  /// One cycle (the contract's steps) at `now`, comms().moos_time().
  void cycle_at(double now);
  /// Sorts the cycle's mail, takes the framework's and hands the rest to on_new_mail().
  void handle_mail();
  void handle_framework_mail(std::vector<Message>& mail);
  /// Takes the framework's messages from `first` (one of them) on.
  void remove_framework_mail(std::vector<Message>& mail, std::vector<Message>::iterator first);
  /// CycleFlags::report_every_cycle from the traits, settings, terminal and requests.
  void update_report_every_cycle();
  /// A standing run warning with the count of mail the comms dropped unread.
  void report_dropped_mail();
  /// A standing run warning with the count of postings the comms refused (full outbox, too
  /// large), naming the latest's variable.
  void report_dropped_postings();
  bool appcast_requested() const;
  /// The status when it is due; only with settings_.post_status.
  void post_status_if_due();
  /// False when post_report() would only set the appcast's iteration: no terminal, no appcast
  /// request, no new configuration warning, no _ITER_LEN, a fixed node name, past iteration 1.
  /// A condition added to post_report() must be added here too (this stays a superset).
  bool report_may_be_due() const;
  void post_report(double iterate_start_moos_s);
  void schedule_next(double cycle_start_moos_s);
  /// After a cycle: tells the comms when the next fetch comes (Comms::expect_fetch_within), so
  /// it can leave reading to it; none while slots are skipped, when mail must wake the app.
  /// Only for a comms that takes the promise (Comms::takes_fetch_promises).
  void promise_next_fetch();
  // IdleAppTick (app_idle.cpp).
  /// When the next cycle is due: the next AppTick slot, or while quiet and without mail the
  /// first slot at or after idle_resume_moos_s_ (idle_due_moos_s).
  double due_moos_s() const {
    return idle_resume_moos_s_ ? idle_due_moos_s() : next_due_moos_s_;
  }
  double idle_due_moos_s() const;
  /// The first slot of the AppTick grid (next_due_moos_s_ + k / AppTick) at or after `t`.
  double grid_slot_at_or_after(double t) const;
  /// After a cycle: until when the following cycles may be skipped; only with IdleAppTick.
  void plan_idle(double cycle_start_moos_s);
  /// From the comms thread: mail (or a connection) arrived; the first since the last fetch
  /// records its MOOS time.
  void note_mail();
  /// Mail arrived since the last fetch.
  bool mail_waiting() const { return mail_signal_.pending(); }
  /// Sleeps until the next cycle is due, `real_s` from now: while the app is quiet in one sleep
  /// that mail and request_stop() end early, else in plain sleeps of at most
  /// kMaxLoopSleep_real_s.
  void sleep_until_due(Clock& clock, double real_s);
  bool term_reporting_enabled() const;

  /// The variable of appcast requests (protocol.md 7.2): the framework's mail.
  static constexpr std::string_view kAppCastRequestKey = "APPCAST_REQ";
  /// A cycle this close to its due time (as a fraction of the period) counts as on time; MOOS
  /// times near 1e12 (epoch x warp 400) carry only ~1e-4 s of resolution.
  static constexpr double kScheduleToleranceFraction = 1e-3;
  /// A cycle that starts less than this many periods after its slot keeps the AppTick grid:
  /// the slot it overran runs at once after it. Later than that, the missed slots are skipped,
  /// so an app that cannot keep up is never more than this far behind.
  static constexpr double kMaxCatchUpPeriods = 2.0;
  /// Longest plain sleep of the real main loop, so that `external_stop` is seen promptly (an
  /// idle sleep is woken by mail and by request_stop() instead).
  static constexpr double kMaxLoopSleep_real_s = 0.1;

  /// The settings and traits a cycle reads, copied at start() next to the cycle's state.
  struct CycleFlags {
    bool sort_mail_by_time = true;       ///< settings_.sort_mail_by_time
    bool post_status = true;             ///< settings_.post_status
    bool post_iteration_timing = true;   ///< traits_.post_iteration_timing
    bool idle_app_tick = false;          ///< settings_.idle_app_tick_hz is set
    bool takes_fetch_promises = false;   ///< comms_->takes_fetch_promises()
    /// post_report() may do more than count the iteration in every cycle: iteration timing, a
    /// node name from the connection, a terminal, or an appcast request once received (requests
    /// are kept). Part of report_may_be_due().
    bool report_every_cycle = true;
    bool new_config_warning = false;     ///< a configuration warning since the last appcast
  };

  // What every cycle reads and writes, together at the front (two cache lines): a lockstep
  // cycles several apps between two cycles of one, and their work evicts the rest of this object.
  Comms* comms_ = nullptr;
  double curr_time_ = 0.0;  // MOOS time of the current cycle (libMOOS m_curr_time)
  double next_due_moos_s_ = 0.0;
  double period_moos_s_ = 0.0;  ///< 1 / AppTick, set at start()
  /// How early a cycle may come and still be due (kScheduleToleranceFraction / AppTick).
  double due_tolerance_moos_s_ = 0.0;
  std::optional<double> idle_resume_moos_s_;  ///< IdleAppTick: skip cycles before it, unless mail
  std::uint64_t iteration_ = 0;
  std::uint64_t seen_connections_ = 0;
  std::uint64_t reported_mail_dropped_ = 0;  ///< comms_->mail_dropped() when last reported
  std::uint64_t reported_postings_dropped_ = 0;  ///< comms_->postings_dropped() when last reported
  /// The cycle's mail, kept between cycles: the next fetch hands its messages back to the comms
  /// for their storage (Comms::fetch_into).
  std::vector<Message> mail_;
  CycleFlags flags_;

  const AppTraits traits_;
  AppSettings settings_;
  // The framework's own variable names, built once at start() (posted every cycle).
  std::string iter_gap_var_, iter_len_var_, status_var_;
  AppCast appcast_;
  std::function<void(const std::string&)> terminal_output_;
  std::atomic<bool> stop_{false};

  double start_time_ = 0.0;
  MailSignal mail_signal_;
  std::atomic<double> first_mail_moos_s_{0.0};  ///< arrival of the first mail since the fetch
  std::string dropped_mail_warning_;          ///< the standing warning about it, if any
  std::string dropped_postings_warning_;         ///< the standing warning about it, if any
  std::optional<double> last_status_moos_s_;
  std::optional<double> last_iterate_start_moos_s_;  ///< only with post_iteration_timing
  std::optional<double> last_term_report_moos_s_;
  std::optional<double> last_appcast_moos_s_;
  bool new_run_warning_ = false;
  std::map<std::string, Request> requests_;  // by requester key
};

/// libMOOS's pause after each packet sent, in ms per unit of time warp
/// (docs/protocol.md 4.3 step 4): `--moos_tw_delay_factor=F` (a number >= 0), else libMOOS's
/// default 0.2. A high-warp mission passes 0: at warp 400 the default pauses 80 ms after every
/// packet, so a vehicle's node reports reach the sensor in bursts of 32 simulated seconds. nullopt, with `error` naming the argument,
/// when the value is not a number >= 0.
std::optional<double> tw_delay_factor_ms(const CommandLine& command_line, std::string* error);

/// The whole life of an app as a MOOS process over TCP (protocol.md 7.1): loads the mission named
/// on the command line (with its `--NAME=value` substitutions), resolves the settings, connects a
/// TcpClient, waits up to 5 MOOS s for the connection, calls start(), prints terminal reports to
/// `out` (when TERM_REPORTING = true, or unset and `out_is_terminal`) and cycles until SIGINT or
/// SIGTERM. Problems go to `err`. Returns the exit code: 0 after a signal, 1 if the mission cannot
/// be read, `--moos_tw_delay_factor` is not a number >= 0, the server refuses the name, or
/// on_start_up() fails.
int run_app(MoosApp& app, const CommandLine& command_line, std::ostream& out, std::ostream& err,
            bool out_is_terminal);

}  // namespace moos
