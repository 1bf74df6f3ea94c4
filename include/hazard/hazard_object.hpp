#pragma once
// One object of the ground-truth field (manual section 5, docs/hazard-file.md), as typed values.

#include <optional>
#include <string>

namespace hazard {

enum class ObjectType { kHazard, kBenign };

/// "hazard" or "benign".
const char* type_name(ObjectType type);

struct HazardObject {
  double x_m = 0.0;  ///< local east (m)
  double y_m = 0.0;  ///< local north (m)
  std::string label; ///< unique in the field, non-empty, no ','
  ObjectType type = ObjectType::kBenign;
  /// Hazard resemblance in [0, 1] (manual 6). Kept on hazards too, where it has no effect.
  std::optional<double> resemblance;
  /// Optimal aspect in [0, 360) deg; full-performance half window and fully-degraded threshold,
  /// both in [0, 90] deg with min <= max and min + max <= 90 (manual 7, differences.md
  /// "Validation").
  std::optional<double> aspect_deg;
  std::optional<double> aspect_min_deg;
  std::optional<double> aspect_max_deg;
  // Rendering hints (manual 5; validated words, width >= 0 m).
  std::optional<std::string> color;
  std::optional<std::string> shape;
  std::optional<double> marker_width_m;
  std::optional<std::string> source;  ///< free text, never used by the sensor

  bool is_hazard() const { return type == ObjectType::kHazard; }
  /// All three aspect fields present: the object is aspect-sensitive (manual 7).
  bool has_aspect_triple() const {
    return aspect_deg.has_value() && aspect_min_deg.has_value() && aspect_max_deg.has_value();
  }
};

}  // namespace hazard
