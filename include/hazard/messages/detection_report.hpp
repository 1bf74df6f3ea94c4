#pragma once
// UHZ_DETECTION_REPORT and UHZ_DETECTION_REPORT_<V> (differences.md D24, "Report payloads").
//
// Examples: UHZ_DETECTION_REPORT        = vname=archie,x=-52,y=-290,label=75
//           UHZ_DETECTION_REPORT_ARCHIE = x=-52,y=-290,label=75
//           with aspect data:
//             vname=archie,x=37,y=-207,label=99,aspect=57,aspect_min=20,aspect_max=45
//
// vname first when present (the general variable), then x, y (FMT(.,2)), label, then the aspect
// fields the object has. The parser accepts both variants (vname optional) and ignores unknown
// keys; x, y and label are required.

#include <optional>
#include <string>
#include <string_view>

#include "hazard/messages/parsed.hpp"

namespace hazard {

struct DetectionReport {
  std::optional<std::string> vname;  ///< set in the general variant only
  double x_m = 0.0;
  double y_m = 0.0;
  std::string label;
  std::optional<double> aspect_deg;
  std::optional<double> aspect_min_deg;
  std::optional<double> aspect_max_deg;
};

Parsed<DetectionReport> parse_detection_report(std::string_view text);
std::string format_detection_report(const DetectionReport& report);

/// The general variant from the vehicle's text (a detection or hazard report formatted without
/// vname): "vname=NAME," in front, exactly what the format functions write with vname set. The
/// engine posts both variants and formats the numbers once.
std::string with_vname(std::string_view vname, std::string_view vehicle_report);

}  // namespace hazard
