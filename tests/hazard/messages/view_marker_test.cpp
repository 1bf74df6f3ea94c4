// VIEW_MARKER: round trip.
#include <gtest/gtest.h>

#include "hazard/messages/view_marker.hpp"

namespace hazard {
namespace {

TEST(VisualMessages, MarkerRoundTrip) {
  for (const std::string text :
       {"x=-52,y=-290,width=8,primary_color=green,type=triangle,label=75",
        "x=-41,y=-246,width=8,primary_color=light_blue,type=triangle,label=82,"
        "fill_transparency=0.5"}) {
    const auto m = parse_view_marker(text);
    ASSERT_TRUE(m) << m.error;
    EXPECT_EQ(format_view_marker(*m.value), text);
  }
}

}  // namespace
}  // namespace hazard
