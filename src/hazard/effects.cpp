#include "hazard/effects.hpp"

#include <algorithm>

#include "hazard/config.hpp"

namespace hazard {

std::vector<std::string_view> Effects::active_names() const {
  std::vector<std::string_view> out;
  const std::pair<bool, std::string_view> all[] = {
      {speed_gate, "speed_gate"},       {turn_blackout, "turn_blackout"},
      {resemblance, "resemblance"},     {aspect, "aspect"},
      {swept_swath, "swept_swath"},     {swath_substeps, "swath_substeps"},
      {geodesy, "geodesy"},
      {swath_visuals, "swath_visuals"}, {detection_visuals, "detection_visuals"},
      {hazard_markers, "hazard_markers"},
  };
  for (const auto& [on, name] : all) {
    if (on) out.push_back(name);
  }
  return out;
}

Effects choose_effects(const EngineConfig& config, const HazardField& field) {
  const auto& objects = field.objects();
  Effects e;
  e.speed_gate = config.max_vehicle_speed_mps.has_value();
  e.turn_blackout = config.max_turn_rate_dps.has_value();
  e.resemblance = !config.ignore_resemblances &&
                  std::any_of(objects.begin(), objects.end(), [](const HazardObject& o) {
                    return !o.is_hazard() && o.resemblance.has_value();
                  });
  e.aspect = !config.ignore_aspect &&
             std::any_of(objects.begin(), objects.end(),
                         [](const HazardObject& o) { return o.has_aspect_triple(); });
  e.swept_swath = config.swath_sweep;
  e.swath_substeps = !config.swath_sweep && config.swath_substeps > 0;
  e.geodesy = config.origin.has_value() && config.geodesy != GeodesyMode::kOff;
  e.swath_visuals = config.show_swath;
  e.detection_visuals = config.show_detections.enabled;
  e.hazard_markers = config.show_hazards;
  return e;
}

}  // namespace hazard
