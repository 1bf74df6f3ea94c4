#pragma once
// The aspect fields a detection or hazard report carries (internal to libhazard).

#include "hazard/hazard_field.hpp"

namespace hazard {

/// Copies an object's aspect fields into `report` (DetectionReport or HazardReport); an object
/// without them (nullptr) leaves the report's fields empty.
template <typename Report>
void set_aspect(Report& report, const HazardField::Aspect* aspect) {
  if (!aspect) return;
  report.aspect_deg = aspect->aspect_deg;
  report.aspect_min_deg = aspect->aspect_min_deg;
  report.aspect_max_deg = aspect->aspect_max_deg;
}

}  // namespace hazard
