#pragma once
// AppCasting (docs/protocol.md 7.2, docs/uFldHazardSensor.md): the report model of one application,
// its APPCAST string, its terminal frame, and APPCAST_REQ parsing.
//
// Contract:
// - appcast_string() produces exactly the core-moos item sequence of protocol.md 7.2:
//   proc, iter, node (omitted when empty), iter again, messages (each body line followed by
//   `!@`), config_warnings (item text empty when none, separator still written),
//   events_total, events (empty item when none), run_warning_total, run_warnings (omitted with
//   no trailing separator when none). Items are separated by `!@#`, list entries by `!@`.
// - terminal_report() produces the terminal frame: a 62-column header
//   `<proc> <node>` + padding + `<#config>/<#run>(<iteration>)` between two lines of 62 '=',
//   then configuration warnings, run warnings (distinct texts with counts, sorted by text), the
//   body, and the retained events newest first under a 67-'=' banner.
// - Events are stamped `[<seconds since start, 2 decimals>]: text` when reported and the oldest
//   is dropped beyond max_events (default 8, at most 50). Distinct run warnings beyond
//   max_run_warnings (default 10) are counted under "Other Run Warnings". At most 100
//   configuration warnings are kept; later ones are counted in config_warnings_dropped().
// - run_warning_count() is the number of reports still standing: a retraction removes that
//   text and subtracts its count (core-moos AppCast behaviour).

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace moos {

class AppCast {
 public:
  static constexpr std::size_t kDefaultMaxEvents = 8;
  static constexpr std::size_t kMaxEventsLimit = 50;
  static constexpr std::size_t kDefaultMaxRunWarnings = 10;
  static constexpr std::size_t kMaxConfigWarnings = 100;
  static constexpr std::string_view kOtherRunWarnings = "Other Run Warnings";

  void set_proc(std::string proc) { proc_ = std::move(proc); }
  void set_node(std::string node) { node_ = std::move(node); }
  void set_iteration(std::uint64_t iteration) { iteration_ = iteration; }
  /// The application's report body (lines separated by '\n').
  void set_messages(std::string body) { messages_ = std::move(body); }
  /// Clipped to [0, kMaxEventsLimit]; extra retained events are dropped, oldest first.
  void set_max_events(std::size_t max_events);
  void set_max_run_warnings(std::size_t max_run_warnings) { max_run_warnings_ = max_run_warnings; }

  void add_event(const std::string& text, double seconds_since_start);
  void add_config_warning(const std::string& text);
  void add_run_warning(const std::string& text);
  /// Removes a standing run warning with exactly this text; false if there is none.
  bool retract_run_warning(const std::string& text);

  const std::string& proc() const { return proc_; }
  const std::string& node() const { return node_; }
  std::uint64_t iteration() const { return iteration_; }
  const std::string& messages() const { return messages_; }
  const std::deque<std::string>& events() const { return events_; }  ///< oldest first
  std::size_t max_events() const { return max_events_; }
  const std::vector<std::string>& config_warnings() const { return config_warnings_; }
  std::size_t config_warnings_dropped() const { return config_warnings_dropped_; }
  const std::map<std::string, unsigned>& run_warnings() const { return run_warnings_; }
  unsigned run_warning_count() const { return run_warning_count_; }

  std::string appcast_string() const;
  std::string terminal_report() const;

 private:
  std::string proc_;
  std::string node_;
  std::uint64_t iteration_ = 0;
  std::string messages_;
  std::deque<std::string> events_;
  std::size_t max_events_ = kDefaultMaxEvents;
  std::size_t max_run_warnings_ = kDefaultMaxRunWarnings;
  std::vector<std::string> config_warnings_;
  std::size_t config_warnings_dropped_ = 0;
  std::map<std::string, unsigned> run_warnings_;
  unsigned run_warning_count_ = 0;
};

/// One APPCAST_REQ (protocol.md 7.2), e.g.
/// `node=henry,app=pHostInfo,duration=3.0,key=uMAC_438,thresh=any`.
struct AppCastRequest {
  std::string key;             ///< the requester
  double duration_s = 0.0;     ///< MOOS seconds, clipped to [0, 30]
  std::string thresh = "any";  ///< "any" or "run_warning"
};

/// Longest lifetime of a request, MOOS seconds (protocol.md 7.2).
inline constexpr double kMaxAppCastRequestDuration_s = 30.0;

/// Parses a request addressed to `node` / `app` (or to `all`): keys case-insensitive, values
/// compared exactly. nullopt if it is for another node or app, or has no key (protocol.md 7.2).
std::optional<AppCastRequest> parse_appcast_request(std::string_view text, std::string_view node,
                                                    std::string_view app);

}  // namespace moos
