#pragma once
// HAZARDSET_REPORT (docs/mission-logic.md): a vehicle's final answer, the set of objects it
// declares hazards.
//
// Example: source=archie#name=archie#x=-52,y=-290,label=75#x=41,y=-108,label=53
//
// Format: '#'-separated parts. `source=<vehicle>` first, then optional `name=<report name>`,
// optional `xpath=FMT(x,1)` (the minimum-hazard transit lane), optional `search_region=pts={...}`
// (final reports omit it), then one part per reported object: the object spec of
// docs/hazard-file.md with
// hr, type, width and color suppressed, i.e. `x=FMT(x,2),y=FMT(y,2),label=<label>` followed by
// `aspect=FMT,aspect_min=FMT,aspect_max=FMT` for the aspect fields the object has (the
// detection report carries them, differences.md "Report payloads"). Shape is never known
// vehicle-side.
//
// Parsing follows the original uFldHazardMetric, quirks included (see docs/mission-logic.md):
// - a part whose text begins with `source`, `name`, `transit_path_width` or `search_region` is
//   metadata (a prefix test, as the original's strBegins); `xpath=` is NOT in that list, so an
//   `xpath=...` part is taken as an object without label or position: it counts in total_objects
//   and never matches a truth label. We keep this: it changes no score, and a grader that counted
//   differently from the original would disagree with existing missions' logs.
// - every other part is an object, whatever its keys: x and y are kept when they are numbers,
//   label when present; other keys (type, aspect, ...) are ignored. Unlike the original, an empty
//   part (a doubled or trailing '#') is skipped instead of becoming an empty object.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mission {

inline constexpr const char* kHazardsetReportVar = "HAZARDSET_REPORT";

struct ReportedObject {
  std::optional<std::string> label;
  std::optional<double> x_m;
  std::optional<double> y_m;
  std::optional<double> aspect_deg;
  std::optional<double> aspect_min_deg;
  std::optional<double> aspect_max_deg;
};

/// A labelled object at (x, y) without aspect fields.
ReportedObject reported_object(std::string label, double x_m, double y_m);

struct HazardsetReport {
  std::string source;                       ///< reporting vehicle ("" when the part is missing)
  std::string name;                         ///< report name, "" when absent
  std::optional<double> xpath_m;            ///< written by the formatter only (see quirk above)
  std::optional<std::string> search_region; ///< `pts={...}` text, when present
  std::vector<ReportedObject> objects;

  /// True if some object carries this label (the grader's match rule, docs/mission-logic.md).
  bool has_label(std::string_view label) const;
};

/// Never fails: every part is either metadata or an object (see the quirks above).
HazardsetReport parse_hazardset_report(std::string_view text);
/// Objects without label or position are written with the fields they have.
std::string format_hazardset_report(const HazardsetReport& report);

}  // namespace mission
