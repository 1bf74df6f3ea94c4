#pragma once
// Swath: the sensor footprint of one vehicle at one pose (rulings D1, D2, "Containment").
//
// Contract: a rectangle centred on the vehicle, `half_width_m` (W, the configured swath width)
// to each side and `length_m` (swath_length) in total along the track, half fore and half aft.
// A point is inside when, in the vehicle frame (offset rotated by minus the heading),
// |along| <= length/2 and |across| <= W, both inclusive. Headings that are exact multiples of
// 90 deg use exact sines and cosines, so axis-aligned swaths have exact edges.
// Corners are listed front-starboard, rear-starboard, rear-port, front-port (spec 8.3 order).
// Headings: degrees, 0 = north (+y), clockwise (90 = east, +x).
// Seam for the swept swath (a later issue): a vehicle's previous and current Swath give the
// area passed over between two node reports; the engine's sensing phase is where it plugs in.

#include <array>

#include <glm/vec2.hpp>

#include "hazard/spatial_grid.hpp"

namespace hazard {

struct SinCos {
  double sin = 0.0;
  double cos = 1.0;
};
/// sin and cos of an angle in degrees; exact at multiples of 90.
SinCos sin_cos_deg(double angle_deg);

class Swath {
 public:
  /// `half_width_m` > 0 and `length_m` > 0 (validated by the configuration); `heading_deg` any
  /// finite value.
  Swath(glm::dvec2 center_m, double heading_deg, double half_width_m, double length_m);

  bool contains(glm::dvec2 point_m) const;
  /// front-starboard, rear-starboard, rear-port, front-port.
  std::array<glm::dvec2, 4> corners() const;
  /// The axis-aligned box around the corners (for the spatial index).
  Box bounds() const;

 private:
  glm::dvec2 center_;
  glm::dvec2 forward_;    ///< unit vector along the heading
  glm::dvec2 starboard_;  ///< unit vector to starboard
  double half_width_m_;
  double half_length_m_;
};

}  // namespace hazard
