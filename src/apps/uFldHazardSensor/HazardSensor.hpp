#pragma once
// HazardSensor: the uFldHazardSensor MOOS application, a thin adapter between libmoos's
// application base and the pure engine (hazard::Engine). It holds no model logic.
//
// Contract:
// - on_start_up: the engine is built by app_support::make_sensor_engine, the wiring
//   hazard_replay shares: the app's block lines (framework keys already taken by libmoos) go to
//   hazard::load_configuration in file order with their file and line; hazard files are read
//   relative to the mission file's folder; the mission's LatOrigin/LongOrigin globals go with
//   them (geodesy); folder and globals come with the settings (moos::AppSettings, from the one
//   reading of the mission file); the seed is resolved (random_seed, else seed_random:
//   the operating system, else seed 1); the engine starts at the start-up time and its config
//   warnings and object visuals are published; the engine's subscriptions are registered.
//   Configuration problems never stop the app (D26).
// - Mail: each message goes to hazard::Driver::deliver with its own time stamp and this cycle's
//   time (the driver clamps the one to the other and dispatches by variable name). Doubles are
//   passed as text. Bad mail only yields a run warning (the driver's), never a stop.
//   Mail passes through a MailBacklog (mail_backlog.hpp): up to kMailPerIteration messages a
//   cycle are handled at once in arrival order (every normal mission); under a flood each
//   source gets its share per cycle, the rest in the next cycles (which run even when idle),
//   and mail the backlog's bounds drop is reported as one run warning.
// - Iterate: Driver::step at this cycle's time (never earlier than the last mail time).
// - Every engine output is published in order: postings with notify(), events, run warnings,
//   retractions and config warnings to the AppCast. With a verbose stream, every posting and
//   event (and warning) is also written there as an .alog line (time since start-up, variable,
//   app name, value), after an .alog header written at start-up (D29).
// - Reconnect (on_connect_to_server after a database restart or a dropped link): the field's
//   visuals (the object markers, with show_hazards) are posted again, because the new database
//   has none of them; libmoos re-sends the registrations itself. The engine is kept as it is
//   (settings, credits, queues): only the database was lost, not the mission. The connection
//   that start-up already served gets nothing twice.
// - Idle (IdleAppTick, opt-in): the app is quiet until Engine::quiet_until_s.
// - build_report: hazard::format_report (docs/uFldHazardSensor.md; seed and active effects in its
//   header).
// The app therefore posts exactly what the engine decided; hazard_replay drives the same engine
// the same way (start, mail before the iteration of its time, step per AppTick).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "hazard/driver.hpp"
#include "mail_backlog.hpp"
#include "hazard/engine.hpp"
#include "moos/app.hpp"

namespace ufld_hazard_sensor {

/// Events kept in the AppCast unless max_appcast_events says otherwise (the original's 20).
inline constexpr std::size_t kDefaultMaxAppCastEvents = 20;

/// Pseudo-variables of the verbose .alog stream for what is not a posting.
inline constexpr const char* kVerboseEvent = "EVENT";
inline constexpr const char* kVerboseRunWarning = "RUN_WARNING";
inline constexpr const char* kVerboseRetracted = "RUN_WARNING_RETRACTED";
inline constexpr const char* kVerboseConfigWarning = "CONFIG_WARNING";

/// The framework defaults of this app: name, AppTick from the parameter table (so the app and
/// hazard_replay iterate alike when a mission omits it), 20 AppCast events, and D36's rule for
/// repeated framework parameters (the last one wins, with a warning).
moos::AppTraits hazard_sensor_traits();

struct HazardSensorOptions {
  /// Where --verbose writes its .alog lines; nullptr: not verbose.
  std::ostream* verbose = nullptr;
  /// The source of an operating-system seed (seed_random = true); empty: app_support::operating_system_seed.
  std::function<std::uint64_t()> os_seed;
  /// Who reads the postings (hazard/effects.hpp): a study that reads only the reports
  /// (hazard_study without --alog) passes kReportCounts, and no visual's text is built.
  hazard::PostingReaders readers = hazard::PostingReaders::kViewers;
  /// `<APP>_ITER_GAP` / `_ITER_LEN` every iteration (moos::AppTraits); a study that reads no
  /// framework postings turns them off.
  bool post_iteration_timing = true;
  /// Builds the engine from the block's lines and the settings, for these readers (a host that
  /// runs many missions over one field, hazard_study, hands out copies of an engine it built
  /// once: Engine::with_seed). Empty: app_support::make_sensor_engine, then `readers`.
  std::function<hazard::Engine(const std::vector<moos::ConfigLine>& lines,
                               const moos::AppSettings& settings, hazard::PostingReaders readers)>
      make_engine;
  /// Node reports parsed through hazard::NodeReportMemo (hazard::Driver::share_node_report_parses):
  /// a process that hosts the managers too (hazard_study) parses each report once.
  bool share_node_report_parses = false;
};

class HazardSensor final : public moos::MoosApp {
 public:
  explicit HazardSensor(HazardSensorOptions options = {});

  /// The engine; nullptr until start-up has run.
  const hazard::Engine* engine() const { return driver_ ? &driver_->engine() : nullptr; }

 protected:
  bool on_start_up() override;
  void on_connect_to_server() override;
  void on_new_mail(const std::vector<moos::Message>& mail) override;
  void iterate() override;
  std::string build_report() override;
  /// The engine's quiet time (Engine::quiet_until_s): with IdleAppTick, cycles before it are
  /// skipped unless mail arrives.
  double quiet_until_moos_s(double now_moos_s) const override;

 private:
  /// The engine of this block (HazardSensorOptions::make_engine, else as the contract says).
  hazard::Engine build_engine() const;
  /// Posts, reports and logs what the engine produced; the posted texts are moved, not copied.
  void publish(hazard::TimedOutputs&& timed);
  void write_verbose(double now_s, const std::string& variable, const std::string& value) const;
  /// Hands this cycle's share of the backlog to the engine.
  void handle_backlog();
  /// Hands `mail` to the engine, in order.
  void deliver(const std::vector<moos::Message>& mail);
  /// The run warning that counts the mail the backlog dropped.
  void report_dropped(std::size_t dropped);

  HazardSensorOptions options_;
  std::optional<hazard::Driver> driver_;
  MailBacklog backlog_;
  bool handled_this_cycle_ = false;  ///< on_new_mail already took this cycle's share
  std::uint64_t backlog_dropped_ = 0;
  std::string backlog_warning_;
  /// The connection (comms' connection count) that start-up's visuals went to.
  std::uint64_t start_up_connection_ = 0;
};

}  // namespace ufld_hazard_sensor
