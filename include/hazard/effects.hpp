#pragma once
// Effects: the parts of the sensor model a scene actually uses, decided once at construction.
//
// Contract: choose_effects() looks at the configuration and the field and switches on only what
// the scene needs; the engine computes, stores and allocates nothing for an effect that is off
// (no heading history without the turn gate, no aspect arithmetic without aspect objects, no
// track of poses without sweeping or sub-stepping, no projection without geodesy, no visual
// strings without the show_* switches). active_names() lists what is on, in a fixed order, for
// the report header. Every effect has a switch, so a scene that does not use an effect gives
// byte-identical outputs with the switch either way (tests/hazard/effects_switch_test.cpp):
//   speed_gate         max_vehicle_speed is not `off`                      (manual 9)
//   turn_blackout      max_turn_rate is not `off`; keeps a 2 s heading history (manual 8)
//   resemblance        some benign object has hr and ignore_resemblances is false (manual 6)
//   aspect             some object has aspect, aspect_min and aspect_max and ignore_aspect is
//                      false (manual 7; ignore_aspect is an extension)
//   swept_swath        swath_sweep = true: the swath swept between node reports (an extension)
//   swath_substeps     swath_substeps = N > 0 and no sweep: N poses per report interval
//   geodesy            the mission gives a usable LatOrigin/LongOrigin and geodesy is not `off`:
//                      LAT/LON-only node reports are placed (lat/lon hazard lines are placed at
//                      load time, by the same projection)
//   swath_visuals      show_swath                                           (manual 7.5)
//   detection_visuals  show_detections is not 0 (detection and classification circles)
//   hazard_markers     show_hazards                                         (manual 7.6)
// Costs per effect are measured in docs/effects.md (bench/engine/effects_bench).
// Who reads the postings can switch the visual effects off too (PostingReaders, below).

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
  bool swept_swath = false;
  bool swath_substeps = false;
  bool geodesy = false;

  std::vector<std::string_view> active_names() const;
};

Effects choose_effects(const EngineConfig& config, const HazardField& field);

/// Who reads the engine's postings. kViewers: they go to MOOS or to a log, where a viewer may
/// draw them; the visual effects are as configured. kReportCounts: only which reports were
/// posted is read (a study over seeds, hazard_replay --seeds), never a posting's text.
enum class PostingReaders { kViewers, kReportCounts };

/// `effects` as `readers` need them: for kReportCounts the visual effects (swath_visuals,
/// detection_visuals, hazard_markers) are off, so no VIEW_* text is built. A visual only posts
/// (it rolls no die and changes no state), so every other posting, event, warning and die
/// outcome is the same either way (tests/hazard/posting_readers_test.cpp).
Effects for_readers(Effects effects, PostingReaders readers);

}  // namespace hazard
