#pragma once
// Configuration of the simulated survey vehicle (the uSimSurveyVehicle application): one table of
// parameters (the parser, --help and --example read it) and the route it implies.
//
// Contract
// - Parameters (keys case-insensitive; each bad value is a warning naming parameter and value, and
//   the previous value stays): speed, max_turn_rate, heading_noise, heading_noise_tau,
//   capture_radius, lead, random_seed (vehicle.hpp); region, swath_width, overlap, lane_heading,
//   lane_extension (survey.hpp, lawnmower); waypoints (a point list, used when no region is
//   given); start_x, start_y, start_heading; report_interval (seconds between NODE_REPORTs).
// - The route: the lawnmower over `region` when one is configured (entered at the lane end nearest
//   the start), else `waypoints`, else none (the vehicle stays idle until given a route).

#include <glm/vec2.hpp>

#include <optional>
#include <string>
#include <string_view>
#include "base/result.hpp"
#include <vector>

#include "mission/params.hpp"
#include "mission/polygon.hpp"
#include "mission/survey.hpp"
#include "mission/vehicle.hpp"

namespace mission {

struct SurveyVehicleConfig {
  VehicleParams vehicle;
  LawnmowerOptions lawnmower;            ///< swath_half_width_m is `swath_width`
  std::optional<ConvexPolygon> region;   ///< survey area (lawnmower)
  std::vector<glm::dvec2> waypoints_m;   ///< used when there is no region
  glm::dvec2 start_m{0.0, 0.0};
  double start_heading_deg = 0.0;
  double report_interval_s = 0.25;       ///< NODE_REPORT period (> 0): 4 Hz, as Jake's vehicles
};

const std::vector<ParamInfo>& survey_vehicle_parameters();

/// Applies one `key = value` line, or fails with a warning naming the parameter and value.
base::Result<void> apply_survey_vehicle_param(SurveyVehicleConfig& config, std::string_view key,
                                              std::string_view value);

/// The route described above (an error names the lawnmower option at fault).
base::Result<std::vector<glm::dvec2>> plan_route(const SurveyVehicleConfig& config);

}  // namespace mission
