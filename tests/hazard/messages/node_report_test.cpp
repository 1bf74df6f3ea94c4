// NODE_REPORT: parser and formatter (T9); round trips keep the pair in sync.
#include <gtest/gtest.h>

#include "hazard/messages/node_report.hpp"

namespace hazard {
namespace {

TEST(NodeReportMessage, ValidReportOfT9) {
  const auto p =
      parse_node_report("NAME=archie,X=10,Y=-5,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90,TIME=123");
  ASSERT_TRUE(p) << p.error;
  EXPECT_EQ(p.value->name, "archie");
  EXPECT_EQ(p.value->x_m, 10);
  EXPECT_EQ(p.value->y_m, -5);
  EXPECT_EQ(p.value->speed_mps, 1.5);
  EXPECT_EQ(p.value->heading_deg, 90);
  EXPECT_EQ(p.value->lat_deg, 43.8);
  EXPECT_EQ(p.value->time_s, 123);
}

TEST(NodeReportMessage, LatLonOnlyIsInvalid_T9) {
  const auto p = parse_node_report("NAME=archie,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90");
  EXPECT_FALSE(p);
  EXPECT_NE(p.error.find("LAT/LON"), std::string::npos);
}

TEST(NodeReportMessage, KeysAnyCaseAliasesBracesAndHeadingNormalised) {
  const auto p = parse_node_report(
      "name=b,x=1,y=2,speed=3,heading=-90,MODE={A,B},COLOR=red,LENGTH=4");
  ASSERT_TRUE(p) << p.error;
  EXPECT_EQ(p.value->speed_mps, 3);
  EXPECT_EQ(p.value->heading_deg, 270);
}

TEST(NodeReportMessage, MalformedFieldsAreNamed) {
  EXPECT_EQ(parse_node_report("X=1,Y=2,SPD=1,HDG=0").error, "missing field 'NAME'");
  EXPECT_EQ(parse_node_report("NAME=a,Y=2,SPD=1,HDG=0").error, "missing field 'X'");
  EXPECT_EQ(parse_node_report("NAME=a,X=1,Y=2,HDG=0").error, "missing field 'SPD'");
  EXPECT_EQ(parse_node_report("NAME=a,X=1,Y=2,SPD=1").error, "missing field 'HDG'");
  EXPECT_EQ(parse_node_report("NAME=a,X=nan,Y=2,SPD=1,HDG=0").error,
            "field 'X' value 'nan' is not a finite number");
  EXPECT_EQ(parse_node_report("NAME=a,X=1,Y=1e999,SPD=1,HDG=0").error,
            "field 'Y' value '1e999' is not a finite number");
  EXPECT_EQ(parse_node_report("NAME=a,X=1,Y=2,SPD=fast,HDG=0").error,
            "field 'SPD' value 'fast' is not a finite number");
}

// The engine's parse (kPose) keeps only the name and the pose, and decides every text as the
// full parse does: the same acceptance, error, name and pose.
TEST(NodeReportMessage, PoseOnlyParseDecidesAsTheFullParse) {
  const GeoPlacement none;
  for (const char* text :
       {"NAME=archie,X=10,Y=-5,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90,TIME=123,TYPE=kayak",
        "NAME=v1,X=-9997.20,Y=-9900.0,SPD=1.5,HDG=90,TYPE=kayak,TIME=1700000000.100,LENGTH=4",
        "NAME=a,X=1,Y=2,SPD=1,HDG=0,LAT=junk,TIME=soon,TYPE=", "name=b,x=1,y=2,speed=3,heading=-90",
        "NAME=a,X=1,Y=2,HDG=0", "NAME=a,X=1,Y=2,SPD=fast,HDG=0", "NAME=a,X=1e9,Y=2,SPD=1,HDG=0",
        "NAME=a,X=1,Y=2,SPD=-1,HDG=0", "NAME=archie,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90", ""}) {
    const auto all = parse_node_report(text, &none, NodeReportKeep::kAll);
    const auto pose = parse_node_report(text, &none, NodeReportKeep::kPose);
    EXPECT_EQ(all.error, pose.error) << text;
    ASSERT_EQ(all.value.has_value(), pose.value.has_value()) << text;
    if (!pose.value) continue;
    EXPECT_EQ(pose.value->name, all.value->name);
    EXPECT_EQ(pose.value->x_m, all.value->x_m);
    EXPECT_EQ(pose.value->y_m, all.value->y_m);
    EXPECT_EQ(pose.value->speed_mps, all.value->speed_mps);
    EXPECT_EQ(pose.value->heading_deg, all.value->heading_deg);
    EXPECT_FALSE(pose.value->lat_deg || pose.value->lon_deg || pose.value->time_s ||
                 pose.value->type)
        << text;
  }
  const auto kept = parse_node_report(
      "NAME=archie,X=10,Y=-5,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90,TIME=123,TYPE=kayak");
  ASSERT_TRUE(kept) << kept.error;
  EXPECT_EQ(kept.value->time_s, 123);  // the default keeps them all
  EXPECT_EQ(kept.value->type, "kayak");
}

// NodeReportMemo (texts read by several readers of one thread) gives what the parse gives, kept
// or not: the same acceptance, error and fields, with and without a placement, on the first
// reading and on the next (more texts than it keeps, so entries are replaced).
TEST(NodeReportMessage, MemoGivesWhatTheParseGives) {
  GeoPlacement placed;
  placed.projection.emplace(GeodeticOrigin{43.825300, -70.330400}, GeodesyMode::kTangent);
  const GeoPlacement none;
  const char* texts[] = {
      "NAME=archie,X=10,Y=-5,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90,TIME=123,TYPE=kayak",
      "NAME=betty,X=11,Y=-5,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90,TIME=123.25,TYPE=kayak",
      "NAME=a,X=1,Y=2,SPD=1,HDG=0,LAT=junk,TIME=soon,TYPE=", "name=b,x=1,y=2,speed=3,heading=-90",
      "NAME=a,X=1,Y=2,HDG=0", "NAME=a,X=1e9,Y=2,SPD=1,HDG=0",
      "NAME=archie,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90,TIME=5", ""};
  const GeoPlacement* const placements[] = {&placed, &none, nullptr};
  NodeReportMemo memo;
  for (int round = 0; round < 2; ++round) {
    for (const char* text : texts) {
      for (const GeoPlacement* placement : placements) {
        const auto want = parse_node_report(text, placement);
        const auto& got = memo.parse(text, placement);
        EXPECT_EQ(got.error, want.error) << text;
        ASSERT_EQ(got.value.has_value(), want.value.has_value()) << text;
        if (!want.value) continue;
        EXPECT_EQ(format_node_report(*got.value), format_node_report(*want.value)) << text;
        EXPECT_EQ(got.value->placed_from_lat_lon, want.value->placed_from_lat_lon) << text;
      }
    }
  }
}

TEST(NodeReportMessage, RoundTrip) {
  NodeReport r;
  r.name = "betty";
  r.x_m = -12.25;
  r.y_m = 300.5;
  r.speed_mps = 1.2;
  r.heading_deg = 271.5;
  r.lat_deg = 43.82537;
  r.lon_deg = -70.33034;
  r.time_s = 1234.5;
  r.type = "kayak";
  const std::string text = format_node_report(r);
  EXPECT_EQ(text, "NAME=betty,X=-12.25,Y=300.5,SPD=1.2,HDG=271.5,LAT=43.82537,LON=-70.33034,"
                  "TIME=1234.5,TYPE=kayak");
  const auto back = parse_node_report(text);
  ASSERT_TRUE(back);
  EXPECT_EQ(format_node_report(*back.value), text);
}

}  // namespace
}  // namespace hazard
