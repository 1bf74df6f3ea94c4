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
  // Any object meeting `test`, by id (the field is stored as tables, not objects).
  const auto any_object = [&](auto test) {
    for (ObjectId id = 0; id < field.size(); ++id)
      if (test(id)) return true;
    return false;
  };
  Effects e;
  e.speed_gate = config.max_vehicle_speed_mps.has_value();
  e.turn_blackout = config.max_turn_rate_dps.has_value();
  e.resemblance = !config.ignore_resemblances &&
                  any_object([&](ObjectId id) {
                    return !field.is_hazard(id) && field.resemblance(id).has_value();
                  });
  e.aspect = !config.ignore_aspect &&
             any_object([&](ObjectId id) { return field.has_aspect_triple(id); });
  e.swept_swath = config.swath_sweep;
  e.swath_substeps = !config.swath_sweep && config.swath_substeps > 0;
  e.geodesy = config.origin.has_value() && config.geodesy != GeodesyMode::kOff;
  e.swath_visuals = config.show_swath;
  e.detection_visuals = config.show_detections.enabled;
  e.hazard_markers = config.show_hazards;
  return e;
}

Effects for_readers(Effects effects, PostingReaders readers) {
  if (readers == PostingReaders::kReportCounts) {
    effects.swath_visuals = false;
    effects.detection_visuals = false;
    effects.hazard_markers = false;
  }
  return effects;
}

}  // namespace hazard
