#pragma once
// NODE_REPORT (docs/messages.md): a vehicle's pose, from the vehicle, bridged to the shoreside.
//
// Example: NAME=archie,X=10,Y=-5,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90,TIME=123,TYPE=kayak
//
// Keys are case-insensitive; commas inside {...} do not split. NAME, X, Y, SPD (or SPEED) and
// HDG (or HEADING) are required and must be finite numbers; the heading is normalised to
// [0, 360) exactly, however large (1e15 -> 280, N3). LAT, LON and TIME are kept when they are
// numbers; other keys are ignored (node reports carry many).
// Position: X and Y when given (LAT/LON are then only kept, as in the original). A report with
// LAT and LON but no X/Y is placed through a GeoPlacement (geodesy.hpp: the mission's
// LatOrigin/LongOrigin and the `geodesy` mode), LAT in [-90, 90] and LON in [-180, 360]; without
// a projection it is rejected with the placement's reason (the original rejected it, T9).

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "base/fmt_fixed.hpp"
#include "hazard/geodesy.hpp"
#include "hazard/messages/parsed.hpp"

namespace hazard {

struct NodeReport {
  // User-provided, so that value-initialisation (optional::emplace()) does not first zero the
  // whole object and then set every member again: a parse per node report.
  NodeReport() {}  // NOLINT(modernize-use-equals-default)

  std::string name;          ///< vehicle name, case-sensitive
  double x_m = 0.0;          ///< local east
  double y_m = 0.0;          ///< local north
  double speed_mps = 0.0;
  double heading_deg = 0.0;  ///< [0, 360)
  std::optional<double> lat_deg;
  std::optional<double> lon_deg;
  std::optional<double> time_s;     ///< the report's own time stamp (unused by the sensor)
  std::optional<std::string> type;  ///< platform type (unused by the sensor)
  /// x_m/y_m were placed from LAT/LON (geodesy), not read from X/Y.
  bool placed_from_lat_lon = false;
};

/// What a parse keeps. kAll: every field above. kPose: what the sensor reads, the name and the
/// placed pose; lat_deg, lon_deg, time_s and type stay empty (their text is not converted,
/// which is a quarter of the parse of a typical report). Both accept and reject the same
/// texts with the same errors, and give the same name and pose.
enum class NodeReportKeep { kAll, kPose };

/// Without geodesy: a LAT/LON-only report is rejected.
Parsed<NodeReport> parse_node_report(std::string_view text);
/// With `placement` (nullptr: none) for LAT/LON-only reports.
Parsed<NodeReport> parse_node_report(std::string_view text, const GeoPlacement* placement,
                                     NodeReportKeep keep = NodeReportKeep::kAll);
/// The parses of one thread's last few node report texts, for several readers of the same texts
/// in one thread (hazard_study hosts the sensor and every manager: each report is read three
/// times). parse() gives what parse_node_report(text, placement) gives, every field kept, by
/// reference: valid until the next parse() on this memo, so a reader takes what it needs
/// before it posts anything that may reach another reader. Only a report placed from its X and
/// Y, which no placement changes, is kept (anything else is parsed anew).
class NodeReportMemo {
 public:
  static NodeReportMemo& this_thread();

  const Parsed<NodeReport>& parse(std::string_view text, const GeoPlacement* placement);
  /// format_node_report(report), its parse kept for this thread's readers: the parse is known
  /// from the writing (a vehicle posting in the same thread as the readers, hazard_study).
  std::string format(const NodeReport& report);
  /// The texts parse() has read itself (not found kept): what the memo saved, for tests.
  std::size_t texts_read() const { return texts_read_; }

 private:
  static constexpr std::size_t kKept = 4;  // the latest reports of a few vehicles
  struct Entry {
    std::string text;
    Parsed<NodeReport> parsed;
    bool direct = false;  ///< kept by format()'s direct writing: its name and type pass its checks
  };

  const Parsed<NodeReport>& keep(std::string_view text, Parsed<NodeReport>&& parsed);
  /// format() for a report the direct writing does not take (through WrittenFields).
  std::string format_general(const NodeReport& report);
  /// The entry replaced next, now holding `text` (its parse is the caller's to set).
  Entry& next_entry(std::string_view text);

  std::array<Entry, kKept> entries_;
  std::size_t used_ = 0;   // entries in use
  std::size_t next_ = 0;   // the entry replaced next
  Parsed<NodeReport> unkept_;  // the last parse that is not kept
  base::LongWholeCache time_whole_;  // the digits of the last TIME's whole seconds
  std::size_t texts_read_ = 0;
};

/// NAME=..,X=FMT(x,2),Y=FMT(y,2),SPD=FMT(s,2),HDG=FMT(h,2)
///   [,LAT=..,LON=..][,TIME=FMT(t,3)][,TYPE=..]
std::string format_node_report(const NodeReport& report);

}  // namespace hazard
