// Ten million classification requests on one vehicle's queue (differences.md D8, "Ten million
// classify requests": a test of the queue itself). The original ordered equal priorities by
// subtracting n/1e6 from each request's priority, so after a million requests a priority 1 higher
// lost to an older one, and a counter grew without bound. The queue keeps one FIFO bucket per
// priority and a stack of `top` entries: no counter, no drift.
#include <gtest/gtest.h>

#include <cstdint>

#include "hazard/classify_queue.hpp"

namespace hazard {
namespace {

constexpr std::uint32_t kTenMillion = 10'000'000;

PendingAnswer entry(std::uint32_t n) {
  PendingAnswer a;
  a.object = n;
  a.credit.pass = n;
  return a;
}

TEST(NumericsQueue, TenMillionEqualPrioritiesStayFirstComeFirstServed_D8_N9) {
  ClassifyQueue q;
  for (std::uint32_t n = 0; n < kTenMillion; ++n) q.push(entry(n), 50.0, false);
  // Pushed last, after ten million others: a priority 1e-9 higher goes first, one 1e-9 lower
  // last (the original's n/1e6 offset would have put both at the very end).
  q.push(entry(kTenMillion), 50.0 + 1e-9, false);
  q.push(entry(kTenMillion + 1), 50.0 - 1e-9, false);
  ASSERT_EQ(q.size(), kTenMillion + 2u);
  EXPECT_EQ(q.pop()->object, kTenMillion);
  std::uint32_t out_of_order = 0;
  for (std::uint32_t n = 0; n < kTenMillion; ++n) out_of_order += q.pop()->object != n;
  EXPECT_EQ(out_of_order, 0u);
  EXPECT_EQ(q.pop()->object, kTenMillion + 1);
  EXPECT_TRUE(q.empty());
  EXPECT_FALSE(q.pop());
}

TEST(NumericsQueue, FifoHoldsWhileTenMillionRequestsComeAndGo_D8) {
  // Requests arrive two at a time and leave one at a time, in three priorities; within each
  // priority every entry leaves in arrival order, and a higher priority always leaves first.
  ClassifyQueue q;
  std::uint32_t next_in = 0;
  std::uint32_t last_out[3] = {0, 0, 0};
  bool seen[3] = {false, false, false};
  std::uint32_t errors = 0;
  const double priority[3] = {10.0, 50.0, 50.5};
  while (next_in < kTenMillion) {
    for (int i = 0; i < 2 && next_in < kTenMillion; ++i, ++next_in) {
      q.push(entry(next_in), priority[next_in % 3], false);
    }
    const auto a = q.pop();
    const int c = static_cast<int>(a->object % 3);
    errors += seen[c] && a->object <= last_out[c];
    last_out[c] = a->object;
    seen[c] = true;
  }
  EXPECT_EQ(errors, 0u);
  // What is left: highest priority first, each class in arrival order.
  double previous = 1e300;
  while (auto a = q.pop()) {
    const double p = priority[a->object % 3];
    errors += p > previous;
    previous = p;
  }
  EXPECT_EQ(errors, 0u);
}

TEST(NumericsQueue, TopEntriesGoFirstNewestFirstAndZeroSignDoesNotSplitABucket_D8) {
  ClassifyQueue q;
  q.push(entry(0), 0.0, false);
  q.push(entry(1), -0.0, false);  // the same priority as +0: after 0
  q.push(entry(2), 1.0, true);
  q.push(entry(3), -5.0, true);
  std::vector<std::uint32_t> order;
  while (auto a = q.pop()) order.push_back(a->object);
  EXPECT_EQ(order, (std::vector<std::uint32_t>{3, 2, 0, 1}));
}

}  // namespace
}  // namespace hazard
