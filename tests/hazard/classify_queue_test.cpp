// The classify queue's order (differences.md D8, T7).
#include <gtest/gtest.h>

#include "hazard/classify_queue.hpp"

namespace hazard {
namespace {

PendingAnswer entry(ObjectId id) {
  PendingAnswer a;
  a.object = id;
  a.credit.pass = id + 1;
  return a;
}

std::vector<ObjectId> drain(ClassifyQueue& q) {
  std::vector<ObjectId> out;
  while (auto a = q.pop()) out.push_back(a->object);
  return out;
}

TEST(ClassifyQueue, HighestPriorityFirstFifoAmongEquals_D8_T7) {
  ClassifyQueue q;
  q.push(entry(0), 50, false);  // A
  q.push(entry(1), 95, false);  // B
  q.push(entry(2), 50, false);  // C
  EXPECT_EQ(drain(q), (std::vector<ObjectId>{1, 0, 2}));
}

TEST(ClassifyQueue, TopGoesAheadNewestTopFirst_D8_T7) {
  ClassifyQueue q;
  q.push(entry(0), 50, false);  // A
  q.push(entry(1), 95, false);  // B
  q.push(entry(2), 50, false);  // C
  q.push(entry(3), 10, true);   // D top
  EXPECT_EQ(drain(q), (std::vector<ObjectId>{3, 1, 0, 2}));
  q.push(entry(4), 100, true);
  q.push(entry(5), 1, true);
  q.push(entry(6), 99, false);
  EXPECT_EQ(drain(q), (std::vector<ObjectId>{5, 4, 6}));
}

TEST(ClassifyQueue, ManyEqualPrioritiesKeepArrivalOrder_N9) {
  ClassifyQueue q;
  for (ObjectId i = 0; i < 5000; ++i) q.push(entry(i), i == 4999 ? 50 + 1e-9 : 50.0, false);
  // The last one has a marginally higher priority and must come first (no drift, N9).
  const auto order = drain(q);
  ASSERT_EQ(order.size(), 5000u);
  EXPECT_EQ(order[0], 4999u);
  for (ObjectId i = 1; i < 5000; ++i) EXPECT_EQ(order[i], i - 1);
}

TEST(ClassifyQueue, ClearReturnsEveryEntryInReleaseOrder_D10) {
  ClassifyQueue q;
  q.push(entry(0), 10, false);
  q.push(entry(1), 20, false);
  const auto cleared = q.clear();
  ASSERT_EQ(cleared.size(), 2u);
  EXPECT_EQ(cleared[0].object, 1u);
  EXPECT_EQ(cleared[1].credit.pass, 1u);
  EXPECT_TRUE(q.empty());
  EXPECT_FALSE(q.pop());
}

}  // namespace
}  // namespace hazard
