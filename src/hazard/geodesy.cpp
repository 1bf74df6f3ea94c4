#include "hazard/geodesy.hpp"

#include <cmath>

#include <GeographicLib/AzimuthalEquidistant.hpp>
#include <GeographicLib/Constants.hpp>
#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/LocalCartesian.hpp>
#include <GeographicLib/Math.hpp>
#include <GeographicLib/TransverseMercator.hpp>
#include <GeographicLib/UTMUPS.hpp>

#include "base/text.hpp"

namespace hazard {

namespace {

constexpr double kMaxLatitudeDeg = 90.0;
constexpr double kMinLongitudeDeg = -180.0;
constexpr double kMaxLongitudeDeg = 360.0;
// UTM zone z has its central meridian at 6 z - 183 deg (zones 1..60 from 180 W).
constexpr double kUtmZoneWidthDeg = 6.0;
constexpr double kUtmZoneOffsetDeg = 183.0;

struct Word {
  GeodesyMode mode;
  const char* name;
};
constexpr Word kWords[] = {{GeodesyMode::kOff, "off"},
                           {GeodesyMode::kTangent, "tangent"},
                           {GeodesyMode::kEnu, "enu"},
                           {GeodesyMode::kAzimuthal, "azimuthal"},
                           {GeodesyMode::kUtm, "utm"}};

}  // namespace

const char* geodesy_mode_name(GeodesyMode mode) {
  for (const Word& w : kWords) {
    if (w.mode == mode) return w.name;
  }
  return "";
}

std::optional<GeodesyMode> parse_geodesy_mode(std::string_view word) {
  for (const Word& w : kWords) {
    if (base::iequals(base::trim(word), w.name)) return w.mode;
  }
  return std::nullopt;
}

bool valid_latitude(double lat_deg) {
  return std::isfinite(lat_deg) && std::fabs(lat_deg) <= kMaxLatitudeDeg;
}

bool valid_longitude(double lon_deg) {
  return std::isfinite(lon_deg) && lon_deg >= kMinLongitudeDeg && lon_deg <= kMaxLongitudeDeg;
}

// One implementation per mode; only the one in use is built.
struct LocalProjection::Impl {
  explicit Impl(GeodeticOrigin o, GeodesyMode mode) : origin(o) {
    using GeographicLib::Constants;
    switch (mode) {
      case GeodesyMode::kTangent: {
        // Radii of curvature at the origin (any geodesy text, e.g. Karney's GeographicLib
        // documentation): N = a / W, M = a (1 - e^2) / W^3, W = sqrt(1 - e^2 sin^2 lat0).
        const double a = Constants::WGS84_a();
        const double f = Constants::WGS84_f();
        const double e2 = f * (2.0 - f);
        const double s = GeographicLib::Math::sind(o.lat_deg);
        const double w = std::sqrt(1.0 - e2 * s * s);
        const double deg = GeographicLib::Math::degree();
        north_m_per_deg = a * (1.0 - e2) / (w * w * w) * deg;
        east_m_per_deg = a / w * GeographicLib::Math::cosd(o.lat_deg) * deg;
        break;
      }
      case GeodesyMode::kEnu:
        enu.emplace(o.lat_deg, o.lon_deg, 0.0, GeographicLib::Geocentric::WGS84());
        break;
      case GeodesyMode::kAzimuthal:
        azimuthal.emplace(GeographicLib::Geodesic::WGS84());
        break;
      case GeodesyMode::kUtm: {
        const int zone = GeographicLib::UTMUPS::StandardZone(o.lat_deg, o.lon_deg,
                                                             GeographicLib::UTMUPS::UTM);
        central_meridian_deg = kUtmZoneWidthDeg * zone - kUtmZoneOffsetDeg;
        double gamma = 0, k = 0;
        GeographicLib::TransverseMercator::UTM().Forward(central_meridian_deg, o.lat_deg,
                                                         o.lon_deg, utm_origin.x, utm_origin.y,
                                                         gamma, k);
        break;
      }
      case GeodesyMode::kOff:
        break;
    }
  }

  glm::dvec2 to_local(GeodesyMode mode, double lat_deg, double lon_deg) const {
    switch (mode) {
      case GeodesyMode::kTangent:
        return {east_m_per_deg * GeographicLib::Math::AngDiff(origin.lon_deg, lon_deg),
                north_m_per_deg * (lat_deg - origin.lat_deg)};
      case GeodesyMode::kEnu: {
        double x = 0, y = 0, z = 0;
        enu->Forward(lat_deg, lon_deg, 0.0, x, y, z);
        return {x, y};
      }
      case GeodesyMode::kAzimuthal: {
        double x = 0, y = 0, azimuth = 0, scale = 0;
        azimuthal->Forward(origin.lat_deg, origin.lon_deg, lat_deg, lon_deg, x, y, azimuth,
                           scale);
        return {x, y};
      }
      case GeodesyMode::kUtm: {
        double x = 0, y = 0, gamma = 0, k = 0;
        GeographicLib::TransverseMercator::UTM().Forward(central_meridian_deg, lat_deg, lon_deg,
                                                         x, y, gamma, k);
        return {x - utm_origin.x, y - utm_origin.y};
      }
      case GeodesyMode::kOff:
        break;
    }
    return {0.0, 0.0};
  }

  GeodeticOrigin origin;
  double north_m_per_deg = 0.0;  // tangent
  double east_m_per_deg = 0.0;
  std::optional<GeographicLib::LocalCartesian> enu;
  std::optional<GeographicLib::AzimuthalEquidistant> azimuthal;
  double central_meridian_deg = 0.0;  // utm
  glm::dvec2 utm_origin{0.0, 0.0};
};

LocalProjection::LocalProjection(GeodeticOrigin origin, GeodesyMode mode)
    : mode_(mode), impl_(std::make_shared<const Impl>(origin, mode)) {}

glm::dvec2 LocalProjection::to_local(double lat_deg, double lon_deg) const {
  return impl_->to_local(mode_, lat_deg, lon_deg);
}

}  // namespace hazard
