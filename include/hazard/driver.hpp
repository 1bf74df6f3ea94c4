#pragma once
// Driver: the one way a program feeds the engine. uFldHazardSensor, hazard_replay,
// the benchmarks and the tests all deliver mail and run iterations through it, so the time
// clamp and the dispatch on variable names exist once.
//
// Contract:
// - Mail in: (variable, value as text, time stamp). The engine sees the time clamped to
//   [the last time it was given, `now_s`]: the engine needs non-decreasing times, and mail from
//   a foreign clock (skewed, unwarped) must not reach the future. A caller without a clock of
//   its own (hazard_replay, tests) passes the mail's own time as `now_s`.
// - Dispatch: the variable selects its message module's parser and the engine's handler
//   (NODE_REPORT, UHZ_SENSOR_REQUEST, UHZ_CONFIG_REQUEST, UHZ_CLASSIFY_REQUEST,
//   UHZ_SENSOR_CLEAR, PMV_CONNECT). Unknown variables are ignored; a value longer than
//   kMaxMailValueBytes or one its parser rejects gives one run warning naming the variable and
//   an excerpt of the value, and changes nothing else.
// - Iterations: step(now_s) runs Engine::step at max(now_s, the last time given).
// - Postings out: every call returns the engine's Outputs with the time they belong to.
// Pure like the engine: no I/O, no clock, no sockets.

#include <cstddef>
#include <functional>
#include <optional>
#include <string_view>
#include <utility>

#include "hazard/config.hpp"
#include "hazard/engine.hpp"
#include "hazard/outputs.hpp"

namespace hazard {

/// Longest mail value handled; longer values are refused with a warning (bad-input guard).
inline constexpr std::size_t kMaxMailValueBytes = 64 * 1024;

/// One piece of mail as it arrived.
struct Mail {
  std::string_view variable;
  std::string_view value;  ///< as text (a double in its shortest exact form)
  double time_s = 0.0;     ///< its time stamp
};

/// What one call produced, and the engine time it ran at (the postings' time).
struct TimedOutputs {
  Outputs outputs;
  double time_s = 0.0;
};

class Driver {
 public:
  Driver(EngineSetup setup, SeedChoice seed);
  explicit Driver(Engine engine);

  /// Start-up at `now_s`: the config warnings and, if shown, the object visuals.
  TimedOutputs start(double now_s);
  /// One piece of mail, taken at its time clamped to [last time given, now_s].
  TimedOutputs deliver(const Mail& mail, double now_s);
  /// The same, appended to `out` (a caller's reused Outputs: most mail posts nothing, and an
  /// Outputs returned per piece of mail is five vectors to move and destroy); returns the time.
  double deliver(const Mail& mail, double now_s, Outputs& out);
  /// The same, at the mail's own time (never before the last time given).
  TimedOutputs deliver(const Mail& mail) { return deliver(mail, mail.time_s); }
  /// One iteration at max(now_s, last time given).
  TimedOutputs step(double now_s);
  /// The field's visuals again (Engine::restart_field_visuals): the first batch in the returned
  /// postings, the rest over the next steps. For an app that reconnected to its MOOSDB.
  TimedOutputs restart_field_visuals(double now_s);

  /// The last time given to the engine; nullopt before the first call.
  std::optional<double> last_time_s() const { return last_time_s_; }
  /// The engine, to inspect (its mail handlers are the driver's alone).
  const Engine& engine() const { return engine_; }
  /// Node reports parsed through NodeReportMemo::this_thread() (same results): for a process
  /// whose other readers parse the same texts (hazard_study). Off by default.
  void share_node_report_parses(bool share) { share_node_report_parses_ = share; }
  /// Engine::set_decision_observer.
  void set_decision_observer(std::function<void(const Decision&)> observer) {
    engine_.set_decision_observer(std::move(observer));
  }

 private:
  /// `now_s` raised to the last time given, and recorded as the new last time.
  double advance_to(double now_s);
  void dispatch(std::string_view variable, std::string_view value, double now_s, Outputs& out);

  Engine engine_;
  std::optional<double> last_time_s_;
  bool share_node_report_parses_ = false;
};

}  // namespace hazard
