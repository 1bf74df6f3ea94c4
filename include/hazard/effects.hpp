#pragma once
// Effects: the parts of the sensor model a scene actually uses, decided once at construction.
//
// Contract: choose_effects() looks at the configuration and the field and switches on only what
// the scene needs; the engine computes, stores and allocates nothing for an effect that is off
// (no heading history without the turn gate, no aspect arithmetic without aspect objects, no
// visual strings without the show_* switches). active_names() lists what is on, in a fixed
// order, for the report header.
//   speed_gate         max_vehicle_speed is not `off`                      (manual 9)
//   turn_blackout      max_turn_rate is not `off`; keeps a 2 s heading history (manual 8)
//   resemblance        some benign object has hr and ignore_resemblances is false (manual 6)
//   aspect             some object has aspect, aspect_min and aspect_max (manual 7)
//   swath_visuals      show_swath                                           (manual 7.5)
//   detection_visuals  show_detections is not 0 (detection and classification circles)
//   hazard_markers     show_hazards                                         (manual 7.6)
// Seams for a later issue (never on yet): swept_swath (an object counts as entering when the
// swath passed over it between two node reports) and geodesy (LAT/LON node reports and lat=/lon=
// hazard lines through GeographicLib around LatOrigin/LongOrigin).

#include <string_view>
#include <vector>

namespace hazard {

struct EngineConfig;
class HazardField;

struct Effects {
  bool speed_gate = false;
  bool turn_blackout = false;
  bool resemblance = false;
  bool aspect = false;
  bool swath_visuals = false;
  bool detection_visuals = false;
  bool hazard_markers = false;
  bool swept_swath = false;  ///< seam, not implemented
  bool geodesy = false;      ///< seam, not implemented

  std::vector<std::string_view> active_names() const;
};

Effects choose_effects(const EngineConfig& config, const HazardField& field);

}  // namespace hazard
