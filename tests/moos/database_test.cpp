// Unit tests of moos::Database without sockets: handshake, delivery rules and NOTIFY
// (docs/protocol.md 1, 5.2, 5.3, 5.6).
#include <gtest/gtest.h>
#include <malloc.h>

#include <cmath>
#include <string>
#include <vector>

#include "database_fixture.hpp"

namespace moos::test {
namespace {

// ---------------------------------------------------------------------------------------
// Handshake (protocol.md 1.6, 1.8)

TEST_F(DatabaseTest, WelcomeCarriesHostCommunitySkewAndAsynchronous_1_6) {
  const double ident_time = kT0 - 0.25;
  const double now = kT0 + 3.0;
  ASSERT_TRUE(db_.connect(kA, {identification("pA", true, ident_time)}, now));
  const auto out = db_.take_output();
  ASSERT_FALSE(out.empty());
  ASSERT_EQ(out.front().to, kA);
  ASSERT_EQ(out.front().messages.size(), 1u);
  const Message& w = out.front().messages.front();
  EXPECT_EQ(w.type, mt::kWelcome);
  EXPECT_EQ(w.data_type, dt::kDouble);
  EXPECT_EQ(w.id, -1);
  EXPECT_EQ(w.source, "");
  EXPECT_EQ(w.source_aux, "hostname=dbhost");
  EXPECT_EQ(w.community, "alpha");
  EXPECT_EQ(w.key, "");
  EXPECT_EQ(w.time, now);
  EXPECT_EQ(w.dval, now - ident_time);  // skew = server time - identification time (1.8)
  EXPECT_EQ(w.dval2, -1.0);
  EXPECT_EQ(w.sval, "asynchronous");
}

TEST_F(DatabaseTest, DuplicateNameGetsPoisonWithReferenceText_1_6) {
  connect(kA, "pTest", true);
  EXPECT_FALSE(db_.connect(kB, {identification("pTest", false)}, kT0 + 1));
  const auto packets = to(db_.take_output(), kB);
  ASSERT_EQ(packets.size(), 1u);
  ASSERT_EQ(packets[0].size(), 1u);
  const Message& p = packets[0][0];
  EXPECT_EQ(p.type, mt::kPoison);
  EXPECT_EQ(p.data_type, dt::kString);
  EXPECT_EQ(p.id, -1);
  EXPECT_EQ(p.time, kT0 + 1);
  EXPECT_EQ(p.dval, -1.0);
  EXPECT_EQ(p.dval2, -1.0);
  EXPECT_EQ(p.sval, "A client of this name (\"pTest\") already exists");
  EXPECT_FALSE(db_.is_connected(kB));
}

TEST_F(DatabaseTest, IdentificationWithoutMessageGetsFailedToReadPoison_1_5) {
  EXPECT_FALSE(db_.connect(kA, {}, kT0));
  const auto packets = to(db_.take_output(), kA);
  ASSERT_EQ(packets.size(), 1u);
  EXPECT_EQ(packets[0][0].type, mt::kPoison);
  EXPECT_EQ(packets[0][0].sval, "Failed to read receive client's name");
}

// A name is repeated in DB_CLIENTS, DB_EVENT and the log: bounded.
TEST_F(DatabaseTest, ANameOverTheBoundGetsPoisonAndTheBoundItselfConnects_Hardening) {
  const std::string at_bound(kMaxClientNameBytes, 'n');
  const std::string over(10 * 1024, 'o');
  EXPECT_EQ(db_.handshake_refusal({identification(over, true)}),
            std::optional<std::string>(overlong_name_reason(over.size())));
  EXPECT_FALSE(db_.connect(kA, {identification(over, true)}, kT0));
  const auto packets = to(db_.take_output(), kA);
  ASSERT_EQ(packets.size(), 1u);
  EXPECT_EQ(packets[0][0].type, mt::kPoison);
  EXPECT_EQ(packets[0][0].sval, "A client name of 10240 bytes is longer than the 1024 allowed");
  EXPECT_FALSE(db_.is_connected(kA));
  EXPECT_EQ(db_.handshake_refusal({identification(at_bound, true)}), std::nullopt);
  EXPECT_TRUE(db_.connect(kB, {identification(at_bound, true)}, kT0));
}

TEST_F(DatabaseTest, NameIsFreeAgainAfterDisconnect_1_9) {
  connect(kA, "pA", true);
  db_.disconnect(kA, kT0 + 1);
  EXPECT_TRUE(db_.connect(kB, {identification("pA", true)}, kT0 + 2));
}

TEST_F(DatabaseTest, LoneNotifiesOfClientsWhoseIdsShareACachePlaceKeepTheirSenders_5_2) {
  // The DB finds recent senders by id modulo 16 without a look-up; a lone NOTIFY takes a
  // path of its own. Neither may mix two clients up, nor serve a disconnected one.
  const ClientId twin = kA + 16;
  connect(kA, "pA", true);
  connect(twin, "pTwin", true);
  db_.process_message(kA, notify_double("X", 1, ""), kT0);  // an empty source: the sender's
  EXPECT_EQ(db_.latest("X")->source, "pA");
  db_.process_message(twin, notify_double("X", 2, ""), kT0);
  EXPECT_EQ(db_.latest("X")->source, "pTwin");
  db_.disconnect(kA, kT0);
  db_.process_message(kA, notify_double("X", 3, ""), kT0);  // no longer a client: ignored
  EXPECT_EQ(db_.latest("X")->dval, 2);
  db_.process_message(twin, notify_double("X", 4, ""), kT0);
  EXPECT_EQ(db_.latest("X")->source, "pTwin");
  EXPECT_EQ(db_.latest("X")->dval, 4);
}

TEST_F(DatabaseTest, KeyAsynchronousIsCaseInsensitive_1_5) {
  Message ident = identification("pA", false);
  ident.key = "ASYNCHRONOUS";
  ASSERT_TRUE(db_.connect(kA, {ident}, kT0));
  EXPECT_TRUE(db_.is_async(kA));
  ASSERT_TRUE(db_.connect(kB, {identification("pB", false)}, kT0));
  EXPECT_FALSE(db_.is_async(kB));
}

TEST_F(DatabaseTest, ConnectAndDisconnectPublishDbEventAndDbClientsAtOnce_5_7) {
  connect(kA, "watcher", true);
  send(kA, {registration("DB_EVENT", 0, "watcher"), registration("DB_CLIENTS", 0, "watcher")});
  ASSERT_TRUE(db_.connect(kB, {identification("pB", false)}, kT0 + 1));
  auto mail = to(db_.take_output(), kA);
  ASSERT_EQ(mail.size(), 1u);
  ASSERT_EQ(keys(mail[0]), (std::vector<std::string>{"DB_EVENT", "DB_CLIENTS"}));
  EXPECT_EQ(mail[0][0].sval, "connected=pB");
  EXPECT_EQ(mail[0][1].sval, "watcher,pB,");  // each name followed by a comma
  EXPECT_EQ(mail[0][0].source, "MOOSDB_alpha");
  EXPECT_EQ(mail[0][0].community, "alpha");

  db_.disconnect(kB, kT0 + 2);
  mail = to(db_.take_output(), kA);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0][0].sval, "disconnected=pB");
  EXPECT_EQ(mail[0][1].sval, "watcher,");
}

// ---------------------------------------------------------------------------------------
// Delivery rules (protocol.md 5.2, 5.6)

TEST_F(DatabaseTest, SyncClientGetsExactlyOneReplyStartingWithNull_5_6) {
  connect(kA, "sync", false);
  const auto out = send(kA, {null_message("sync")}, kT0 + 5);
  ASSERT_EQ(out.size(), 1u);
  ASSERT_EQ(out[0].to, kA);
  ASSERT_EQ(out[0].messages.size(), 1u);
  const Message& n = out[0].messages[0];
  EXPECT_EQ(n.type, mt::kNull);
  EXPECT_EQ(n.id, -1);
  EXPECT_EQ(n.dval, kT0 + 5);  // server time (protocol.md 2.6 "NULL S->C")
  EXPECT_EQ(n.time, -1.0);
  EXPECT_EQ(n.source, "");
}

TEST_F(DatabaseTest, SyncClientIsAnsweredEvenForAnEmptyPacket_5_6) {
  connect(kA, "sync", false);
  const auto out = send(kA, {});
  ASSERT_EQ(to(out, kA).size(), 1u);
  EXPECT_EQ(to(out, kA)[0][0].type, mt::kNull);
}

TEST_F(DatabaseTest, SyncClientNeverGetsUnsolicitedPacketsAndCollectsMailInReply_5_6) {
  connect(kA, "sync", false);
  connect(kB, "pub", true);
  send(kA, {registration("X", 0, "sync")});
  auto out = send(kB, {notify_double("X", 1.0, "pub"), notify_double("X", 2.0, "pub")});
  EXPECT_TRUE(to(out, kA).empty());
  db_.refresh_db_variables(kT0 + 1);
  EXPECT_TRUE(to(db_.take_output(), kA).empty());

  out = send(kA, {null_message("sync")}, kT0 + 2);
  const auto replies = to(out, kA);
  ASSERT_EQ(replies.size(), 1u);
  ASSERT_EQ(replies[0].size(), 3u);
  EXPECT_EQ(replies[0][0].type, mt::kNull);
  EXPECT_EQ(replies[0][1].dval, 1.0);
  EXPECT_EQ(replies[0][2].dval, 2.0);
}

TEST_F(DatabaseTest, SyncClientTimingIsNotEchoed_5_6) {
  connect(kA, "sync", false);
  const auto replies = to(send(kA, {timing(kT0)}), kA);
  ASSERT_EQ(replies.size(), 1u);
  ASSERT_EQ(replies[0].size(), 1u);
  EXPECT_EQ(replies[0][0].type, mt::kNull);
}

TEST_F(DatabaseTest, AsyncTimingEchoIsFirstAndCarriesServerTime_5_2) {
  connect(kA, "async", true);
  send(kA, {registration("X", 0, "async")});
  const double client_time = kT0 - 7.5;
  const auto replies =
      to(send(kA, {timing(client_time), notify_double("X", 4.0, "async")}, kT0 + 0.125), kA);
  ASSERT_EQ(replies.size(), 1u);
  ASSERT_EQ(replies[0].size(), 2u);
  const Message& echo = replies[0][0];
  EXPECT_EQ(echo.type, mt::kTiming);
  EXPECT_EQ(echo.key, "_async_timing");
  EXPECT_EQ(echo.time, client_time);  // the client's original value (vector J)
  EXPECT_EQ(echo.dval, kT0 + 0.125);
  EXPECT_EQ(echo.dval2, 0.0);
  EXPECT_EQ(echo.source, "");
  EXPECT_EQ(replies[0][1].key, "X");
}

TEST_F(DatabaseTest, AsyncPacketOfOnlyTimingIsAnsweredWithTheEchoAlone_5_6) {
  connect(kA, "async", true);
  const auto replies = to(send(kA, {timing(kT0)}), kA);
  ASSERT_EQ(replies.size(), 1u);
  ASSERT_EQ(replies[0].size(), 1u);
  EXPECT_EQ(replies[0][0].type, mt::kTiming);
}

TEST_F(DatabaseTest, AsyncClientGetsNoEmptyPacketForRegistrationsWithoutValues_5_6) {
  connect(kA, "async", true);
  const auto out = send(kA, {registration("NEVER_1", 0, "async"), registration("NEVER_2", 0, "async"),
                             wildcard("AppPattern=*,VarPattern=Z_*,Interval=0", "async")});
  EXPECT_TRUE(to(out, kA).empty());
}

TEST_F(DatabaseTest, AsyncClientGetsMailAsSoonAsQueuedWithoutNullOrTiming_5_6) {
  connect(kA, "async", true);
  connect(kB, "pub", false);
  send(kA, {registration("X", 0, "async")});
  const auto out = send(kB, {notify_string("X", "hello", "pub")});
  const auto mail = to(out, kA);
  ASSERT_EQ(mail.size(), 1u);
  ASSERT_EQ(mail[0].size(), 1u);
  EXPECT_EQ(mail[0][0].type, mt::kNotify);
  EXPECT_EQ(mail[0][0].sval, "hello");
  // DB-variable refreshes are pushed too, not held until the client speaks.
  send(kA, {registration("DB_UPTIME", 0, "async")});
  db_.refresh_db_variables(kT0 + 2);
  const auto refreshed = to(db_.take_output(), kA);
  ASSERT_EQ(refreshed.size(), 1u);
  EXPECT_EQ(keys(refreshed[0]), std::vector<std::string>{"DB_UPTIME"});
  EXPECT_EQ(refreshed[0][0].dval, 2.0);
}

TEST_F(DatabaseTest, MailOrderIsPreservedPerClient_5_6) {
  connect(kA, "async", true);
  connect(kB, "pub", true);
  send(kA, {registration("X", 0, "async"), registration("Y", 0, "async")});
  std::vector<Message> packet;
  for (int i = 0; i < 50; ++i) packet.push_back(notify_double(i % 2 ? "X" : "Y", i, "pub"));
  const auto mail = to(send(kB, packet), kA);
  ASSERT_EQ(mail.size(), 1u);
  ASSERT_EQ(mail[0].size(), 50u);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(mail[0][static_cast<std::size_t>(i)].dval, i);
}

// ---------------------------------------------------------------------------------------
// NOTIFY (protocol.md 5.3)

TEST_F(DatabaseTest, PublisherReceivesItsOwnPostWithIdKeptAndCommunityFilled_5_3) {
  connect(kA, "async", true);
  send(kA, {registration("TEST_VAR", 0, "async")});
  Message post = notify_double("TEST_VAR", 3.25, "async", kT0 - 1, 17);
  post.source_aux = "aux";
  const auto mail = to(send(kA, {post}), kA);
  ASSERT_EQ(mail.size(), 1u);
  const Message& m = mail[0][0];
  EXPECT_EQ(m.id, 17);
  EXPECT_EQ(m.type, mt::kNotify);
  EXPECT_EQ(m.community, "alpha");
  EXPECT_EQ(m.source, "async");
  EXPECT_EQ(m.source_aux, "aux");
  EXPECT_EQ(m.time, kT0 - 1);
  EXPECT_EQ(m.dval, 3.25);
}

TEST_F(DatabaseTest, NonEmptyCommunityOfAPostIsKept_5_3) {
  connect(kA, "async", true);
  send(kA, {registration("X", 0, "async")});
  Message post = notify_double("X", 1, "async");
  post.community = "bravo";
  const auto mail = to(send(kA, {post}), kA);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0][0].community, "bravo");
}

TEST_F(DatabaseTest, TypeIsFixedByFirstWriteAndOtherTypesAreDroppedAndLogged_5_3) {
  connect(kA, "async", true);
  send(kA, {registration("X", 0, "async")});
  send(kA, {notify_double("X", 1.5, "async")});
  const auto out = send(kA, {notify_string("X", "text", "async")});
  EXPECT_TRUE(to(out, kA).empty());
  EXPECT_TRUE(logged("client \"async\": NOTIFY X as string refused"));
  // The stored value is unchanged: a new registration's snapshot still says 1.5.
  const auto snap = to(send(kA, {registration("X", 0, "async")}), kA);
  ASSERT_EQ(snap.size(), 1u);
  EXPECT_EQ(snap[0][0].data_type, dt::kDouble);
  EXPECT_EQ(snap[0][0].dval, 1.5);
}

TEST_F(DatabaseTest, StringAndBinaryAreDifferentTypes_5_3) {
  connect(kA, "async", true);
  send(kA, {registration("BLOB", 0, "async")});
  Message binary = moos::make_binary_notify("BLOB", std::string("\0\xff", 2), "async", kT0);
  ASSERT_EQ(to(send(kA, {binary}), kA).size(), 1u);
  EXPECT_TRUE(to(send(kA, {notify_string("BLOB", "text", "async")}), kA).empty());
  EXPECT_TRUE(logged("NOTIFY BLOB as string refused: the variable is binary"));
}

TEST_F(DatabaseTest, ThrottledUpdatesAreDroppedNotDelayed_5_3) {
  connect(kA, "async", true);
  connect(kB, "pub", true);
  send(kA, {registration("X", 1.0, "async")});
  std::vector<double> received;
  for (int i = 0; i <= 10; ++i) {
    const double now = kT0 + 0.25 * i;
    for (const auto& p : to(send(kB, {notify_double("X", i, "pub", now)}, now), kA))
      for (const auto& m : p) received.push_back(m.dval);
  }
  // Writes at 0, 0.25, ..., 2.5 s with a 1 s interval: delivered at 0, 1.0, 2.0 s.
  EXPECT_EQ(received, (std::vector<double>{0, 4, 8}));
}

TEST_F(DatabaseTest, PacketsOfADisconnectedSenderAreIgnoredEvenRightAfterItsLast_1_9) {
  connect(kA, "sender", true);
  connect(kB, "reader", true);
  send(kB, {registration("X", 0, "reader")});
  send(kA, {notify_double("X", 1, "sender")});  // the latest sender
  db_.disconnect(kA, kT0);
  db_.take_output();
  EXPECT_TRUE(send(kA, {notify_double("X", 2, "sender")}).empty());
  EXPECT_EQ(db_.latest("X")->dval, 1);
  connect(kA, "newcomer", true);  // the same id, a new connection
  const auto mail = to(send(kA, {notify_double("X", 3, "")}), kB);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0][0].source, "newcomer");
  EXPECT_EQ(mail[0][0].dval, 3);
}

TEST_F(DatabaseTest, EmptySourceIsReplacedByTheClientName) {
  connect(kA, "async", true);
  send(kA, {registration("X", 0, "async")});
  const auto mail = to(send(kA, {notify_double("X", 1, "")}), kA);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0][0].source, "async");
}

TEST_F(DatabaseTest, MalformedMessagesAreRefusedWithReasonAndTheRestIsProcessed) {
  connect(kA, "async", true);
  send(kA, {registration("GOOD", 0, "async")});
  Message bad_type = notify_double("GOOD", 1, "async");
  bad_type.data_type = 'Z';
  Message nan_interval = registration("R", std::nan(""), "async");
  Message unknown = notify_double("U", 1, "async");
  unknown.type = 'A';
  const auto mail =
      to(send(kA, {notify_double("", 1, "async"), bad_type, nan_interval, unknown,
                   wildcard("AppPattern=*,VarPattern=*,Interval=soon", "async"),
                   notify_double("GOOD", 2, "async")}),
         kA);
  ASSERT_EQ(mail.size(), 1u);
  ASSERT_EQ(mail[0].size(), 1u);
  EXPECT_EQ(mail[0][0].dval, 2.0);
  EXPECT_TRUE(logged("client \"async\": NOTIFY with an empty variable name refused"));
  EXPECT_TRUE(logged("client \"async\": NOTIFY GOOD with data type 'Z' refused"));
  EXPECT_TRUE(logged("client \"async\": REGISTER R with interval"));
  EXPECT_TRUE(logged("client \"async\": message of unknown type 'A'"));
  EXPECT_TRUE(logged("Interval 'soon' is not a number >= 0"));
}

// Client text in a refusal (name, variable, type byte, pattern) cannot end a log line or
// forge one: control bytes and backslashes are escaped.
TEST_F(DatabaseTest, RefusalsEscapeTheClientsText) {
  connect(kA, "p\nEvil", true);
  Message bad_type = notify_double("KEY\nmoosdb-lite: forged", 1, "p\nEvil");
  bad_type.data_type = '\r';
  send(kA, {bad_type, wildcard("AppPattern=*\\,VarPattern=\n,Interval=-1", "p\nEvil")});
  EXPECT_TRUE(logged("client \"p\\x0AEvil\": NOTIFY KEY\\x0Amoosdb-lite: forged with data type "
                     "'\\x0D' refused"));
  EXPECT_TRUE(logged("WILDCARD_REGISTER \"AppPattern=*\\x5C,VarPattern=\\x0A,Interval=-1\""));
  for (const auto& line : logs_) EXPECT_EQ(line.find_first_of("\n\r"), std::string::npos) << line;
}

TEST_F(DatabaseTest, RefusalsBeyondTheLogLimitAreCountedNotLogged) {
  connect(kA, "async", true);
  std::vector<Message> bad(kLoggedRefusalsPerClient + 30, notify_double("", 1, "async"));
  send(kA, bad);
  const std::size_t lines = logs_.size();
  EXPECT_EQ(lines, static_cast<std::size_t>(kLoggedRefusalsPerClient + 1));
  db_.disconnect(kA, kT0);
  EXPECT_TRUE(logged(std::to_string(kLoggedRefusalsPerClient + 30) + " messages refused in total"));
}

TEST_F(DatabaseTest, ObserverSeesEveryAcceptedNotifyOnly) {
  connect(kA, "async", true);
  observed_.clear();
  send(kA, {notify_double("X", 1, "async"), notify_string("X", "no", "async"),
            notify_string("Y", "yes", "async")});
  ASSERT_EQ(observed_.size(), 2u);
  EXPECT_EQ(observed_[0].key, "X");
  EXPECT_EQ(observed_[0].community, "alpha");  // as stored and forwarded
  EXPECT_EQ(observed_[1].sval, "yes");
}

// A short value that replaces a large one gives the large one's memory back: the store keeps
// no buffer sized for a value it no longer holds (a short string moved into a long one is
// copied into the long one's buffer, which then stays).
std::size_t heap_in_use() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;  // large blocks are mapped on their own (hblkhd)
}

TEST_F(DatabaseTest, AShortValueReplacingALargeOneReleasesItsMemory_Hardening) {
  connect(kA, "writer", true);
  const std::size_t before = heap_in_use();
  send(kA, {make_string_notify("BIG", std::string(std::size_t{8} << 20, 'x'), "writer", kT0)});
  send(kA, {make_string_notify("BIG", "x", "writer", kT0)});
  observed_.clear();  // the observer's copies are the test's, not the store's
  observed_.shrink_to_fit();
  ASSERT_EQ(db_.latest("BIG")->sval, "x");
  EXPECT_LT(heap_in_use(), before + (std::size_t{1} << 20));
}

}  // namespace
}  // namespace moos::test
