// VIEW_SEGLIST: round trip.
#include <gtest/gtest.h>

#include "hazard/messages/view_seglist.hpp"

namespace hazard {
namespace {

TEST(VisualMessages, SeglistRoundTrip) {
  const std::string seg = "pts={37,-192:37,-222},edge_color=gray70,vertex_size=0,edge_size=1";
  const auto s = parse_view_seglist(seg);
  ASSERT_TRUE(s) << s.error;
  EXPECT_EQ(format_view_seglist(*s.value), seg);
}

}  // namespace
}  // namespace hazard
