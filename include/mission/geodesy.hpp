#pragma once
// Local x/y (metres east/north of a datum) <-> latitude/longitude, for the LAT and LON fields of
// the simulated vehicle's NODE_REPORT (LatOrigin/LongOrigin of the .moos file).
//
// Choice: GeographicLib::LocalCartesian on the WGS84 ellipsoid, datum at height 0. x is east and
// y north in the plane tangent to the ellipsoid at the datum; a point is placed at height 0
// above the ellipsoid (its tangent-plane height is dropped). This is exact (no series), needs
// nothing but the origin, and round-trips a local point to well under 1 mm within a few
// kilometres of the datum (the dropped height is r^2/(2R), about 8 cm at 1 km, and it moves the
// point horizontally by its product with r/R, about 0.01 mm at 1 km).
// Difference from MOOS: the original's CMOOSGeodesy works in UTM (or a flat-earth local grid);
// the two agree to a few centimetres over a mission area of a kilometre, which no hazard test
// can see. We never read LAT/LON back in the sensor (docs/messages.md, NODE_REPORT: LAT/LON-only
// reports are invalid), so they are for viewers and logs.

#include <GeographicLib/LocalCartesian.hpp>
#include <glm/vec2.hpp>

namespace mission {

struct GeoPoint {
  double lat_deg = 0.0;  ///< [-90, 90]
  double lon_deg = 0.0;  ///< [-180, 180)
};

class LocalGeodesy {
 public:
  /// origin: the datum (LatOrigin, LongOrigin) in degrees; lat in [-90, 90].
  explicit LocalGeodesy(GeoPoint origin);

  /// Latitude/longitude of a local point (x east, y north, metres).
  GeoPoint to_geo(glm::dvec2 local_m) const;
  /// Local point of a latitude/longitude (height 0).
  glm::dvec2 to_local(GeoPoint geo) const;

  GeoPoint origin() const { return origin_; }

 private:
  GeoPoint origin_;
  GeographicLib::LocalCartesian frame_;
};

}  // namespace mission
