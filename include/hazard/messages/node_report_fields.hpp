#pragma once
// The keys parse_node_report reads, found in one pass over a NODE_REPORT text (public for the
// differential test that holds the scan to base::split_key_values's rule).
//
// Why a dedicated scan: every vehicle posts a report ten times a second and every report is
// read by the sensor and every manager. The generic reader finds a piece's end, then trims and
// compares its key, then parse_number walks the value again. Here a number is read as the scan
// passes over it: the digits that end at ',' are the value's end and its number in one walk.
//
// The rule is base::split_key_values(text, ',', /*respect_braces=*/true)'s: keys compare
// case-insensitively, both sides are trimmed, a piece without '=' is no value, a repeated key:
// the last one wins.

#include <string_view>

namespace hazard {

/// One key's value text; `has_number` when the scan read it as a plain decimal, and then
/// `number` is what base::parse_number(text) gives (anything else is left to parse_number).
struct NodeReportField {
  std::string_view text;
  bool present = false;
  bool has_number = false;
  double number = 0.0;
};

struct NodeReportFields {
  NodeReportField name, x, y, spd, speed, hdg, heading, lat, lon, time, type;

  NodeReportFields() = default;  ///< none present (a writer fills what it wrote)
  /// `pose_only`: LAT, LON and TIME are found but not read as numbers (the engine's parse,
  /// NodeReportKeep::kPose, does not convert them).
  explicit NodeReportFields(std::string_view text, bool pose_only = false);
};

}  // namespace hazard
