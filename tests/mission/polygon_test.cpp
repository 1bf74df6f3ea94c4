#include <gtest/gtest.h>

#include "mission/polygon.hpp"

namespace mission {
namespace {

ConvexPolygon must_parse(std::string_view text) {
  auto parsed = ConvexPolygon::parse(text);
  if (!parsed) ADD_FAILURE() << parsed.error;
  return std::move(parsed.value).value();
}

std::string parse_error(std::string_view text) {
  auto parsed = ConvexPolygon::parse(text);
  return parsed ? std::string("(parsed)") : parsed.error;
}

TEST(Polygon, ParsesColonListAndPtsForm_Spec12_1) {
  const auto a = must_parse("-150,-75:-150,-400:400,-400:400,-75");
  const auto b = must_parse("pts={-150,-75:-150,-400:400,-400:400,-75}");
  ASSERT_EQ(a.vertices().size(), 4u);
  EXPECT_EQ(a.vertices(), b.vertices());
  EXPECT_DOUBLE_EQ(a.area_m2(), 550.0 * 325.0);
  EXPECT_EQ(a.spec_pts(), "pts={-150,-75:-150,-400:400,-400:400,-75}");
}

TEST(Polygon, PtsFormIgnoresRenderingFields) {
  const auto p = must_parse("label=search_region, pts={0,0:10,0:10,10}, edge_color=gray45");
  EXPECT_EQ(p.vertices().size(), 3u);
}

TEST(Polygon, ContainmentIsInclusiveOfEdgesAndVertices_Spec8_3) {
  for (const char* text : {"0,0:10,0:10,10:0,10", "0,10:10,10:10,0:0,0"}) {  // both windings
    const auto p = must_parse(text);
    EXPECT_TRUE(p.contains({5, 5}));
    EXPECT_TRUE(p.contains({0, 0}));
    EXPECT_TRUE(p.contains({10, 5}));
    EXPECT_FALSE(p.contains({10.000001, 5}));
    EXPECT_FALSE(p.contains({-0.000001, 5}));
  }
}

TEST(Polygon, RejectsNonConvexDegenerateAndMalformedWithReasons) {
  EXPECT_NE(parse_error("0,0:10,0:5,2:10,10:0,10").find("not convex at vertex 3 (5,2)"),
            std::string::npos);
  EXPECT_NE(parse_error("0,0:10,0").find("at least 3 vertices, got 2"), std::string::npos);
  EXPECT_NE(parse_error("0,0:5,5:10,10").find("zero area"), std::string::npos);
  EXPECT_NE(parse_error("0,0:10,zz:10,10").find("bad vertex '10,zz'"), std::string::npos);
  EXPECT_NE(parse_error("0,0:10,nan:10,10").find("bad vertex"), std::string::npos);
  EXPECT_NE(parse_error("pts={0,0:1,0:1,1").find("no closing"), std::string::npos);
  EXPECT_NE(parse_error("").find("no vertices"), std::string::npos);
  // A pentagram turns the same way at every corner but winds twice.
  EXPECT_NE(parse_error("0,10:5.88,-8.09:-9.51,3.09:9.51,3.09:-5.88,-8.09").find("winds"),
            std::string::npos);
}

TEST(Polygon, CollinearVerticesAreAllowed) {
  const auto p = must_parse("0,0:5,0:10,0:10,10:0,10");
  EXPECT_TRUE(p.contains({5, 5}));
}

TEST(Polygon, ClipToBandKeepsOnlyTheBand) {
  const auto p = must_parse("0,0:10,0:10,10:0,10");
  const auto band = clip_to_band(p.vertices(), {1.0, 0.0}, 2.0, 3.0);
  ASSERT_FALSE(band.empty());
  for (const auto& v : band) {
    EXPECT_GE(v.x, 2.0 - 1e-12);
    EXPECT_LE(v.x, 3.0 + 1e-12);
  }
  EXPECT_TRUE(clip_to_band(p.vertices(), {1.0, 0.0}, 11.0, 12.0).empty());
}

TEST(Polygon, PointListsRoundTrip) {
  const std::vector<glm::dvec2> pts{{1.25, -3}, {0, 0}};
  EXPECT_EQ(format_points(pts), "pts={1.2,-3:0,0}");  // FMT(.,1): %.1f rounds 1.25 to 1.2
  auto parsed = parse_points("pts={1.5,-3:0,0}");
  ASSERT_TRUE(parsed) << parsed.error;
  EXPECT_EQ(parsed.value->size(), 2u);
}

}  // namespace
}  // namespace mission
