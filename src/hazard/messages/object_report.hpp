#pragma once
// Private: the part detection and hazard reports share (position, label, aspect fields).

#include <optional>
#include <string>

#include "fields.hpp"

namespace hazard::detail {

struct ObjectReportFields {
  std::optional<std::string> vname;
  double x_m = 0.0;
  double y_m = 0.0;
  std::string label;
  std::optional<double> aspect_deg, aspect_min_deg, aspect_max_deg;
};

/// Reads vname (optional), x, y, label and the aspect fields; empty string on success.
std::string read_object_report(const Fields& f, ObjectReportFields& out);
/// "vname=..," (if set) + "x=..,y=..,label=.." ; `type` (if not empty) after the label; then the
/// aspect fields.
std::string write_object_report(const ObjectReportFields& r, std::string_view type);

}  // namespace hazard::detail
