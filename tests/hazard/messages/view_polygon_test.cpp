// VIEW_POLYGON: round trip.
#include <gtest/gtest.h>

#include "hazard/messages/view_polygon.hpp"

namespace hazard {
namespace {

TEST(VisualMessages, PolygonRoundTrip) {
  const std::string text =
      "pts={25,2.5:25,-2.5:-25,-2.5:-25,2.5},label=sensor_swath_archie,msg=0.90/0.66,"
      "edge_color=green,fill_color=white,vertex_size=0,edge_size=0,fill_transparency=0.2";
  const auto p = parse_view_polygon(text);
  ASSERT_TRUE(p) << p.error;
  EXPECT_EQ(p.value->points.size(), 4u);
  EXPECT_EQ(format_view_polygon(*p.value), text);
  EXPECT_FALSE(parse_view_polygon("label=x"));
  EXPECT_FALSE(parse_view_polygon("pts={1,2:x,4}"));
}

}  // namespace
}  // namespace hazard
