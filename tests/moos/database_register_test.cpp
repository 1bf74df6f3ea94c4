// Unit tests of moos::Database: REGISTER / UNREGISTER and wildcard filters
// (docs/protocol.md 5.4, 5.5).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "database_fixture.hpp"

namespace moos::test {
namespace {

// ---------------------------------------------------------------------------------------
// REGISTER / UNREGISTER (protocol.md 5.4)

TEST_F(DatabaseTest, EveryRegisterSendsASnapshotOfTheLastWrite_5_4) {
  connect(kA, "writer", true);
  connect(kB, "reader", true);
  Message post = notify_string("MODE", "SURVEY", "writer", kT0 - 3, 9);
  post.source_aux = "aux1";
  send(kA, {post});
  const auto mail = to(send(kB, {registration("MODE", 0, "reader"), registration("MODE", 0, "reader")}), kB);
  ASSERT_EQ(mail.size(), 1u);
  ASSERT_EQ(mail[0].size(), 2u);  // duplicate registrations, duplicate snapshots
  for (const Message& s : mail[0]) {
    EXPECT_EQ(s.type, mt::kNotify);
    EXPECT_EQ(s.id, -1);
    EXPECT_EQ(s.data_type, dt::kString);
    EXPECT_EQ(s.key, "MODE");
    EXPECT_EQ(s.sval, "SURVEY");
    EXPECT_EQ(s.dval, -1.0);
    EXPECT_EQ(s.dval2, -1.0);
    EXPECT_EQ(s.source, "writer");
    EXPECT_EQ(s.source_aux, "aux1");
    EXPECT_EQ(s.community, "alpha");
    EXPECT_EQ(s.time, kT0 - 3);  // the original time stamp
  }
}

TEST_F(DatabaseTest, RegisteringAnUnwrittenVariableSendsNothingUntilItsFirstWrite_5_4) {
  connect(kA, "reader", true);
  connect(kB, "writer", true);
  EXPECT_TRUE(to(send(kA, {registration("LATER", 0, "reader")}), kA).empty());
  const auto mail = to(send(kB, {notify_double("LATER", 7, "writer")}), kA);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0][0].dval, 7.0);
}

TEST_F(DatabaseTest, UnregisterStopsDelivery_5_4) {
  connect(kA, "reader", true);
  connect(kB, "writer", true);
  send(kA, {registration("X", 0, "reader")});
  send(kA, {unregistration("X", "reader")});
  EXPECT_TRUE(to(send(kB, {notify_double("X", 1, "writer")}), kA).empty());
}

TEST_F(DatabaseTest, DisconnectRemovesSubscriptionsAndUndeliveredMail_1_9) {
  connect(kA, "sync", false);
  connect(kB, "writer", true);
  send(kA, {registration("X", 0, "sync")});
  send(kB, {notify_double("X", 1, "writer")});
  db_.disconnect(kA, kT0);
  ASSERT_TRUE(db_.connect(kC, {identification("sync", false)}, kT0));
  db_.take_output();
  const auto replies = to(send(kC, {null_message("sync")}), kC);
  ASSERT_EQ(replies.size(), 1u);
  EXPECT_EQ(replies[0].size(), 1u);  // just the NULL: old mail and subscription are gone
}

TEST_F(DatabaseTest, FanOutFollowsConnectionOrderWhateverTheOrderOfTheRegistrations_5_3) {
  constexpr ClientId kWriter = 4;
  connect(kA, "a", true);
  connect(kB, "b", true);
  connect(kC, "c", true);
  connect(kWriter, "writer", true);
  send(kC, {registration("X", 0, "c")});
  send(kA, {registration("X", 0, "a")});
  send(kB, {registration("X", 0, "b")});
  send(kB, {unregistration("X", "b")});
  send(kB, {registration("X", 0, "b")});  // back in its place, not at the end
  send(kA, {registration("X", 0, "a")});  // registering again replaces, adds no second one
  const auto out = send(kWriter, {notify_double("X", 1, "writer")});
  std::vector<ClientId> order;
  for (const auto& packet : out) order.push_back(packet.to);
  EXPECT_EQ(order, (std::vector<ClientId>{kA, kB, kC}));
}

// ---------------------------------------------------------------------------------------
// Wildcards (protocol.md 5.5)

TEST_F(DatabaseTest, WildcardCommaFormSubscribesExistingAndNewVariables_5_5) {
  connect(kA, "reader", true);
  connect(kB, "writer", true);
  send(kB, {notify_double("NAV_X", 1, "writer"), notify_double("DEPTH", 2, "writer")});
  auto mail = to(send(kA, {wildcard("AppPattern=*,VarPattern=NAV_*,Interval=0", "reader")}), kA);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(keys(mail[0]), std::vector<std::string>{"NAV_X"});
  mail = to(send(kB, {notify_double("NAV_Y", 3, "writer"), notify_double("DEPTH", 4, "writer")}), kA);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(keys(mail[0]), std::vector<std::string>{"NAV_Y"});
}

TEST_F(DatabaseTest, WildcardSpaceFormOfPymoos2IsAccepted_5_5) {
  connect(kA, "pyreader", false);
  connect(kB, "writer", true);
  send(kA, {wildcard("AppPattern=* VarPattern=X_* Interval=0.0", "pyreader")});
  send(kB, {notify_string("X_STR", "hello", "writer"), notify_double("Y", 1, "writer")});
  const auto replies = to(send(kA, {null_message("pyreader")}), kA);
  ASSERT_EQ(replies.size(), 1u);
  ASSERT_EQ(replies[0].size(), 2u);
  EXPECT_EQ(replies[0][1].key, "X_STR");
}

TEST_F(DatabaseTest, WildcardBindsAtFirstWriteUsingTheFirstWriter_5_5) {
  connect(kA, "reader", true);
  connect(kB, "pGood", true);
  connect(kC, "pOther", true);
  send(kA, {wildcard("AppPattern=pGood,VarPattern=*,Interval=0", "reader")});
  send(kC, {notify_double("FIRST_BY_OTHER", 1, "pOther")});
  // Later writes by the matching app do not bind: the first writer decided.
  EXPECT_TRUE(to(send(kB, {notify_double("FIRST_BY_OTHER", 2, "pGood")}), kA).empty());
  const auto mail = to(send(kB, {notify_double("FIRST_BY_GOOD", 3, "pGood")}), kA);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(keys(mail[0]), std::vector<std::string>{"FIRST_BY_GOOD"});
  // ...and then the variable stays subscribed whoever writes it.
  EXPECT_EQ(to(send(kC, {notify_double("FIRST_BY_GOOD", 4, "pOther")}), kA).size(), 1u);
}

TEST_F(DatabaseTest, WildcardMatchesExistingVariablesByLastWriter_5_5) {
  connect(kA, "reader", true);
  connect(kB, "pGood", true);
  connect(kC, "pOther", true);
  send(kC, {notify_double("V", 1, "pOther")});
  send(kB, {notify_double("V", 2, "pGood")});
  const auto mail = to(send(kA, {wildcard("AppPattern=pGood,VarPattern=V,Interval=0", "reader")}), kA);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0][0].dval, 2.0);
}

TEST_F(DatabaseTest, WildcardUnregisterRemovesSubscriptionsAndTheFilter_5_5) {
  connect(kA, "reader", true);
  connect(kB, "writer", true);
  send(kB, {notify_double("NAV_X", 1, "writer")});
  send(kA, {wildcard("AppPattern=*,VarPattern=NAV_*,Interval=0", "reader")});
  send(kA, {wildcard("AppPattern=*,VarPattern=NAV_*,Interval=0", "reader", mt::kWildcardUnregister)});
  EXPECT_TRUE(to(send(kB, {notify_double("NAV_X", 2, "writer"), notify_double("NAV_NEW", 3, "writer")}), kA)
                  .empty());
}

TEST_F(DatabaseTest, WildcardIntervalThrottlesBoundVariables_5_5) {
  connect(kA, "reader", true);
  connect(kB, "writer", true);
  send(kA, {wildcard("AppPattern=*,VarPattern=T,Interval=10", "reader")});
  EXPECT_EQ(to(send(kB, {notify_double("T", 1, "writer")}, kT0), kA).size(), 1u);
  EXPECT_TRUE(to(send(kB, {notify_double("T", 2, "writer")}, kT0 + 5), kA).empty());
  EXPECT_EQ(to(send(kB, {notify_double("T", 3, "writer")}, kT0 + 10), kA).size(), 1u);
}

// ---------------------------------------------------------------------------------------
// Settled with the reference MOOSDB (include/moos/database.hpp, docs/moos.md)

TEST_F(DatabaseTest, WildcardFilterReplacesAnExplicitRegistrationAtFirstWrite_5_3) {
  connect(kA, "reader", true);
  connect(kB, "writer", true);
  send(kA, {registration("X", 10, "reader"), wildcard("AppPattern=*,VarPattern=X,Interval=0", "reader")});
  // The filter's interval 0 applies from the first write on: no update is throttled.
  EXPECT_EQ(to(send(kB, {notify_double("X", 1, "writer")}, kT0), kA).size(), 1u);
  EXPECT_EQ(to(send(kB, {notify_double("X", 2, "writer")}, kT0 + 1), kA).size(), 1u);
}

TEST_F(DatabaseTest, WildcardIntervalReplacesAnExplicitEveryUpdateRegistration_5_3) {
  connect(kA, "reader", true);
  connect(kB, "writer", true);
  send(kA, {registration("X", 0, "reader"), wildcard("AppPattern=*,VarPattern=X,Interval=10", "reader")});
  EXPECT_EQ(to(send(kB, {notify_double("X", 1, "writer")}, kT0), kA).size(), 1u);
  EXPECT_TRUE(to(send(kB, {notify_double("X", 2, "writer")}, kT0 + 1), kA).empty());
  EXPECT_EQ(to(send(kB, {notify_double("X", 3, "writer")}, kT0 + 10), kA).size(), 1u);
}

TEST_F(DatabaseTest, OfSeveralMatchingFiltersTheGreatestPatternPairWinsWhateverTheOrder_5_3) {
  // ("*", "X?") > ("*", "X*") since '?' sorts after '*': interval 0 wins in both orders.
  connect(kA, "first", true);
  connect(kB, "second", true);
  connect(kC, "writer", true);
  send(kA, {wildcard("AppPattern=*,VarPattern=X*,Interval=10", "first"),
            wildcard("AppPattern=*,VarPattern=X?,Interval=0", "first")});
  send(kB, {wildcard("AppPattern=*,VarPattern=X?,Interval=0", "second"),
            wildcard("AppPattern=*,VarPattern=X*,Interval=10", "second")});
  send(kC, {notify_double("XY", 1, "writer")}, kT0);
  const auto out = send(kC, {notify_double("XY", 2, "writer")}, kT0 + 1);
  EXPECT_EQ(to(out, kA).size(), 1u);
  EXPECT_EQ(to(out, kB).size(), 1u);
}

TEST_F(DatabaseTest, NeverDeliveredIsDueWhateverTheClock_5_3) {
  // A DB whose MOOS time starts at 0 (a manual clock): the first update is not throttled
  // against a time 0 that never was a delivery.
  Database db(config(), 0.0, [](const std::string&) {});
  ASSERT_TRUE(db.connect(kA, {identification("reader", true, 0.0)}, 0.0));
  ASSERT_TRUE(db.connect(kB, {identification("writer", true, 0.0)}, 0.0));
  db.process_packet(kA, {registration("X", 5, "reader")}, 0.5);
  db.take_output();
  db.process_packet(kB, {notify_double("X", 1, "writer")}, 1.0);
  EXPECT_EQ(to(db.take_output(), kA).size(), 1u);
  db.process_packet(kB, {notify_double("X", 2, "writer")}, 3.0);
  EXPECT_TRUE(to(db.take_output(), kA).empty());  // then the interval counts from t = 1
  db.process_packet(kB, {notify_double("X", 3, "writer")}, 6.0);
  EXPECT_EQ(to(db.take_output(), kA).size(), 1u);
}

}  // namespace
}  // namespace moos::test
