// A vehicle's credit pool (credit_lists.hpp; differences.md "Credits").
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "hazard/credit_lists.hpp"

namespace hazard {
namespace {

std::vector<std::uint32_t> passes(const CreditLists& pool, const CreditList& list) {
  std::vector<std::uint32_t> out;
  for (const Credit& c : pool.to_vector(list)) out.push_back(c.pass);
  return out;
}

TEST(CreditLists, ListsKeepTheirOwnCreditsOldestFirst) {
  CreditLists pool;
  CreditList a, b;
  pool.push_back(a, Credit{1, 10.0});
  pool.push_back(b, Credit{1, 200.0});
  pool.push_back(a, Credit{3, 30.0});
  pool.push_back(b, Credit{2, 210.0});
  EXPECT_EQ(passes(pool, a), (std::vector<std::uint32_t>{1, 3}));
  EXPECT_EQ(passes(pool, b), (std::vector<std::uint32_t>{1, 2}));
  EXPECT_EQ(a.size, 2u);
  EXPECT_EQ(pool.front(a).heading_deg, 10.0);
  const Credit oldest = pool.pop_front(a);
  EXPECT_EQ(oldest.pass, 1u);
  EXPECT_EQ(oldest.heading_deg, 10.0);  // the heading comes back exactly (aspect dice)
  EXPECT_EQ(pool.pop_front(a).heading_deg, 30.0);
  EXPECT_TRUE(a.empty());
  EXPECT_EQ(passes(pool, a), std::vector<std::uint32_t>{});
  pool.push_back(a, Credit{4, 40.0});  // an emptied list takes credits again
  EXPECT_EQ(passes(pool, a), (std::vector<std::uint32_t>{4}));
  EXPECT_EQ(passes(pool, b), (std::vector<std::uint32_t>{1, 2}));
}

TEST(CreditLists, ReturnedCreditsGoBackInPassOrder_RulingsClear) {
  CreditLists pool;
  CreditList list;
  for (std::uint32_t pass : {2u, 4u, 6u}) pool.push_back(list, Credit{pass, 1.0 * pass});
  pool.insert_in_pass_order(list, Credit{1, 1.0});  // before all
  pool.insert_in_pass_order(list, Credit{5, 5.0});  // between
  pool.insert_in_pass_order(list, Credit{7, 7.0});  // after all
  pool.insert_in_pass_order(list, Credit{3, 3.0});
  EXPECT_EQ(passes(pool, list), (std::vector<std::uint32_t>{1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(list.size, 7u);
  for (const Credit& c : pool.to_vector(list)) EXPECT_EQ(c.heading_deg, 1.0 * c.pass);
  CreditList empty;
  pool.insert_in_pass_order(empty, Credit{9, 9.0});
  EXPECT_EQ(passes(pool, empty), (std::vector<std::uint32_t>{9}));
  // The tail is kept right after an insertion at the end: a new detection appends after it.
  pool.push_back(list, Credit{8, 8.0});
  EXPECT_EQ(passes(pool, list).back(), 8u);
}

TEST(CreditLists, TakenSlotsAreReusedSoThePoolHoldsThePeakOnly_Hardening) {
  CreditLists pool;
  std::vector<CreditList> lists(100);
  std::uint32_t pass = 0;
  // Many rounds of grant-then-take never hold more than 100 credits at once.
  for (int round = 0; round < 1000; ++round) {
    ++pass;
    for (CreditList& l : lists) pool.push_back(l, Credit{pass, 0.0});
    for (CreditList& l : lists) pool.pop_front(l);
  }
  EXPECT_EQ(pool.slots(), 100u);
  EXPECT_EQ(pool.free_slots(), 100u);
  for (CreditList& l : lists) pool.push_back(l, Credit{pass + 1, 0.0});
  EXPECT_EQ(pool.slots(), 100u);
  EXPECT_EQ(pool.free_slots(), 0u);
}

}  // namespace
}  // namespace hazard
