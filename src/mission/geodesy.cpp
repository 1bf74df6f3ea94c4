#include "mission/geodesy.hpp"

namespace mission {

namespace {
constexpr double kDatumHeight_m = 0.0;  // the datum lies on the WGS84 ellipsoid
}  // namespace

LocalGeodesy::LocalGeodesy(GeoPoint origin)
    : origin_(origin), frame_(origin.lat_deg, origin.lon_deg, kDatumHeight_m) {}

GeoPoint LocalGeodesy::to_geo(glm::dvec2 local_m) const {
  GeoPoint out;
  double height_m = 0.0;
  frame_.Reverse(local_m.x, local_m.y, 0.0, out.lat_deg, out.lon_deg, height_m);
  return out;
}

glm::dvec2 LocalGeodesy::to_local(GeoPoint geo) const {
  double x = 0.0, y = 0.0, z = 0.0;
  frame_.Forward(geo.lat_deg, geo.lon_deg, kDatumHeight_m, x, y, z);
  return {x, y};
}

}  // namespace mission
