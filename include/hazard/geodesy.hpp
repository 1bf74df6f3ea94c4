#pragma once
// Geodesy: latitude/longitude placed in the local frame (x east, y north, metres) around the
// mission's LatOrigin/LongOrigin (the original had none; docs/messages.md, NODE_REPORT).
//
// Contract: a LocalProjection is built once from a valid origin and a mode, and to_local() is a
// pure function of (lat, lon) on the WGS84 ellipsoid, at height 0. The modes (parameter
// `geodesy`; accuracy and cost measured in docs/accuracy.md):
//   tangent    a fast local tangent plane: x = N(lat0) cos(lat0) dlon, y = M(lat0) dlat, with the
//              prime-vertical and meridional radii of curvature at the origin (no trigonometry
//              per point). Error grows with distance^2: centimetres at 1 km, metres at 10 km.
//   enu        GeographicLib::LocalCartesian: the exact east/north plane tangent to the ellipsoid
//              at the origin (geodetic -> geocentric -> rotated; the up component dropped). The
//              default, and what the mission's vehicle simulator uses to write LAT/LON.
//   azimuthal  GeographicLib::AzimuthalEquidistant: the point at geodesic distance s and
//              azimuth a from the origin lands at (s sin a, s cos a), exactly.
//   utm        GeographicLib::TransverseMercator::UTM() in the origin's standard UTM zone (Norway
//              and Svalbard exceptions included), relative to the origin's own UTM position: the
//              local-UTM convention of MOOS geodesy. Krueger series, 5 nm within 3900 km of the
//              zone's central meridian; scale 0.9996 on that meridian, so UTM distances differ
//              from ground distances by up to 0.04 % near the origin.
// Inputs are validated at the edge (parse_node_report, parse_hazard_line, the origin loader):
// latitudes in [-90, 90], longitudes in [-180, 360]; the longitude difference to the origin is
// taken exactly across the antimeridian (GeographicLib::Math::AngDiff).
// Rejected alternative: GeographicLib::UTMUPS (it switches hemispheres and zones, so a local
// frame would jump by 10,000 km at the equator).

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <glm/vec2.hpp>

namespace hazard {

enum class GeodesyMode { kOff, kTangent, kEnu, kAzimuthal, kUtm };

/// "off", "tangent", "enu", "azimuthal", "utm".
const char* geodesy_mode_name(GeodesyMode mode);
/// The mode a word names (case-insensitive), nullopt for any other word.
std::optional<GeodesyMode> parse_geodesy_mode(std::string_view word);

/// Latitude in [-90, 90] deg (the domain of every projection).
bool valid_latitude(double lat_deg);
/// Longitude in [-180, 360] deg (MOOS writes [-180, 180]; some logs write [0, 360)).
bool valid_longitude(double lon_deg);

/// The mission's LatOrigin / LongOrigin, degrees.
struct GeodeticOrigin {
  double lat_deg = 0.0;  ///< [-90, 90]
  double lon_deg = 0.0;  ///< [-180, 360]
};

class LocalProjection {
 public:
  /// `origin` valid (see valid_latitude / valid_longitude); `mode` not kOff.
  LocalProjection(GeodeticOrigin origin, GeodesyMode mode);

  /// The local position of a point at height 0: x east, y north, metres. `lat_deg` valid,
  /// `lon_deg` valid. The origin maps to (0, 0) (exactly for tangent and utm; within 1e-9 m
  /// for enu and azimuthal).
  glm::dvec2 to_local(double lat_deg, double lon_deg) const;

 private:
  struct Impl;
  GeodesyMode mode_;
  std::shared_ptr<const Impl> impl_;  ///< immutable, so copies share it
};

/// How the parsers place a position given only as latitude/longitude: through `projection`, or
/// not at all, and then `unavailable` says why (it ends the parser's warning).
struct GeoPlacement {
  std::optional<LocalProjection> projection;
  std::string unavailable = "the mission file gives no LatOrigin and LongOrigin";
};

}  // namespace hazard
