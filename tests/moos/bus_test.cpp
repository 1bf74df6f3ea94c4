// In-process bus: MOOSDB semantics of docs/protocol.md section 5 (moos::Database), through the
// Comms interface.
#include <gtest/gtest.h>

#include "moos/bus.hpp"
#include "moos/codec.hpp"
#include "moos/database.hpp"
#include "moos/wildcard.hpp"
#include "wire_messages.hpp"

namespace moos {
namespace {

class BusTest : public ::testing::Test {
 protected:
  ManualClock clock{1000.0};
  InProcessBus bus{clock, InProcessBus::Options{"alpha", 2.0}};
  std::unique_ptr<BusClient> a = bus.connect("pA");
  std::unique_ptr<BusClient> b = bus.connect("pB");
};

TEST_F(BusTest, TimeIsTheClockTimesTheWarp_0_3) {
  EXPECT_DOUBLE_EQ(bus.moos_time(), 2000.0);
  EXPECT_DOUBLE_EQ(a->moos_time(), 2000.0);
  clock.advance_real_s(1.5);
  EXPECT_DOUBLE_EQ(a->moos_time(), 2003.0);
  EXPECT_EQ(a->community(), "alpha");
  EXPECT_TRUE(a->is_connected());
  EXPECT_EQ(a->connection_count(), 1u);
}

TEST_F(BusTest, SecondClientWithTheSameNameIsRefused_1_6) {
  EXPECT_EQ(bus.connect("pA"), nullptr);
  EXPECT_EQ(bus.connect(""), nullptr);
  EXPECT_EQ(bus.client_names(), (std::vector<std::string>{"pA", "pB"}));
  a.reset();
  EXPECT_NE(bus.connect("pA"), nullptr);  // the name is free again
}

TEST_F(BusTest, LiveNotifyReachesEverySubscriberIncludingThePublisher_5_3) {
  a->register_variable("DEPTH");
  b->register_variable("DEPTH");
  ASSERT_TRUE(a->notify("DEPTH", 12.5));
  const auto mail_a = a->fetch();
  const auto mail_b = b->fetch();
  ASSERT_EQ(mail_a.size(), 1u);
  ASSERT_EQ(mail_b.size(), 1u);
  const Message& m = mail_b[0];
  EXPECT_EQ(m.type, msg_type::kNotify);
  EXPECT_EQ(m.key, "DEPTH");
  EXPECT_TRUE(m.is_double());
  EXPECT_EQ(m.dval, 12.5);
  EXPECT_EQ(m.source, "pA");
  EXPECT_EQ(m.community, "alpha");  // an empty community becomes the bus's (protocol.md 5.3)
  EXPECT_DOUBLE_EQ(m.time, 2000.0);
  EXPECT_TRUE(a->fetch().empty());  // fetch empties the inbox
}

TEST_F(BusTest, FetchIntoCopiesNewMailIntoTheStorageOfTheMailReadBefore) {
  b->register_variable("REPORT");
  // The last reader takes the posting itself (next test); b, a reader before it, gets copies.
  const auto last = bus.connect("pLast");
  last->register_variable("REPORT");
  // Values beyond the small-string buffer: each owns storage.
  const std::string first(200, 'a');
  const std::string second(200, 'b');
  const std::string third(150, 'c');
  std::vector<Message> mail;
  a->notify("REPORT", first);
  b->fetch_into(mail);
  ASSERT_EQ(mail.size(), 1u);
  const char* storage = mail[0].sval.data();
  a->notify("REPORT", second);
  b->fetch_into(mail);  // hands the first back
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0].sval, second);
  // Had the first been freed, this would take its storage.
  const std::string blocker(200, 'x');
  a->notify("REPORT", third);
  b->fetch_into(mail);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0].sval, third);
  EXPECT_EQ(mail[0].source, "pA");
  EXPECT_EQ(mail[0].sval.data(), storage);  // written over, not allocated
  EXPECT_NE(blocker.data(), storage);
  b->fetch_into(mail);
  EXPECT_TRUE(mail.empty());
}

TEST_F(BusTest, ThePostingsLastReaderGetsItsStorageNotACopy) {
  a->register_variable("REPORT");
  b->register_variable("REPORT");  // connected after a: the last reader
  std::vector<Message> mail_a;
  std::vector<Message> mail_b;
  for (const char fill : {'a', 'b', 'c'}) {
    std::string value(200, fill);  // beyond the small-string buffer: it owns storage
    const char* posted = value.data();
    ASSERT_TRUE(a->notify("REPORT", std::move(value)));
    a->fetch_into(mail_a);
    b->fetch_into(mail_b);
    ASSERT_EQ(mail_a.size(), 1u);
    ASSERT_EQ(mail_b.size(), 1u);
    EXPECT_EQ(mail_b[0], mail_a[0]);
    EXPECT_EQ(mail_b[0].sval, std::string(200, fill));
    EXPECT_EQ(mail_b[0].source, "pA");
    EXPECT_EQ(mail_b[0].sval.data(), posted);  // moved all the way, never copied
    EXPECT_NE(mail_a[0].sval.data(), posted);
  }
}

TEST_F(BusTest, MailKeepsPostingOrderAcrossVariables) {
  b->register_variable("X");
  b->register_variable("Y");
  for (int i = 0; i < 100; ++i) {
    a->notify(i % 2 ? "X" : "Y", static_cast<double>(i));
  }
  const auto mail = b->fetch();
  ASSERT_EQ(mail.size(), 100u);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(mail[static_cast<std::size_t>(i)].dval, i);
}

TEST_F(BusTest, RegisterSendsASnapshotOfTheLastWrite_5_4) {
  a->notify("MODE", std::string("SURVEY"), 1234.5, "aux=1");
  clock.advance_real_s(10);
  b->register_variable("MODE");
  auto mail = b->fetch();
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0].id, kUnsetId);
  EXPECT_EQ(mail[0].sval, "SURVEY");
  EXPECT_EQ(mail[0].source, "pA");
  EXPECT_EQ(mail[0].source_aux, "aux=1");
  EXPECT_EQ(mail[0].time, 1234.5);  // the write's own time stamp
  EXPECT_EQ(mail[0].dval, kUnsetDouble);
  // Every REGISTER sends the snapshot again (protocol.md 5.4).
  b->register_variable("MODE");
  EXPECT_EQ(b->fetch().size(), 1u);
}

TEST_F(BusTest, UnwrittenVariableSendsNothingUntilItsFirstWrite_5_4) {
  b->register_variable("LATER");
  EXPECT_TRUE(b->fetch().empty());
  a->notify("LATER", 1.0);
  EXPECT_EQ(b->fetch().size(), 1u);
}

TEST_F(BusTest, FirstWriteFixesTheDataType_5_3) {
  b->register_variable("V");
  a->notify("V", std::string("text"));
  a->notify("V", 3.0);                        // D onto S: dropped
  a->notify_binary("V", std::string("\x01", 1));  // B onto S: dropped too
  a->notify("V", std::string("more"));
  const auto mail = b->fetch();
  ASSERT_EQ(mail.size(), 2u);
  EXPECT_EQ(mail[1].sval, "more");
  EXPECT_EQ(bus.diagnostics().size(), 2u);
  EXPECT_EQ(bus.postings_of("V").size(), 2u);
  EXPECT_EQ(bus.latest("V")->sval, "more");
}

TEST_F(BusTest, BinaryValuesKeepEveryByte_2_4) {
  b->register_variable("BLOB");
  const std::string bytes("\x00\xff\x10\x7f", 4);
  a->notify_binary("BLOB", bytes);
  const auto mail = b->fetch();
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_TRUE(mail[0].is_binary());
  EXPECT_EQ(mail[0].sval, bytes);
}

TEST_F(BusTest, ThrottledUpdatesAreDroppedNotDelayed_5_3) {
  b->register_variable("NAV_X", 1.0);  // at most one per MOOS second
  for (int i = 0; i < 10; ++i) {
    a->notify("NAV_X", static_cast<double>(i));
    clock.advance_real_s(0.125);  // warp 2: 0.25 MOOS s per post
  }
  const auto mail = b->fetch();
  ASSERT_EQ(mail.size(), 3u);  // MOOS t = 0, 1.0, 2.0 since the first post
  EXPECT_EQ(mail[0].dval, 0);
  EXPECT_EQ(mail[1].dval, 4);
  EXPECT_EQ(mail[2].dval, 8);
}

TEST_F(BusTest, SnapshotStartsTheThrottleWindow_5_4) {
  a->notify("NAV_Y", 1.0);
  b->register_variable("NAV_Y", 5.0);
  a->notify("NAV_Y", 2.0);
  ASSERT_EQ(b->fetch().size(), 1u);  // only the snapshot
  clock.advance_real_s(2.5);          // 5 MOOS s
  a->notify("NAV_Y", 3.0);
  const auto mail = b->fetch();
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0].dval, 3.0);
}

TEST_F(BusTest, UnregisterStopsDelivery_5_4) {
  b->register_variable("X");
  a->notify("X", 1.0);
  EXPECT_TRUE(b->unregister_variable("X"));
  a->notify("X", 2.0);
  EXPECT_EQ(b->fetch().size(), 1u);
  EXPECT_FALSE(b->unregister_variable("NEVER_REGISTERED"));  // nothing to send (protocol.md 4.1)
}

TEST_F(BusTest, WildcardMatchesExistingVariablesByNameAndLastWriter_5_5) {
  a->notify("NAV_X", 1.0);
  b->notify("NAV_Y", 2.0);
  a->notify("DEPTH", 3.0);
  auto c = bus.connect("pC");
  c->register_wildcard("NAV_*", "pA");
  const auto mail = c->fetch();
  ASSERT_EQ(mail.size(), 1u);  // NAV_Y was written by pB, DEPTH does not match
  EXPECT_EQ(mail[0].key, "NAV_X");
  a->notify("NAV_X", 4.0);
  EXPECT_EQ(c->fetch().size(), 1u);
}

TEST_F(BusTest, WildcardBindsNewVariablesAtTheirFirstWrite_5_5) {
  b->register_wildcard("X_*");  // any app
  a->notify("X_STR", std::string("hello"));
  a->notify("Y_STR", std::string("no"));
  a->notify("X_STR", std::string("again"));
  const auto mail = b->fetch();
  ASSERT_EQ(mail.size(), 2u);
  EXPECT_EQ(mail[0].sval, "hello");
  EXPECT_EQ(mail[1].sval, "again");
}

TEST_F(BusTest, WildcardAppPatternIsCheckedAgainstTheFirstWriterOnly_5_5) {
  b->register_wildcard("*", "pA");
  a->notify("SHARED", 1.0);   // first writer pA: b subscribes
  auto c = bus.connect("pC");
  c->notify("SHARED", 2.0);   // later writers still reach b
  c->notify("ONLY_C", 3.0);   // first writer pC: not subscribed
  const auto mail = b->fetch();
  ASSERT_EQ(mail.size(), 2u);
  EXPECT_EQ(mail[1].source, "pC");
}

TEST_F(BusTest, WildcardThrottleUsesTheFilterInterval_5_5) {
  b->register_wildcard("NAV_*", "*", 1.0);
  for (int i = 0; i < 4; ++i) {
    a->notify("NAV_Z", static_cast<double>(i));
    clock.advance_real_s(0.25);  // 0.5 MOOS s
  }
  EXPECT_EQ(b->fetch().size(), 2u);
}

TEST_F(BusTest, WildcardUnregisterRemovesSubscriptionsAndTheFilter_5_5) {
  a->notify("NAV_X", 1.0);
  b->register_wildcard("NAV_*");
  b->fetch();
  EXPECT_TRUE(b->unregister_wildcard("NAV_*"));
  a->notify("NAV_X", 2.0);
  a->notify("NAV_NEW", 3.0);  // the filter is gone too (documented deviation, protocol.md 5.5)
  EXPECT_TRUE(b->fetch().empty());
}

TEST_F(BusTest, InvalidRegistrationsAreRefused_4_1) {
  EXPECT_FALSE(a->register_variable(""));
  EXPECT_FALSE(a->register_variable("X", -1.0));
  EXPECT_FALSE(a->register_wildcard("A,B"));
  EXPECT_FALSE(a->register_wildcard("X", "p,q"));
  EXPECT_FALSE(a->notify("", 1.0));
}

TEST_F(BusTest, StatusListsComeFromTheBook_7_1) {
  a->register_variable("Y");
  a->register_variable("X");
  a->register_wildcard("NAV_*");
  a->notify("OUT_B", 1.0);
  a->notify("OUT_A", std::string("s"));
  EXPECT_EQ(a->registered_names(), (std::set<std::string>{"X", "Y"}));
  EXPECT_EQ(a->published_names(), (std::set<std::string>{"OUT_A", "OUT_B"}));
}

TEST_F(BusTest, PostingsWhileDisconnectedLeaveInOrderAfterTheReplay_1_9) {
  b->register_variable("X");
  a->register_variable("X");
  a->simulate_disconnect();
  EXPECT_FALSE(a->is_connected());
  EXPECT_TRUE(a->notify("X", 1.0));  // kept in the outbox (comms.hpp)
  EXPECT_TRUE(a->notify("X", 2.0));
  EXPECT_TRUE(b->fetch().empty());
  EXPECT_EQ(a->published_names(), std::set<std::string>{"X"});
  EXPECT_TRUE(a->simulate_reconnect());
  const auto mail = b->fetch();
  ASSERT_EQ(mail.size(), 2u);
  EXPECT_EQ(mail[0].dval, 1.0);
  EXPECT_EQ(mail[1].dval, 2.0);
  // a's own registration was replayed first, so it sees its postings too.
  EXPECT_EQ(a->fetch().size(), 2u);
  EXPECT_EQ(a->postings_dropped(), 0u);
}

TEST_F(BusTest, AFullOutboxRefusesAndCountsPostingsNamingTheVariable) {
  b->register_variable("X");
  a->simulate_disconnect();
  for (std::size_t i = 0; i < kDefaultMaxOutboxMessages; ++i)
    ASSERT_TRUE(a->notify("X", static_cast<double>(i)));
  EXPECT_FALSE(a->notify("X", -1.0));
  EXPECT_EQ(a->postings_dropped(), 1u);
  EXPECT_NE(a->last_post_error().find("NOTIFY X refused: the outbox holds its"), std::string::npos)
      << a->last_post_error();
  EXPECT_TRUE(a->simulate_reconnect());
  const auto mail = b->fetch();
  ASSERT_EQ(mail.size(), kDefaultMaxOutboxMessages);
  EXPECT_EQ(mail.back().dval, static_cast<double>(kDefaultMaxOutboxMessages - 1));
  EXPECT_TRUE(a->notify("X", 0.5));  // the outbox is empty again
}

TEST_F(BusTest, AMessageNoClientCouldReceiveIsRefusedNamingTheVariable) {
  b->register_variable("HUGE");
  EXPECT_FALSE(a->notify("HUGE", std::string(kMaxMessageBytes, 'x')));
  EXPECT_EQ(a->postings_dropped(), 1u);
  EXPECT_NE(a->last_post_error().find("NOTIFY HUGE refused: its"), std::string::npos)
      << a->last_post_error();
  EXPECT_TRUE(b->fetch().empty());
  EXPECT_TRUE(a->published_names().empty());
}

TEST_F(BusTest, ReconnectReplaysEverySubscriptionThenCallsOnConnect_1_9) {
  a->register_variable("X", 0.0);
  a->register_wildcard("NAV_*");
  int connects = 0;  // the bus calls back on the reconnecting thread: no atomic needed
  std::size_t mail_at_connect = 0;
  a->set_on_connect([&] {
    ++connects;
    mail_at_connect = a->fetch().size();  // the replay's snapshots arrived before the callback
  });
  b->notify("X", 1.0);
  b->notify("NAV_X", 1.0);
  a->fetch();
  a->simulate_disconnect();
  b->notify("X", 2.0);  // missed while away
  EXPECT_TRUE(a->simulate_reconnect());
  EXPECT_EQ(connects, 1);
  EXPECT_EQ(a->connection_count(), 2u);
  EXPECT_EQ(mail_at_connect, 2u);  // snapshots of X and NAV_X
  b->notify("X", 3.0);
  b->notify("NAV_Y", 3.0);
  EXPECT_EQ(a->fetch().size(), 2u);
}

TEST_F(BusTest, OnMailCallbackWakesTheSubscriber_4_5) {
  int woken = 0;
  b->set_on_mail([&] { ++woken; });
  b->register_variable("X");
  a->notify("X", 1.0);
  a->notify("OTHER", 1.0);
  EXPECT_EQ(woken, 1);
}

TEST_F(BusTest, AnOnMailCallbackSetOrClearedBetweenPostingsCountsFromTheNext_4_5) {
  b->register_variable("X");
  a->notify("X", 1.0);  // b has no callback yet: its mail waits unannounced
  int woken = 0;
  b->set_on_mail([&] { ++woken; });
  a->notify("X", 2.0);  // mail was waiting already; the callback is still called
  EXPECT_EQ(woken, 1);
  b->set_on_mail({});
  a->notify("X", 3.0);
  EXPECT_EQ(woken, 1);
  b->set_on_mail([&] { ++woken; });
  a->notify("X", 4.0);
  EXPECT_EQ(woken, 2);
  EXPECT_EQ(b->fetch().size(), 4u);
}

TEST_F(BusTest, APostingFromAnOnMailCallbackDuringAPostingIsWhole_4_5) {
  // a hears its own PING while posting it, and posts PONG from inside that posting.
  a->register_variable("PING");
  b->register_variable("PING");
  b->register_variable("PONG");
  bool ponged = false;
  a->set_on_mail([&] {
    if (ponged) return;
    ponged = true;
    a->notify("PONG", std::string("from the callback"), std::nullopt, "aux");
  });
  ASSERT_TRUE(a->notify("PING", std::string("first")));
  ASSERT_TRUE(a->notify("PING", std::string("second")));
  const auto mail = b->fetch();
  ASSERT_EQ(mail.size(), 3u);
  EXPECT_EQ(mail[0].key, "PING");
  EXPECT_EQ(mail[0].sval, "first");
  EXPECT_EQ(mail[1].key, "PONG");
  EXPECT_EQ(mail[1].sval, "from the callback");
  EXPECT_EQ(mail[1].source_aux, "aux");
  EXPECT_EQ(mail[2].key, "PING");
  EXPECT_EQ(mail[2].sval, "second");
  EXPECT_EQ(mail[2].source_aux, "");
  for (const Message& m : mail) EXPECT_EQ(m.source, "pA");
  a->set_on_mail({});
}

TEST_F(BusTest, PostingsHistoryAndLatest) {
  a->notify("X", 1.0);
  b->notify("Y", std::string("y"));
  const auto all = bus.postings();
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].source, "pA");
  EXPECT_EQ(all[1].source, "pB");
  EXPECT_FALSE(bus.latest("Z").has_value());
  bus.clear_postings();
  EXPECT_TRUE(bus.postings().empty());
  EXPECT_EQ(bus.latest("X")->dval, 1.0);
}

TEST(Bus, WithoutKeptPostingsTheMailStillArrives) {
  ManualClock clock{1000.0};
  InProcessBus bus{clock, InProcessBus::Options{"alpha", 1.0, false}};
  auto a = bus.connect("pA");
  auto b = bus.connect("pB");
  b->register_variable("X");
  a->notify("X", 1.0);
  a->notify("X", 2.0);
  EXPECT_TRUE(bus.postings().empty());
  EXPECT_EQ(bus.latest("X")->dval, 2.0);
  const auto mail = b->fetch();
  ASSERT_EQ(mail.size(), 2u);
  EXPECT_EQ(mail[1].dval, 2.0);
  EXPECT_TRUE(b->fetch().empty());
}

TEST_F(BusTest, ADisconnectedClientFetchesNothingAndItsStateSurvivesTheOthers) {
  b->register_variable("X");
  a->notify("X", 1.0);
  b->simulate_disconnect();
  EXPECT_FALSE(b->is_connected());
  EXPECT_TRUE(b->fetch().empty());  // undelivered mail goes with the connection
  auto c = bus.connect("pC");
  c.reset();  // another client's going leaves pB's state alone
  ASSERT_TRUE(b->simulate_reconnect());
  EXPECT_TRUE(b->is_connected());
  EXPECT_EQ(b->connection_count(), 2u);
  EXPECT_EQ(b->fetch().size(), 1u);  // the snapshot of X at the replayed REGISTER
}

// ---- settled with the server: the bus runs moos::Database's rules --------------------------

TEST_F(BusTest, WildcardFilterReplacesAnExplicitRegistrationAtFirstWrite_5_3) {
  b->register_variable("X", 10.0);
  b->register_wildcard("X", "*", 0.0);
  a->notify("X", 1.0);
  clock.advance_real_s(0.5);  // 1 MOOS s, well inside the explicit 10 s
  a->notify("X", 2.0);
  EXPECT_EQ(b->fetch().size(), 2u);  // the filter's interval 0 applies (reference DB)
}

TEST(BusClock, ManualClockAtZeroThrottlesLikeOneStartingToday_5_3) {
  ManualClock clock{0.0};
  InProcessBus bus{clock};
  auto a = bus.connect("pA");
  auto b = bus.connect("pB");
  b->register_variable("X", 5.0);
  clock.advance_real_s(1.0);
  a->notify("X", 1.0);  // never delivered before: due, though 1 - 0 < 5
  clock.advance_real_s(2.0);
  a->notify("X", 2.0);  // throttled: 2 s after the delivery
  clock.advance_real_s(3.0);
  a->notify("X", 3.0);
  const auto mail = b->fetch();
  ASSERT_EQ(mail.size(), 2u);
  EXPECT_EQ(mail[0].dval, 1.0);
  EXPECT_EQ(mail[1].dval, 3.0);
}

TEST_F(BusTest, BusAndServerDeliverTheSameMail_5) {
  // The same traffic through the bus and into a moos::Database driven as moosdb-lite drives
  // it (one packet per message): pB's mail agrees message for message.
  DatabaseConfig config;
  config.community = "alpha";
  config.db_variables = false;
  Database server(config, bus.moos_time(), [](const std::string&) {});
  ASSERT_TRUE(server.connect(1, {test::identification("pA", true)}, bus.moos_time()));
  ASSERT_TRUE(server.connect(2, {test::identification("pB", true)}, bus.moos_time()));
  server.take_output();
  std::vector<Message> server_mail;
  auto to_server = [&](ClientId id, const Message& m) {
    server.process_packet(id, {m}, bus.moos_time());
    for (auto& packet : server.take_output())
      if (packet.to == 2) server_mail.insert(server_mail.end(), packet.messages.begin(), packet.messages.end());
  };
  auto post = [&](const std::string& var, double value) {
    EXPECT_TRUE(a->notify(var, value));
    to_server(1, make_double_notify(var, value, "pA", bus.moos_time()));
    clock.advance_real_s(0.25);  // 0.5 MOOS s
  };
  post("NAV_X", 1.0);
  b->register_variable("NAV_X", 1.0);
  to_server(2, test::registration("NAV_X", 1.0, "pB"));
  post("NAV_X", 2.0);  // throttled: the snapshot was just delivered
  b->register_wildcard("NAV_*", "*", 0.0);
  to_server(2, test::wildcard(format_wildcard_spec(WildcardSpec{"*", "NAV_*", 0.0}), "pB"));
  for (int i = 0; i < 6; ++i) post(i % 2 ? "NAV_X" : "NAV_Y", i);
  const auto bus_mail = b->fetch();
  ASSERT_EQ(bus_mail.size(), server_mail.size());
  ASSERT_EQ(bus_mail.size(), 8u);  // 2 snapshots of NAV_X, then every post
  for (std::size_t i = 0; i < bus_mail.size(); ++i) {
    EXPECT_EQ(bus_mail[i].key, server_mail[i].key) << i;
    EXPECT_EQ(bus_mail[i].dval, server_mail[i].dval) << i;
    EXPECT_EQ(bus_mail[i].time, server_mail[i].time) << i;
    EXPECT_EQ(bus_mail[i].source, server_mail[i].source) << i;
    EXPECT_EQ(bus_mail[i].community, server_mail[i].community) << i;
  }
}

}  // namespace
}  // namespace moos
