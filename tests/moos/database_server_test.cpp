// Unit tests of moos::Database: DB variables, server requests and limits
// (docs/protocol.md 5.7, 5.8).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "database_fixture.hpp"

namespace moos::test {
namespace {

// ---------------------------------------------------------------------------------------
// DB variables (protocol.md 5.7)

TEST_F(DatabaseTest, DbVariablesAreWrittenAtStartSoEarlyRegistrationsGetSnapshots_5_7) {
  connect(kA, "reader", true);
  const auto mail = to(send(kA, {registration("DB_TIME", 0, "reader"),
                                 registration("DB_UPTIME", 0, "reader")}, kT0 + 0.5),
                       kA);
  ASSERT_EQ(mail.size(), 1u);
  ASSERT_EQ(mail[0].size(), 2u);
  EXPECT_EQ(mail[0][0].dval, kT0);
  EXPECT_EQ(mail[0][0].source, "MOOSDB_alpha");
  EXPECT_EQ(mail[0][0].community, "alpha");
  EXPECT_EQ(mail[0][0].id, -1);
  EXPECT_EQ(mail[0][1].dval, 0.0);
}

TEST_F(DatabaseTest, RefreshWritesTimeUptimeClientsAndRwSummary_5_7) {
  connect(kA, "reader", true);
  connect(kB, "writer", true);
  send(kB, {notify_double("OUT", 1, "writer"), registration("IN", 0, "writer")});
  send(kA, {registration("DB_TIME", 0, "reader"), registration("DB_UPTIME", 0, "reader"),
            registration("DB_CLIENTS", 0, "reader"), registration("DB_RWSUMMARY", 0, "reader")});
  db_.refresh_db_variables(kT0 + 12);
  const auto mail = to(db_.take_output(), kA);
  ASSERT_EQ(mail.size(), 1u);
  ASSERT_EQ(keys(mail[0]),
            (std::vector<std::string>{"DB_TIME", "DB_UPTIME", "DB_CLIENTS", "DB_RWSUMMARY"}));
  EXPECT_EQ(mail[0][0].dval, kT0 + 12);
  EXPECT_EQ(mail[0][0].time, kT0 + 12);
  EXPECT_EQ(mail[0][1].dval, 12.0);
  EXPECT_EQ(mail[0][2].sval, "reader,writer,");
  EXPECT_EQ(mail[0][3].sval,
            "reader=DB_TIME:DB_UPTIME:DB_CLIENTS:DB_RWSUMMARY&,writer=IN&OUT");
}

// ---------------------------------------------------------------------------------------
// Server requests (protocol.md 5.8)

TEST_F(DatabaseTest, VarSummaryIsOneAnswerWithRequestIdAndAllNames_5_8) {
  connect(kA, "logger", true);
  send(kA, {notify_double("A_VAR", 1, "logger"), registration("UNWRITTEN", 0, "logger")});
  const auto mail = to(send(kA, {server_request("VAR_SUMMARY", "logger")}, kT0 + 4), kA);
  ASSERT_EQ(mail.size(), 1u);
  ASSERT_EQ(mail[0].size(), 1u);
  const Message& m = mail[0][0];
  EXPECT_EQ(m.id, -2);
  EXPECT_EQ(m.type, mt::kNotify);
  EXPECT_EQ(m.data_type, dt::kString);
  EXPECT_EQ(m.key, "VAR_SUMMARY");
  EXPECT_EQ(m.source, "MOOSDB_alpha");
  EXPECT_EQ(m.time, kT0 + 4);
  EXPECT_EQ(m.dval, -1.0);
  EXPECT_EQ(m.sval, "DB_TIME,DB_UPTIME,DB_CLIENTS,DB_RWSUMMARY,DB_EVENT,A_VAR,UNWRITTEN");
}

TEST_F(DatabaseTest, AllAnswersOneMessagePerVariableIncludingUnwritten_5_8) {
  connect(kA, "client", false);
  send(kA, {registration("UNWRITTEN", 0, "client")});
  send(kA, {notify_double("D", 2.5, "client")}, kT0 + 10);
  const auto replies = to(send(kA, {server_request("ALL", "client")}, kT0 + 11), kA);
  ASSERT_EQ(replies.size(), 1u);
  std::vector<Message> answers(replies[0].begin() + 1, replies[0].end());  // after the NULL
  ASSERT_EQ(keys(answers), (std::vector<std::string>{"DB_TIME", "DB_UPTIME", "DB_CLIENTS",
                                                     "DB_RWSUMMARY", "DB_EVENT", "UNWRITTEN", "D"}));
  const Message& unwritten = answers[5];
  EXPECT_EQ(unwritten.id, -2);
  EXPECT_EQ(unwritten.data_type, dt::kNotSet);
  EXPECT_EQ(unwritten.time, -1.0);
  const Message& d = answers[6];
  EXPECT_EQ(d.data_type, dt::kDouble);
  EXPECT_EQ(d.dval, 2.5);
  EXPECT_EQ(d.source, "client");
  EXPECT_EQ(d.time, 10.0);  // last DB write time - DB start time
  EXPECT_EQ(d.community, "alpha");
}

TEST_F(DatabaseTest, ProcSummaryListsSubscriptionsAndPublicationsPerClient_5_8) {
  connect(kA, "pA", true);
  connect(kB, "pB", true);
  send(kB, {registration("S1", 0, "pB"), registration("S2", 0, "pB"), notify_double("P1", 1, "pB")});
  const auto mail = to(send(kA, {server_request("PROC_SUMMARY", "pA")}, kT0 + 3), kA);
  ASSERT_EQ(mail.size(), 1u);
  ASSERT_EQ(mail[0].size(), 2u);
  EXPECT_EQ(mail[0][0].sval, "pA:SUBSCRIBED=,PUBLISHED=");
  EXPECT_EQ(mail[0][1].sval, "pB:SUBSCRIBED=,S1,S2,PUBLISHED=,P1");
  EXPECT_EQ(mail[0][1].key, "PROC_SUMMARY");
  EXPECT_EQ(mail[0][1].id, -2);
  EXPECT_EQ(mail[0][1].time, 3.0);  // uptime
}

TEST_F(DatabaseTest, DbClearForgetsValuesAndPendingMail_5_8) {
  connect(kA, "sync", false);
  connect(kB, "writer", true);
  send(kA, {registration("X", 0, "sync")});
  send(kB, {notify_double("X", 1, "writer")});
  const auto out = send(kB, {server_request("DB_CLEAR", "writer")});
  EXPECT_TRUE(to(out, kB).empty());  // no answer
  const auto replies = to(send(kA, {null_message("sync"), registration("X", 0, "sync")}), kA);
  ASSERT_EQ(replies.size(), 1u);
  EXPECT_EQ(replies[0].size(), 1u);  // the NULL only: no old mail, no snapshot
  // The type is free again: a string write is accepted and delivered.
  send(kB, {notify_string("X", "new", "writer")});
  const auto after = to(send(kA, {null_message("sync")}), kA);
  ASSERT_EQ(after[0].size(), 2u);
  EXPECT_EQ(after[0][1].sval, "new");
}

TEST_F(DatabaseTest, UnknownServerRequestGetsNoAnswerAndIsLogged_5_8) {
  connect(kA, "async", true);
  EXPECT_TRUE(to(send(kA, {server_request("WHAT_IS_THIS", "async")}), kA).empty());
  EXPECT_TRUE(logged("unknown server request \"WHAT_IS_THIS\""));
}

// ---------------------------------------------------------------------------------------
// Limits

TEST(DatabaseLimits, ClientWhoseUndeliveredMailOverflowsIsReportedForDropping) {
  DatabaseConfig config;
  config.max_pending_bytes = 1000;
  std::vector<std::string> logs;
  Database db(config, kT0, [&](const std::string& l) { logs.push_back(l); });
  ASSERT_TRUE(db.connect(kA, {identification("lazy", false)}, kT0));
  ASSERT_TRUE(db.connect(kB, {identification("pub", true)}, kT0));
  db.process_packet(kA, {registration("X", 0, "lazy")}, kT0);
  for (int i = 0; i < 20; ++i) db.process_packet(kB, {notify_double("X", i, "pub")}, kT0);
  const auto drops = db.take_drop_requests();
  ASSERT_EQ(drops.size(), 1u);
  EXPECT_EQ(drops[0].id, kA);
  EXPECT_NE(drops[0].reason.find("exceed 1000 bytes"), std::string::npos);
}

// The mail a synchronous client has not collected is what the server's memory budget counts.
TEST(DatabaseLimits, PendingBytesCountTheMailASyncClientHasNotCollected) {
  Database db(DatabaseConfig{}, kT0, [](const std::string&) {});
  ASSERT_TRUE(db.connect(kA, {identification("lazy", false)}, kT0));
  ASSERT_TRUE(db.connect(kB, {identification("pub", true)}, kT0));
  db.process_packet(kA, {registration("X", 0, "lazy")}, kT0);
  EXPECT_EQ(db.pending_bytes(kA), 0u);
  db.process_packet(kB, {notify_string("X", std::string(500, 'x'), "pub")}, kT0);
  const std::size_t one = db.pending_bytes(kA);
  EXPECT_GT(one, 500u);
  db.process_packet(kB, {notify_string("X", std::string(500, 'x'), "pub")}, kT0);
  EXPECT_EQ(db.pending_bytes(kA), 2 * one);
  EXPECT_EQ(db.pending_bytes(kB), 0u);  // an asynchronous client's mail leaves at once
  db.process_packet(kA, {null_message("lazy")}, kT0);
  EXPECT_EQ(db.pending_bytes(kA), 0u);
  EXPECT_EQ(db.pending_bytes(kC), 0u);
}

// The store is bounded: new names and larger values that would take it beyond
// max_stored_bytes are refused with a logged reason, the client stays, smaller writes and the
// DB's own variables go on, and DB_CLEAR gives the room back.
TEST(DatabaseLimits, WritesAndRegistrationsBeyondTheStoreBoundAreRefused_Hardening) {
  DatabaseConfig config;
  config.max_stored_bytes = 64 * 1024;
  std::vector<std::string> logs;
  Database db(config, kT0, [&](const std::string& l) { logs.push_back(l); });
  ASSERT_TRUE(db.connect(kA, {identification("flooder", true)}, kT0));
  ASSERT_TRUE(db.connect(kB, {identification("reader", true)}, kT0));
  const std::size_t at_start = db.stored_bytes();
  int accepted = 0;
  for (int i = 0; i < 100; ++i) {  // 100 variables of 4 kB: 400 kB asked, 64 kB allowed
    const std::string name = "V" + std::to_string(i);
    db.process_packet(kA, {notify_string(name, std::string(4096, 'v'), "flooder")}, kT0 + 1);
    if (db.latest(name)) ++accepted;
  }
  EXPECT_GT(accepted, 5);
  EXPECT_LT(accepted, 20);
  EXPECT_LE(db.stored_bytes(), config.max_stored_bytes);
  EXPECT_GT(db.stored_bytes(), at_start + accepted * 4096u);
  const auto refused = [&](const std::string& what) {
    for (const auto& l : logs)
      if (l.find(what) != std::string::npos &&
          l.find("the store would hold more than its 65536 bytes") != std::string::npos)
        return true;
    return false;
  };
  EXPECT_TRUE(refused("NOTIFY V" + std::to_string(accepted) + " refused"));
  // (the flooder's later refusals are only counted: another client registers)
  db.process_packet(kB, {registration("NEVER_WRITTEN_" + std::string(64 * 1024, 'n'), 0, "reader")},
                    kT0 + 1);
  EXPECT_TRUE(refused("REGISTER NEVER_WRITTEN_nnn"));
  for (const auto& l : logs) EXPECT_LT(l.size(), 400u) << "a refusal quotes an excerpt only";
  // A smaller value for a stored variable still fits; the client is still served.
  db.process_packet(kA, {notify_string("V0", "small", "flooder")}, kT0 + 2);
  EXPECT_EQ(db.latest("V0")->sval, "small");
  db.process_packet(kB, {registration("V1", 0, "reader")}, kT0 + 2);
  EXPECT_TRUE(db.is_connected(kA));
  db.refresh_db_variables(kT0 + 3);  // the DB's own variables are always written
  EXPECT_DOUBLE_EQ(db.latest("DB_TIME")->dval, kT0 + 3);
  // DB_CLEAR frees the values: the next write fits again.
  db.process_packet(kA, {server_request("DB_CLEAR", "flooder")}, kT0 + 4);
  EXPECT_LT(db.stored_bytes(), 64 * 1024u / 2);
  db.process_packet(kA, {notify_string("V99", std::string(4096, 'v'), "flooder")}, kT0 + 5);
  EXPECT_TRUE(db.latest("V99").has_value());
}

}  // namespace
}  // namespace moos::test

namespace moos::test {
namespace {

// A synchronous client's reply never exceeds what a client accepts: the rest of its mail
// waits, in order, for its next replies (limits in codec.hpp).
TEST(DatabaseLimits, ASynchronousReplyHoldsAtMostMaxReplyBytesAndTheRestWaitsInOrder) {
  DatabaseConfig config;
  config.max_reply_bytes = 4096;
  Database db(config, kT0, [](const std::string&) {});
  ASSERT_TRUE(db.connect(kA, {identification("sync", false)}, kT0));
  ASSERT_TRUE(db.connect(kB, {identification("pub", true)}, kT0));
  db.process_packet(kA, {registration("X", 0, "sync")}, kT0);
  db.take_output();
  for (int i = 0; i < 10; ++i)
    db.process_packet(kB, {notify_string("X", std::string(1000, 'a' + i), "pub")}, kT0);
  db.take_output();
  std::vector<char> seen;
  for (int reply = 0; reply < 10 && seen.size() < 10; ++reply) {
    db.process_packet(kA, {null_message("sync")}, kT0);
    const auto out = db.take_output();
    ASSERT_EQ(out.size(), 1u);
    EXPECT_LE(encode_packet(out[0].messages).size(), config.max_reply_bytes);
    EXPECT_EQ(out[0].messages.front().type, msg_type::kNull);
    for (std::size_t i = 1; i < out[0].messages.size(); ++i)
      seen.push_back(out[0].messages[i].sval.front());
  }
  ASSERT_EQ(seen.size(), 10u);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(seen[static_cast<std::size_t>(i)], 'a' + i);
  EXPECT_EQ(db.pending_bytes(kA), 0u);
}

// A value no client could receive is refused where it enters the server, naming it; nothing
// is stored or relayed, and the client stays.
TEST(DatabaseLimits, ANotifyLargerThanAClientAcceptsIsRefusedNamingTheVariable) {
  std::vector<std::string> logs;
  Database db(DatabaseConfig{}, kT0, [&](const std::string& l) { logs.push_back(l); });
  ASSERT_TRUE(db.connect(kA, {identification("big", true)}, kT0));
  ASSERT_TRUE(db.connect(kB, {identification("reader", true)}, kT0));
  db.process_packet(kB, {registration("HUGE", 0, "reader")}, kT0);
  db.take_output();
  db.process_packet(kA, {notify_string("HUGE", std::string(kMaxMessageBytes, 'h'), "big")}, kT0);
  EXPECT_FALSE(db.latest("HUGE").has_value());
  for (const OutPacket& packet : db.take_output()) EXPECT_NE(packet.to, kB);
  ASSERT_FALSE(logs.empty());
  EXPECT_NE(logs.back().find("NOTIFY HUGE refused: its"), std::string::npos) << logs.back();
  EXPECT_NE(logs.back().find("a client accepts"), std::string::npos) << logs.back();
  db.process_packet(kA, {notify_string("HUGE", "fits", "big")}, kT0);
  EXPECT_EQ(db.latest("HUGE")->sval, "fits");
}

}  // namespace
}  // namespace moos::test
