// Geodesy (geodesy.hpp): LAT/LON-only node reports and lat/lon hazard lines placed
// around the mission's LatOrigin/LongOrigin with the chosen projection, against GeographicLib's
// own classes as the reference; without a usable origin the original's behaviour, with a reason.
#include <gtest/gtest.h>

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/LocalCartesian.hpp>
#include <GeographicLib/UTMUPS.hpp>

#include "hazard/messages/hazard_line.hpp"
#include "hazard/messages/node_report.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::contains;
using testing::entries;
using testing::quiet_block;

const GeodeticOrigin kOrigin{42.358436, -71.087448};  // a MOOS-IvP mission origin (Charles River)

// The point at geodesic distance s and azimuth a from the origin (the truth of docs/accuracy.md).
glm::dvec2 geodesic_point(double s_m, double azimuth_deg, double& lat, double& lon) {
  GeographicLib::Geodesic::WGS84().Direct(kOrigin.lat_deg, kOrigin.lon_deg, azimuth_deg, s_m,
                                          lat, lon);
  const double a = azimuth_deg * GeographicLib::Math::degree();
  return {s_m * std::sin(a), s_m * std::cos(a)};
}

TEST(Geodesy, ModeWordsAndRanges) {
  EXPECT_EQ(parse_geodesy_mode("ENU"), GeodesyMode::kEnu);
  EXPECT_EQ(parse_geodesy_mode(" utm "), GeodesyMode::kUtm);
  EXPECT_EQ(parse_geodesy_mode("mercator"), std::nullopt);
  for (GeodesyMode m : {GeodesyMode::kOff, GeodesyMode::kTangent, GeodesyMode::kEnu,
                        GeodesyMode::kAzimuthal, GeodesyMode::kUtm}) {
    EXPECT_EQ(parse_geodesy_mode(geodesy_mode_name(m)), m);
  }
  EXPECT_TRUE(valid_latitude(-90) && valid_latitude(90));
  EXPECT_FALSE(valid_latitude(90.0001));
  EXPECT_TRUE(valid_longitude(-180) && valid_longitude(359.9));
  EXPECT_FALSE(valid_longitude(360.1));
}

TEST(Geodesy, TheOriginIsTheLocalZero) {
  for (GeodesyMode m : {GeodesyMode::kTangent, GeodesyMode::kEnu, GeodesyMode::kAzimuthal,
                        GeodesyMode::kUtm}) {
    const glm::dvec2 p = LocalProjection(kOrigin, m).to_local(kOrigin.lat_deg, kOrigin.lon_deg);
    EXPECT_LT(std::hypot(p.x, p.y), 1e-9) << geodesy_mode_name(m);
  }
}

TEST(Geodesy, EnuIsGeographicLibsLocalCartesian) {
  const GeographicLib::LocalCartesian lc(kOrigin.lat_deg, kOrigin.lon_deg, 0.0);
  const LocalProjection enu(kOrigin, GeodesyMode::kEnu);
  for (double s : {1e3, 1e5}) {
    for (double az : {0.0, 77.0, 200.0}) {
      double lat, lon, x, y, z;
      geodesic_point(s, az, lat, lon);
      lc.Forward(lat, lon, 0.0, x, y, z);
      const glm::dvec2 p = enu.to_local(lat, lon);
      EXPECT_EQ(p.x, x);
      EXPECT_EQ(p.y, y);
    }
  }
}

TEST(Geodesy, AzimuthalKeepsGeodesicDistanceAndAzimuthExactly) {
  const LocalProjection az(kOrigin, GeodesyMode::kAzimuthal);
  for (double s : {1e3, 1e4, 1e5, 1e6}) {
    for (double a : {0.0, 45.0, 137.5, 270.0}) {
      double lat, lon;
      const glm::dvec2 truth = geodesic_point(s, a, lat, lon);
      const glm::dvec2 p = az.to_local(lat, lon);
      EXPECT_LT(std::hypot(p.x - truth.x, p.y - truth.y), 1e-6) << s << " " << a;
    }
  }
}

TEST(Geodesy, UtmIsTheOriginsZoneRelativeToTheOrigin) {
  const LocalProjection utm(kOrigin, GeodesyMode::kUtm);
  int zone;
  bool north;
  double x0, y0, x1, y1;
  GeographicLib::UTMUPS::Forward(kOrigin.lat_deg, kOrigin.lon_deg, zone, north, x0, y0);
  const double lat = 42.4, lon = -71.0;  // same zone (19), same hemisphere
  int zone1;
  GeographicLib::UTMUPS::Forward(lat, lon, zone1, north, x1, y1);
  ASSERT_EQ(zone1, zone);
  const glm::dvec2 p = utm.to_local(lat, lon);
  EXPECT_NEAR(p.x, x1 - x0, 1e-6);
  EXPECT_NEAR(p.y, y1 - y0, 1e-6);
}

TEST(Geodesy, TangentPlaneIsCentimetresAtOneKilometreAndMetresAtTen) {
  const LocalProjection tangent(kOrigin, GeodesyMode::kTangent);
  double worst_1km = 0, worst_10km = 0;
  for (double a = 0; a < 360; a += 15) {
    double lat, lon;
    glm::dvec2 truth = geodesic_point(1e3, a, lat, lon);
    glm::dvec2 p = tangent.to_local(lat, lon);
    worst_1km = std::max(worst_1km, std::hypot(p.x - truth.x, p.y - truth.y));
    truth = geodesic_point(1e4, a, lat, lon);
    p = tangent.to_local(lat, lon);
    worst_10km = std::max(worst_10km, std::hypot(p.x - truth.x, p.y - truth.y));
  }
  EXPECT_LT(worst_1km, 0.1);
  EXPECT_GT(worst_10km, 1.0);
  EXPECT_LT(worst_10km, 10.0);
}

TEST(Geodesy, LongitudeDifferencesAreTakenAcrossTheAntimeridian) {
  const GeodeticOrigin o{10.0, 179.99};
  for (GeodesyMode m : {GeodesyMode::kTangent, GeodesyMode::kEnu, GeodesyMode::kAzimuthal}) {
    const glm::dvec2 p = LocalProjection(o, m).to_local(10.0, -179.99);  // 0.02 deg east
    EXPECT_NEAR(p.x, 2190.0, 10.0) << geodesy_mode_name(m);
    EXPECT_NEAR(p.y, 0.0, 1.0) << geodesy_mode_name(m);
  }
}

// ---- node reports ----------------------------------------------------------------------------------

EngineSetup with_origin(const std::string& block, MissionOrigin origin) {
  return load_configuration(entries(block), testing::no_files,
                            origin);
}

MissionOrigin origin_of(double lat, double lon) {
  return MissionOrigin{lat, lon, base::fmt(lat, 8), base::fmt(lon, 8)};
}

TEST(Geodesy, LatLonOnlyNodeReportIsPlacedAroundTheMissionOrigin) {
  hazard::Driver driver(with_origin(quiet_block("hazard = x=0,y=0,label=a,type=hazard\n"),
                            origin_of(kOrigin.lat_deg, kOrigin.lon_deg)),
                SeedChoice{1, SeedSource::kCommandLine});
  ASSERT_TRUE(driver.engine().effects().geodesy);
  driver.start(0);
  double lat, lon;
  geodesic_point(120.0, 30.0, lat, lon);
  const std::string report =
      "NAME=v,LAT=" + base::fmt(lat, 10) + ",LON=" + base::fmt(lon, 10) + ",SPD=1,HDG=10";
  const Outputs out = driver.deliver(Mail{"NODE_REPORT", report, 0}).outputs;
  EXPECT_TRUE(out.run_warnings.empty());
  const glm::dvec2 expected = LocalProjection(kOrigin, GeodesyMode::kEnu).to_local(
      *base::parse_number(base::fmt(lat, 10)), *base::parse_number(base::fmt(lon, 10)));
  const Pose& pose = *driver.engine().vehicle(*driver.engine().find_vehicle("v")).pose;
  EXPECT_EQ(pose.position_m, expected);
  EXPECT_NEAR(pose.position_m.x, 60.0, 0.01);  // 120 m at azimuth 30
  EXPECT_NEAR(pose.position_m.y, 103.92, 0.01);
}

TEST(Geodesy, XAndYWinOverLatAndLon_Spec6) {
  hazard::Driver driver(with_origin(quiet_block(), origin_of(kOrigin.lat_deg, kOrigin.lon_deg)),
                SeedChoice{1, SeedSource::kCommandLine});
  driver.deliver(Mail{"NODE_REPORT", "NAME=v,X=10,Y=-5,LAT=43.8,LON=-70.3,SPD=1,HDG=10", 0});
  EXPECT_EQ(driver.engine().vehicle(0).pose->position_m, glm::dvec2(10, -5));
}

TEST(Geodesy, BadLatitudeOrLongitudeIsAWarningNamingTheField) {
  hazard::Driver driver(with_origin(quiet_block(), origin_of(kOrigin.lat_deg, kOrigin.lon_deg)),
                SeedChoice{1, SeedSource::kCommandLine});
  Outputs out =
      driver.deliver(Mail{"NODE_REPORT", "NAME=v,LAT=95,LON=-70,SPD=1,HDG=10", 0}).outputs;
  EXPECT_TRUE(contains(out.run_warnings, "field 'LAT' value '95' is outside [-90, 90]"));
  out = driver.deliver(Mail{"NODE_REPORT", "NAME=v,LAT=42,LON=400,SPD=1,HDG=10", 0}).outputs;
  EXPECT_TRUE(contains(out.run_warnings, "field 'LON' value '400' is outside [-180, 360]"));
  out = driver.deliver(Mail{"NODE_REPORT", "NAME=v,LAT=north,LON=-70,SPD=1,HDG=10", 0}).outputs;
  EXPECT_TRUE(contains(out.run_warnings, "field 'LAT' value 'north' is not a finite number"));
  EXPECT_FALSE(driver.engine().find_vehicle("v"));
}

TEST(Geodesy, WithoutAUsableOriginLatLonOnlyInputIsRejectedWithTheReason_T9) {
  const std::string report = "NAME=v,LAT=42.36,LON=-71.08,SPD=1,HDG=10";
  const std::vector<std::pair<MissionOrigin, std::string>> cases = {
      {MissionOrigin{}, "the mission file gives no LatOrigin and LongOrigin"},
      {MissionOrigin{std::nullopt, -71.0, std::string("north"), std::string("-71")},
       "the mission's LatOrigin value 'north' is not a number"},
      {MissionOrigin{std::nullopt, -71.0, std::string("4\x1b[2J"), std::string("-71")},
       "the mission's LatOrigin value '4\\x1B[2J' is not a number"},  // escaped
      {origin_of(95, -71), "the mission's LatOrigin value '95' is outside [-90, 90]"},
      {MissionOrigin{42.0, std::nullopt, std::string("42"), std::nullopt},
       "the mission's LatOrigin is given without LongOrigin"},
  };
  for (const auto& [origin, reason] : cases) {
    hazard::Driver driver(with_origin(quiet_block(), origin),
                          SeedChoice{1, SeedSource::kCommandLine});
    EXPECT_FALSE(driver.engine().effects().geodesy) << reason;
    const Outputs out = driver.deliver(Mail{"NODE_REPORT", report, 0}).outputs;
    ASSERT_EQ(out.run_warnings.size(), 1u) << reason;
    EXPECT_NE(out.run_warnings[0].find("LAT/LON without X/Y cannot be placed (" + reason + ")"),
              std::string::npos)
        << out.run_warnings[0];
  }
  // An unusable origin is also a configuration warning at start-up.
  const EngineSetup bad = with_origin(quiet_block(), origin_of(95, -71));
  EXPECT_TRUE(contains(bad.config_warnings, "mission file: LatOrigin value '95' is outside"));
  // geodesy = off: the origin is known, and the report says why it is not used.
  Driver off(with_origin(quiet_block("geodesy = off\n"), origin_of(42, -71)),
             SeedChoice{1, SeedSource::kCommandLine});
  EXPECT_FALSE(off.engine().effects().geodesy);
  EXPECT_TRUE(contains(off.deliver(Mail{"NODE_REPORT", report, 0}).outputs.run_warnings,
                       "cannot be placed (geodesy = off)"));
}

// ---- hazard lines ----------------------------------------------------------------------------------

TEST(Geodesy, LatLonHazardLinesArePlacedAtLoadTimeWithTheBlocksProjection) {
  double lat, lon;
  geodesic_point(500.0, 90.0, lat, lon);
  const std::string line = "hazard = lat=" + base::fmt(lat, 10) + ",lon=" + base::fmt(lon, 10) +
                           ",label=g,type=hazard\n";
  for (const char* mode : {"tangent", "enu", "azimuthal", "utm"}) {
    // The geodesy line comes after the hazard line: the whole block's value applies.
    const EngineSetup s = with_origin(quiet_block(line + "geodesy = " + mode + "\n"),
                                      origin_of(kOrigin.lat_deg, kOrigin.lon_deg));
    ASSERT_EQ(s.field.size(), 1u) << mode;
    const glm::dvec2 expected =
        LocalProjection(kOrigin, *parse_geodesy_mode(mode))
            .to_local(*base::parse_number(base::fmt(lat, 10)), *base::parse_number(base::fmt(lon, 10)));
    EXPECT_EQ(s.field.position(0), expected) << mode;
    EXPECT_NEAR(s.field.position(0).x, 500.0, mode == std::string("utm") ? 0.5 : 0.01) << mode;
  }
}

TEST(Geodesy, LatLonHazardLinesWithoutAnOriginAreRejectedWithTheReason) {
  const EngineSetup s = with_origin(quiet_block("hazard = lat=42.36,lon=-71.08,label=g,type=hazard\n"
                                                "hazard = x=1,y=2,lat=42.36,lon=-71.08,label=h,"
                                                "type=hazard\n"),
                                    MissionOrigin{});
  ASSERT_EQ(s.field.size(), 1u);  // the line with x and y loads (lat/lon unused)
  EXPECT_EQ(s.field.position(0), glm::dvec2(1, 2));
  EXPECT_TRUE(contains(s.config_warnings,
                       "test.moos:9: position given only as lat/lon cannot be placed (the "
                       "mission file gives no LatOrigin and LongOrigin); line rejected"));
  const EngineSetup placed = with_origin("", origin_of(42, -71));
  const HazardLineParse bad =
      parse_hazard_line("lat=abc,lon=-71,label=g,type=hazard", &placed.placement);
  EXPECT_NE(bad.error.find("field 'lat' value 'abc' is not a number"), std::string::npos);
}

}  // namespace
}  // namespace hazard
