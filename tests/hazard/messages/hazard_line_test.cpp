// The hazard object line (manual 5, docs/hazard-file.md).
#include <gtest/gtest.h>

#include "hazard/messages/hazard_line.hpp"
#include "hazard/style.hpp"

namespace hazard {
namespace {

TEST(HazardLine, MinimalLineLoads) {
  const auto p = parse_hazard_line("x=-52,y=-290,label=75,type=hazard");
  ASSERT_TRUE(p.object) << p.error;
  EXPECT_EQ(p.object->x_m, -52);
  EXPECT_EQ(p.object->y_m, -290);
  EXPECT_EQ(p.object->label, "75");
  EXPECT_TRUE(p.object->is_hazard());
  EXPECT_TRUE(p.warnings.empty());
}

TEST(HazardLine, EveryFieldOfTheManual) {
  const auto p = parse_hazard_line(
      "x=98.2,y=-127.7,label=14,type=benign,hr=0.8,aspect=43,aspect_min=30,"
      "aspect_max=60,color=yellow,shape=square,width=4,source=survey 3");
  // aspect_min + aspect_max = 90 is allowed (<= 90).
  ASSERT_TRUE(p.object) << p.error;
  const HazardObject& o = *p.object;
  EXPECT_EQ(o.resemblance, 0.8);
  EXPECT_EQ(o.aspect_deg, 43);
  EXPECT_EQ(o.aspect_min_deg, 30);
  EXPECT_EQ(o.aspect_max_deg, 60);
  EXPECT_TRUE(o.has_aspect_triple());
  EXPECT_EQ(o.color, "yellow");
  EXPECT_EQ(o.shape, "square");
  EXPECT_EQ(o.marker_width_m, 4);
  EXPECT_EQ(o.source, "survey 3");
}

TEST(HazardLine, KeysAnyCaseValuesTrimmed_Rulings) {
  const auto p = parse_hazard_line(" X = 1 , Y=2 , LABEL = a b , Type = BENIGN ");
  ASSERT_TRUE(p.object) << p.error;
  EXPECT_EQ(p.object->label, "a b");  // interior blanks kept
  EXPECT_FALSE(p.object->is_hazard());
}

TEST(HazardLine, MissingMandatoryFieldsReject) {
  EXPECT_EQ(parse_hazard_line("y=1,label=a,type=hazard").error, "missing field 'x'");
  EXPECT_EQ(parse_hazard_line("x=1,label=a,type=hazard").error, "missing field 'y'");
  EXPECT_EQ(parse_hazard_line("x=1,y=1,type=hazard").error, "missing field 'label'");
  EXPECT_EQ(parse_hazard_line("x=1,y=1,label=,type=hazard").error, "missing field 'label'");
  EXPECT_EQ(parse_hazard_line("x=1,y=1,label=a").error, "missing field 'type'");
}

TEST(HazardLine, TypeMustBeHazardOrBenign_ValidationTable) {
  const auto p = parse_hazard_line("x=1,y=1,label=a,type=inert");
  EXPECT_FALSE(p.object);
  EXPECT_NE(p.error.find("field 'type' value 'inert'"), std::string::npos);
  EXPECT_TRUE(parse_hazard_line("x=1,y=1,label=a,type=Hazard").object->is_hazard());
}

TEST(HazardLine, HazardKeyStandsInForType) {
  EXPECT_TRUE(parse_hazard_line("x=1,y=1,label=a,hazard=true").object->is_hazard());
  EXPECT_FALSE(parse_hazard_line("x=1,y=1,label=a,hazard=false").object->is_hazard());
  EXPECT_FALSE(parse_hazard_line("x=1,y=1,label=a,hazard=maybe").object);
}

TEST(HazardLine, NonNumbersReject) {
  for (const char* line : {"x=abc,y=1,label=a,type=hazard", "x=1,y=nan,label=a,type=hazard",
                           "x=1e999,y=1,label=a,type=hazard", "x=1,y=1,label=a,type=benign,hr=x"}) {
    const auto p = parse_hazard_line(line);
    EXPECT_FALSE(p.object) << line;
    EXPECT_NE(p.error.find("is not a number"), std::string::npos) << p.error;
  }
}

TEST(HazardLine, ResemblanceOutOfRangeRejects_D28) {
  const auto p = parse_hazard_line("x=1,y=1,label=a,type=benign,hr=1.5");
  EXPECT_FALSE(p.object);
  EXPECT_EQ(p.error, "field 'hr' value '1.5' is outside [0, 1]");
  EXPECT_FALSE(parse_hazard_line("x=1,y=1,label=a,type=benign,hr=-0.1").object);
  EXPECT_TRUE(parse_hazard_line("x=1,y=1,label=a,type=benign,hr=0").object);
  EXPECT_TRUE(parse_hazard_line("x=1,y=1,label=a,type=benign,hr=1").object);
}

TEST(HazardLine, HrOnAHazardIsAcceptedAndKept_Rulings) {
  const auto p = parse_hazard_line("x=1,y=1,label=a,type=hazard,hr=0.5");
  ASSERT_TRUE(p.object);
  EXPECT_EQ(p.object->resemblance, 0.5);
}

TEST(HazardLine, AspectRangesReject_D27) {
  EXPECT_FALSE(parse_hazard_line("x=1,y=1,label=a,type=benign,aspect=360").object);
  EXPECT_FALSE(parse_hazard_line("x=1,y=1,label=a,type=benign,aspect=-1").object);
  EXPECT_TRUE(parse_hazard_line("x=1,y=1,label=a,type=benign,aspect=359.9,aspect_min=1,"
                                "aspect_max=2")
                  .object);
  EXPECT_FALSE(parse_hazard_line("x=1,y=1,label=a,type=benign,aspect=1,aspect_min=91,"
                                 "aspect_max=91")
                   .object);
  const auto reversed =
      parse_hazard_line("x=1,y=1,label=a,type=benign,aspect=1,aspect_min=40,aspect_max=20");
  EXPECT_FALSE(reversed.object);
  EXPECT_NE(reversed.error.find("greater than aspect_max"), std::string::npos);
  const auto wide =
      parse_hazard_line("x=1,y=1,label=a,type=benign,aspect=1,aspect_min=40,aspect_max=60");
  EXPECT_FALSE(wide.object);
  EXPECT_NE(wide.error.find("exceeds 90"), std::string::npos);
}

TEST(HazardLine, PartialAspectLoadsWithoutSensitivity_ValidationTable) {
  const auto p = parse_hazard_line("x=1,y=1,label=a,type=benign,aspect=57");
  ASSERT_TRUE(p.object);
  EXPECT_FALSE(p.object->has_aspect_triple());
  EXPECT_EQ(p.object->aspect_deg, 57);
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_NE(p.warnings[0].find("partial aspect"), std::string::npos);
}

TEST(HazardLine, UnknownKeyWarnsAndStillLoads_Rulings) {
  const auto p = parse_hazard_line("x=1,y=1,label=a,type=benign,depth=7");
  ASSERT_TRUE(p.object);
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_EQ(p.warnings[0], "unknown key 'depth' (value '7') ignored");
}

TEST(HazardLine, BadRenderingHintsAreDroppedNotFatal) {
  const auto p = parse_hazard_line("x=1,y=1,label=a,type=benign,color=blurple,shape=blob,width=-2");
  ASSERT_TRUE(p.object);
  EXPECT_FALSE(p.object->color);
  EXPECT_FALSE(p.object->shape);
  EXPECT_FALSE(p.object->marker_width_m);
  EXPECT_EQ(p.warnings.size(), 3u);
}

TEST(HazardLine, LatLonOnlyNeedsGeodesy) {
  const auto p = parse_hazard_line("lat=43.8,lon=-70.3,label=a,type=benign");
  EXPECT_FALSE(p.object);
  EXPECT_NE(p.error.find("lat/lon"), std::string::npos);
}

TEST(HazardLine, FormatFollowsSpecOrderAndRoundTrips_Spec4_4) {
  const std::string line =
      "x=98.2,y=-127.7,label=14,type=benign,color=yellow,shape=square,width=4,hr=0.8,aspect=43,"
      "aspect_min=30,aspect_max=60";
  const auto p = parse_hazard_line(line);
  ASSERT_TRUE(p.object);
  EXPECT_EQ(format_hazard_line(*p.object), line);
  // x and y are FMT(.,2); hr is written for benign objects only.
  HazardObject o = *p.object;
  o.x_m = -293.60001;
  o.type = ObjectType::kHazard;
  EXPECT_EQ(format_hazard_line(o).substr(0, 38), "x=-293.6,y=-127.7,label=14,type=hazard");
  EXPECT_EQ(format_hazard_line(o).find("hr="), std::string::npos);
}

TEST(Style, ColorsOfTheViewer) {
  for (const char* c : {"green", "light_blue", "LightBlue", "gray70", "grey100", "hex:ff,00,a0",
                        "0.5,0.2,1", "1:0:0", "invisible", "empty", "pink", "yellow"}) {
    EXPECT_TRUE(is_known_color(c)) << c;
  }
  for (const char* c : {"", "blurple", "gray101", "hex:fff,0,0", "2,0,0", "0.5,0.5"}) {
    EXPECT_FALSE(is_known_color(c)) << c;
  }
  EXPECT_TRUE(is_known_shape("triangle"));
  EXPECT_TRUE(is_known_shape("gateway"));
  EXPECT_FALSE(is_known_shape("Triangle"));  // callers lower-case first
  EXPECT_FALSE(is_known_shape("pentagon"));
}

}  // namespace
}  // namespace hazard
