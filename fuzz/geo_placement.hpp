#pragma once
// The geodetic placement the fuzz targets give their parsers for LAT/LON-only input: the Jake
// mission's origin (missions/jake/jake.moos).

#include "hazard/geodesy.hpp"

namespace fuzz {

inline const hazard::GeoPlacement& jake_placement(hazard::GeodesyMode mode) {
  static const hazard::GeoPlacement tangent{
      hazard::LocalProjection({43.825300, -70.330400}, hazard::GeodesyMode::kTangent), ""};
  static const hazard::GeoPlacement utm{
      hazard::LocalProjection({43.825300, -70.330400}, hazard::GeodesyMode::kUtm), ""};
  return mode == hazard::GeodesyMode::kUtm ? utm : tangent;
}

}  // namespace fuzz
