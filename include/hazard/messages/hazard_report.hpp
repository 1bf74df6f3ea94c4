#pragma once
// UHZ_HAZARD_REPORT and UHZ_HAZARD_REPORT_<V> (differences.md D25, "Report payloads"): a released
// classification answer; `type` is the perceived type, which may be wrong.
//
// Examples: UHZ_HAZARD_REPORT        = vname=archie,x=-52,y=-290,label=75,type=hazard
//           UHZ_HAZARD_REPORT_ARCHIE = x=-52,y=-290,label=75,type=hazard
//
// vname first when present, then x, y (FMT(.,2)), label, type, then the aspect fields the object
// has. The parser accepts both variants; x, y, label and type (hazard or benign) are required.

#include <optional>
#include <string>
#include <string_view>

#include "hazard/hazard_object.hpp"
#include "hazard/messages/parsed.hpp"

namespace hazard {

struct HazardReport {
  std::optional<std::string> vname;  ///< set in the general variant only
  double x_m = 0.0;
  double y_m = 0.0;
  std::string label;
  ObjectType type = ObjectType::kBenign;  ///< as perceived by the classifier
  std::optional<double> aspect_deg;
  std::optional<double> aspect_min_deg;
  std::optional<double> aspect_max_deg;
};

Parsed<HazardReport> parse_hazard_report(std::string_view text);
std::string format_hazard_report(const HazardReport& report);

}  // namespace hazard
