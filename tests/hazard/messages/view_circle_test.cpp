// VIEW_CIRCLE: round trip.
#include <gtest/gtest.h>

#include "hazard/messages/view_circle.hpp"

namespace hazard {
namespace {

TEST(VisualMessages, CircleRoundTrip) {
  for (const std::string text :
       {"x=-52,y=-290,radius=10,vertices=12,duration=60,edge_color=white,fill_color=white,"
        "time=12.5,vertex_size=0,edge_size=1,fill_transparency=0.3",
        "x=1,y=2,radius=10,vertices=5,edge_color=yellow,fill_color=pink,time=40,vertex_size=0,"
        "edge_size=2,fill_transparency=0.5"}) {
    const auto c = parse_view_circle(text);
    ASSERT_TRUE(c) << c.error;
    EXPECT_EQ(format_view_circle(*c.value), text);
  }
  EXPECT_FALSE(parse_view_circle("y=1,radius=3"));
}

}  // namespace
}  // namespace hazard
