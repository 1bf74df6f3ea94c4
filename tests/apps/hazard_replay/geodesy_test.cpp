// hazard_replay hands the mission's LatOrigin/LongOrigin to the engine (geodesy):
// LAT/LON-only node reports and lat/lon hazard lines are placed; without an origin they are
// refused with a warning that says why.
#include <gtest/gtest.h>

#include <GeographicLib/LocalCartesian.hpp>

#include "base/text.hpp"
#include "replay_support.hpp"

namespace hazard_replay {
namespace {

using test_support::alog_entries;
using test_support::ScratchDir;
using test_support::write_file;
using testing::alog;
using testing::Line;
using testing::mission;
using testing::run;

constexpr double kLat0 = 42.358436, kLon0 = -71.087448;
const GeographicLib::LocalCartesian kFrame(kLat0, kLon0, 0.0);

std::string lat_lon(double x, double y, const char* lat_key, const char* lon_key) {
  double lat, lon, h;
  kFrame.Reverse(x, y, 0.0, lat, lon, h);
  return std::string(lat_key) + "=" + base::fmt(lat, 10) + "," + lon_key + "=" +
         base::fmt(lon, 10);
}

std::string report(double x, double y) {
  return "NAME=v," + lat_lon(x, y, "LAT", "LON") + ",SPD=1,HDG=0";
}

void make(const ScratchDir& dir, const std::string& globals) {
  write_file(dir / "m.moos", globals + mission("  hazard_file = h.txt\n"
                                               "  sensor_config = width=25, exp=4, pclass=0.8\n"
                                               "  show_hazards = false\n"));
  write_file(dir / "h.txt", "hazard = " + lat_lon(0, 50, "lat", "lon") + ",label=a,type=hazard\n"
                            "hazard = x=0,y=-50,label=b,type=hazard\n");
  write_file(dir / "in.alog", alog({{0.0, "UHZ_SENSOR_REQUEST", "vname=v"},
                                    {0.0, "UHZ_CONFIG_REQUEST", "vname=v,width=25,pd=1"},
                                    {1.0, "NODE_REPORT", report(0, -50)},
                                    {2.0, "NODE_REPORT", report(0, 50)}}));
}

TEST(ReplayGeodesy, TheMissionOriginPlacesLatLonReportsAndHazardLines) {
  ScratchDir dir;
  make(dir, "LatOrigin = " + base::fmt(kLat0, 6) + "\nLongOrigin = " + base::fmt(kLon0, 6) +
                "\n");
  const auto r = run(dir, {"m.moos", "in.alog", "--seed=1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> detections;
  for (const auto& e : alog_entries(r.out)) {
    if (e.variable == "UHZ_DETECTION_REPORT") detections.push_back(e.value);
  }
  EXPECT_EQ(detections, (std::vector<std::string>{"vname=v,x=0,y=-50,label=b",
                                                  "vname=v,x=0,y=50,label=a"}));
  EXPECT_EQ(r.err.find("cannot be placed"), std::string::npos) << r.err;
}

TEST(ReplayGeodesy, WithoutAnOriginLatLonInputIsRefusedSayingWhy_T9) {
  ScratchDir dir;
  make(dir, "");
  const auto r = run(dir, {"m.moos", "in.alog", "--seed=1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("h.txt:1: position given only as lat/lon cannot be placed (the mission "
                       "file gives no LatOrigin and LongOrigin); line rejected"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("NODE_REPORT: LAT/LON without X/Y cannot be placed"), std::string::npos);
  EXPECT_EQ(r.out.find("UHZ_DETECTION_REPORT"), std::string::npos);
}

TEST(ReplayGeodesy, AnOriginThatIsNotANumberIsAConfigWarningNamingIt) {
  ScratchDir dir;
  make(dir, "LatOrigin = north\nLongOrigin = -71\n");
  const auto r = run(dir, {"m.moos", "in.alog", "--seed=1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("config warning: mission file: LatOrigin value 'north' is not a number"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace hazard_replay
