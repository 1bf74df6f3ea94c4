#pragma once
// Swath: the sensor footprint of one vehicle at one pose (differences.md D1, D2, "Containment").
//
// Contract: a rectangle centred on the vehicle, `half_width_m` (W, the configured swath width)
// to each side and `length_m` (swath_length) in total along the track, half fore and half aft.
// The inclusive rule (one rule for edges and corners, at every heading and every coordinate
// size): a point is inside when, in the vehicle frame (offset = point - centre, rotated by
// minus the heading), |along| <= length/2 + e and |across| <= W + e, where e = 2^-50 (four
// units in the last place) of |x| + |y| of the centre plus W + length/2. e only absorbs the
// rounding of a point computed to lie on an edge or a corner (1e-14 m near the origin, 1e-8 m
// at 1e7 m), so such a point is inside at headings 45 or 137.5 as it is at 0 or 90, while a
// point 1 micrometre outside is outside at any coordinate up to 1e8 m. The offset is taken
// before rotating, so the test has the same outcome at UTM coordinates (x = 6e5, y = 4.8e6)
// as at the origin: subtracting two nearby doubles is exact (Sterbenz).
// Headings that are exact multiples of 90 deg use exact sines and cosines, so axis-aligned
// swaths have exact edges. Corners are listed front-starboard, rear-starboard, rear-port,
// front-port (the original's order). Headings: degrees, 0 = north (+y), clockwise (90 = east,
// +x).
// Swept test (swath_sweep, sensing_track.hpp): the swath translated along a displacement at a
// fixed heading covers a point when some t in [0, 1] puts the point inside the translated
// rectangle under the same rule; in the swath's frame that is two 1-D interval conditions on t
// (a slab test), exact for straight motion.

#include <array>

#include <glm/vec2.hpp>

#include "hazard/spatial_grid.hpp"

namespace hazard {

/// Radians per degree.
inline constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;

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

  /// The inclusive rule above.
  bool contains(glm::dvec2 point_m) const;
  /// True when the swath translated by t * `displacement_m` (heading fixed) contains `point_m`
  /// for some t in [0, 1], under the inclusive rule (slab test; exact for straight motion).
  bool swept_contains(glm::dvec2 displacement_m, glm::dvec2 point_m) const;
  /// The rounding allowance e of the inclusive rule, metres.
  double tolerance_m() const { return tolerance_m_; }
  glm::dvec2 center() const { return center_; }
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
  double tolerance_m_;
};

}  // namespace hazard
