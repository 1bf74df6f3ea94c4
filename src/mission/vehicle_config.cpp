#include "mission/vehicle_config.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "base/text.hpp"

namespace mission {

namespace {

/// Where a numeric parameter lives in the configuration.
using Field = double& (*)(SurveyVehicleConfig&);

using Applied = base::Result<void>;

struct Row {
  ParamInfo info;
  std::function<Applied(SurveyVehicleConfig&, std::string_view)> apply;
};

bool positive(double v) { return v > 0.0; }
bool non_negative(double v) { return v >= 0.0; }
bool any(double) { return true; }
bool fraction_below_one(double v) { return v >= 0.0 && v < 1.0; }

// A numeric row whose value must satisfy `ok`; `rule` is the sentence shown otherwise.
Row number_row(ParamInfo info, bool (*ok)(double), const char* rule, Field field) {
  auto apply = [info, ok, rule, field](SurveyVehicleConfig& c, std::string_view value) {
    const auto v = base::parse_number(value);
    const std::string name(info.name);
    if (!v) return Applied::fail("parameter " + name + "='" + std::string(value) +
                                 "' is not a number");
    if (!ok(*v)) return Applied::fail("parameter " + name + "=" + base::fmt(*v, 6) + " " + rule);
    field(c) = *v;
    return Applied::ok();
  };
  return {info, apply};
}

// A parameter whose value is a point list (a region or a route).
template <class Apply>
Row points_row(ParamInfo info, Apply apply) {
  return {info, [info, apply](SurveyVehicleConfig& c, std::string_view value) {
            Applied applied = apply(c, value);
            if (!applied)
              applied.error = "parameter " + std::string(info.name) + ": " + applied.error;
            return applied;
          }};
}

const std::vector<Row>& rows() {
  using C = SurveyVehicleConfig;
  static const std::vector<Row> table = {
      number_row({"speed", "1.5", "cruise speed, m/s (> 0)"}, positive, "must be > 0",
                 [](C& c) -> double& { return c.vehicle.speed_mps; }),
      number_row({"max_turn_rate", "10", "turn-rate limit, deg/s (> 0)"}, positive, "must be > 0",
                 [](C& c) -> double& { return c.vehicle.max_turn_rate_dps; }),
      number_row({"heading_noise", "0", "heading disturbance std, deg (>= 0; 0 = off)"},
                 non_negative, "must be >= 0",
                 [](C& c) -> double& { return c.vehicle.heading_noise_deg; }),
      number_row({"heading_noise_tau", "20", "correlation time of the disturbance, s (> 0)"},
                 positive, "must be > 0",
                 [](C& c) -> double& { return c.vehicle.heading_noise_tau_s; }),
      number_row({"capture_radius", "5", "waypoint reached within this distance, m (>= 0)"},
                 non_negative, "must be >= 0",
                 [](C& c) -> double& { return c.vehicle.capture_radius_m; }),
      number_row({"lead", "15", "look-ahead along the track line, m (> 0)"}, positive,
                 "must be > 0", [](C& c) -> double& { return c.vehicle.lead_m; }),
      {{"random_seed", "1", "heading-noise seed (whole number)"},
       [](C& c, std::string_view value) {
         const auto v = base::parse_unsigned(value);
         if (!v) {
           return Applied::fail("parameter random_seed='" + std::string(value) +
                                "' is not a whole number");
         }
         c.vehicle.seed = *v;
         return Applied::ok();
       }},
      points_row({"region", "", "survey area, convex polygon (lawnmower)"},
                 [](C& c, std::string_view value) {
                   auto parsed = ConvexPolygon::parse(value);
                   if (!parsed) return Applied::fail(std::move(parsed.error));
                   c.region = std::move(parsed.value);
                   return Applied::ok();
                 }),
      number_row({"swath_width", "25", "sensor W (m to each side) the lanes are spaced for (> 0)"},
                 positive, "must be > 0",
                 [](C& c) -> double& { return c.lawnmower.swath_half_width_m; }),
      number_row({"overlap", "0.1", "fraction of the swath shared by neighbouring lanes, [0, 1)"},
                 fraction_below_one, "must be in [0, 1)",
                 [](C& c) -> double& { return c.lawnmower.overlap; }),
      number_row({"lane_heading", "0", "direction of the lanes, deg (0 = north-south)"}, any, "",
                 [](C& c) -> double& { return c.lawnmower.lane_heading_deg; }),
      number_row({"lane_extension", "20", "straight run beyond the region at lane ends, m (>= 0)"},
                 non_negative, "must be >= 0",
                 [](C& c) -> double& { return c.lawnmower.lane_extension_m; }),
      points_row({"waypoints", "", "route when there is no region: pts={x1,y1:x2,y2:...}"},
                 [](C& c, std::string_view value) {
                   auto parsed = parse_points(value);
                   if (!parsed) return Applied::fail(std::move(parsed.error));
                   c.waypoints_m = std::move(*parsed.value);
                   return Applied::ok();
                 }),
      number_row({"start_x", "0", "start position east, m"}, any, "",
                 [](C& c) -> double& { return c.start_m.x; }),
      number_row({"start_y", "0", "start position north, m"}, any, "",
                 [](C& c) -> double& { return c.start_m.y; }),
      number_row({"start_heading", "0", "start heading, deg"}, any, "",
                 [](C& c) -> double& { return c.start_heading_deg; }),
      number_row({"report_interval", "0.25", "seconds between NODE_REPORT postings (> 0)"},
                 positive, "must be > 0", [](C& c) -> double& { return c.report_interval_s; }),
  };
  return table;
}

}  // namespace

const std::vector<ParamInfo>& survey_vehicle_parameters() {
  static const std::vector<ParamInfo> infos = param_infos(rows());
  return infos;
}

Applied apply_survey_vehicle_param(SurveyVehicleConfig& config, std::string_view key,
                                   std::string_view value) {
  const std::string name = base::to_lower(base::trim(key));
  for (const Row& r : rows())
    if (name == r.info.name) return r.apply(config, base::trim(value));
  return Applied::fail("unknown parameter '" + std::string(base::trim(key)) + "'");
}

base::Result<std::vector<glm::dvec2>> plan_route(const SurveyVehicleConfig& config) {
  using R = base::Result<std::vector<glm::dvec2>>;
  if (!config.region) return R::ok(config.waypoints_m);
  LawnmowerOptions options = config.lawnmower;
  options.start_m = config.start_m;
  base::Result<LawnmowerPlan> plan = plan_lawnmower(*config.region, options);
  if (!plan) return R::fail(std::move(plan.error));
  return R::ok(std::move(plan.value->waypoints_m));
}

}  // namespace mission
