// hazard::QuietBox (include/hazard/quiet_box.hpp): when it asks, what box it asks about, and
// what it answers in between.
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "hazard/quiet_box.hpp"

namespace hazard {
namespace {

/// A query that records the boxes it was asked about and answers `empty`.
struct Query {
  bool empty = true;
  std::vector<Box> asked;
  bool operator()(const Box& b) {
    asked.push_back(b);
    return empty;
  }
};

TEST(QuietBox, AsksOnceForTheReachPlusSlackAndAnswersFromItWhileTheReachStaysInside) {
  QuietBox q;
  Query query;
  EXPECT_TRUE(q.nothing_near({100.0, 200.0}, 5.0, 10.0, query));
  ASSERT_EQ(query.asked.size(), 1u);
  EXPECT_EQ(query.asked[0].min_x, 85.0);
  EXPECT_EQ(query.asked[0].min_y, 185.0);
  EXPECT_EQ(query.asked[0].max_x, 115.0);
  EXPECT_EQ(query.asked[0].max_y, 215.0);
  // Up to the slack in any direction: the same answer, no new query (even if the set changed
  // meanwhile: that is what forget() is for).
  query.empty = false;
  EXPECT_TRUE(q.nothing_near({110.0, 190.0}, 5.0, 10.0, query));
  EXPECT_TRUE(q.nothing_near({90.0, 210.0}, 5.0, 10.0, query));
  EXPECT_EQ(query.asked.size(), 1u);
  // A reach beyond the box, by moving or by a wider reach: asked again, around the new pose.
  EXPECT_FALSE(q.nothing_near({110.5, 200.0}, 5.0, 10.0, query));
  ASSERT_EQ(query.asked.size(), 2u);
  EXPECT_EQ(query.asked[1].min_x, 95.5);
  EXPECT_FALSE(q.nothing_near({110.5, 200.0}, 16.0, 10.0, query));
  EXPECT_EQ(query.asked.size(), 3u);
}

TEST(QuietBox, ForgetAsksAgainAtTheSamePose) {
  QuietBox q;
  Query query;
  EXPECT_TRUE(q.nothing_near({0.0, 0.0}, 5.0, 10.0, query));
  q.forget();
  query.empty = false;
  EXPECT_FALSE(q.nothing_near({0.0, 0.0}, 5.0, 10.0, query));
  EXPECT_EQ(query.asked.size(), 2u);
}

TEST(QuietBox, FarOutOrNotANumberIsNeverQuietAndNeverAsks) {
  QuietBox q;
  Query query;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(q.nothing_near({2e9, 0.0}, 5.0, 10.0, query));
  EXPECT_FALSE(q.nothing_near({0.0, -2e9}, 5.0, 10.0, query));
  EXPECT_FALSE(q.nothing_near({nan, 0.0}, 5.0, 10.0, query));
  EXPECT_FALSE(q.nothing_near({0.0, 0.0}, 2e9, 10.0, query));
  EXPECT_FALSE(q.nothing_near({0.0, 0.0}, nan, 10.0, query));
  EXPECT_TRUE(query.asked.empty());
}

}  // namespace
}  // namespace hazard
