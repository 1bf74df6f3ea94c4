// Unit tests of moos::Database's ways for a connection layer in the same process
// (moos::InProcessBus): the mail sink, one-message packets and output into a kept list. Each is
// checked against the plain packet path, which the other database tests pin down.
#include <gtest/gtest.h>

#include <deque>
#include <string>
#include <utility>
#include <vector>

#include "database_fixture.hpp"

namespace moos::test {
namespace {

struct Sunk {
  ClientId to;
  Message message;
  bool taken = false;  ///< handed over by take_mail, not copy_mail
};

/// One client's sink: records its mail into a list shared by all clients; a taken message is
/// emptied, as a sink that moves it may leave it.
class RecordingSink final : public MailSink {
 public:
  RecordingSink(ClientId to, std::vector<Sunk>* out) : to_(to), out_(out) {}
  void copy_mail(const Message& msg) override { out_->push_back({to_, msg, false}); }
  void take_mail(Message& msg) override {
    out_->push_back({to_, msg, true});
    msg = Message{};
  }

 private:
  ClientId to_;
  std::vector<Sunk>* out_;
};

/// Two DBs fed the same traffic: `plain` sends every mail in packets, `sunk` hands the
/// asynchronous clients' mail to their sinks.
class DatabaseSinkTest : public ::testing::Test {
 protected:
  static DatabaseConfig config() {
    DatabaseConfig c;
    c.community = "alpha";
    return c;
  }

  void connect(ClientId id, const std::string& name, bool async) {
    ASSERT_TRUE(plain_.connect(id, {identification(name, async)}, kT0));
    sinks_.emplace_back(id, &sink_);
    ASSERT_TRUE(sunk_.connect(id, {identification(name, async)}, kT0, &sinks_.back()));
  }

  /// The packets' messages of `plain` and the sink's of `sunk`, for client `id`.
  void send(ClientId from, const std::vector<Message>& packet, double now = kT0) {
    plain_.process_packet(from, packet, now);
    sunk_.process_packet(from, packet, now);
  }

  static std::vector<Message> mail_of(const std::vector<OutPacket>& out, ClientId id) {
    std::vector<Message> mail;
    for (const auto& p : out)
      if (p.to == id)
        for (const auto& m : p.messages)
          if (m.type == msg_type::kNotify) mail.push_back(m);
    return mail;
  }

  std::vector<Message> sunk_mail_of(ClientId id) const {
    std::vector<Message> mail;
    for (const auto& s : sink_)
      if (s.to == id) mail.push_back(s.message);
    return mail;
  }

  std::vector<Sunk> sink_;
  std::deque<RecordingSink> sinks_;  // one per client; a deque keeps them in place
  Database plain_{config(), kT0, [](const std::string&) {}};
  Database sunk_{config(), kT0, [](const std::string&) {}};
};

TEST_F(DatabaseSinkTest, TheSinkGetsAnAsynchronousClientsMailAsItsPacketsWouldCarryIt) {
  connect(kA, "async", true);
  connect(kB, "pub", true);
  plain_.take_output();
  sunk_.take_output();
  sink_.clear();
  send(kB, {notify_double("X", 0.5, "pub")});  // written before: a snapshot at REGISTER
  send(kA, {registration("X", 0, "async"), registration("Y", 0, "async"),
            wildcard("AppPattern=*,VarPattern=Z_*,Interval=0", "async")});
  std::vector<Message> packet;
  for (int i = 0; i < 30; ++i) packet.push_back(notify_double(i % 3 ? "X" : "Z_1", i, "pub"));
  packet.push_back(notify_string("Y", "text", "pub"));
  send(kB, packet);
  const auto plain_out = plain_.take_output();
  const auto expected = mail_of(plain_out, kA);
  ASSERT_EQ(expected.size(), 1u + 31u);
  EXPECT_EQ(sunk_mail_of(kA), expected);
  EXPECT_TRUE(mail_of(sunk_.take_output(), kA).empty());  // no packet carried it as well
}

TEST_F(DatabaseSinkTest, ASynchronousClientsMailStillWaitsForItsReply) {
  connect(kA, "sync", false);
  connect(kB, "pub", true);
  send(kA, {registration("X", 0, "sync")});
  send(kB, {notify_double("X", 1, "pub")});
  EXPECT_TRUE(sunk_mail_of(kA).empty());
  sunk_.take_output();
  sunk_.process_packet(kA, {null_message("sync")}, kT0);
  const auto reply = sunk_.take_output();
  ASSERT_EQ(reply.size(), 1u);
  ASSERT_EQ(reply[0].messages.size(), 2u);  // the NULL, then the mail
  EXPECT_EQ(reply[0].messages[0].type, msg_type::kNull);
  EXPECT_EQ(reply[0].messages[1].key, "X");
}

TEST_F(DatabaseSinkTest, ATimingEchoStillLeavesInAPacket) {
  connect(kA, "async", true);
  sunk_.take_output();
  sunk_.process_packet(kA, {timing(kT0 - 1)}, kT0 + 2);
  const auto out = sunk_.take_output();
  ASSERT_EQ(out.size(), 1u);
  ASSERT_EQ(out[0].messages.size(), 1u);
  EXPECT_EQ(out[0].messages[0].type, msg_type::kTiming);
  EXPECT_EQ(out[0].messages[0].dval, kT0 + 2);
}

TEST_F(DatabaseSinkTest, APostingsLastReaderGetsTheMessageItselfTheOthersACopy) {
  connect(kA, "first", true);
  connect(kB, "second", true);
  connect(kC, "pub", true);
  send(kA, {registration("X", 0, "first")});
  send(kB, {registration("X", 0, "second")});
  sink_.clear();
  send(kC, {notify_double("X", 1, "pub"), notify_double("X", 2, "pub")});
  ASSERT_EQ(sink_.size(), 4u);  // the readers in connection order, posting by posting
  const std::vector<ClientId> to = {sink_[0].to, sink_[1].to, sink_[2].to, sink_[3].to};
  EXPECT_EQ(to, (std::vector<ClientId>{kA, kB, kA, kB}));
  EXPECT_FALSE(sink_[0].taken);
  EXPECT_TRUE(sink_[1].taken);
  EXPECT_EQ(sink_[0].message, sink_[1].message);  // taken after the copy: the copy is whole
  EXPECT_EQ(sink_[3].message.dval, 2);
  EXPECT_EQ(sunk_.latest("X")->dval, 2);  // stored before the message was given away
}

TEST(DatabaseSink, TheUndeliveredMailBoundStillAppliesPerCall) {
  std::vector<Sunk> sink;
  RecordingSink reader(kA, &sink);
  DatabaseConfig config;
  config.max_pending_bytes = 1000;
  Database db(config, kT0, [](const std::string&) {});
  ASSERT_TRUE(db.connect(kA, {identification("reader", true)}, kT0, &reader));
  ASSERT_TRUE(db.connect(kB, {identification("pub", true)}, kT0));
  db.process_packet(kA, {registration("X", 0, "reader")}, kT0);
  // One message per call: the mail leaves with each call, nothing accumulates.
  for (int i = 0; i < 40; ++i) db.process_packet(kB, {notify_double("X", i, "pub")}, kT0);
  EXPECT_TRUE(db.take_drop_requests().empty());
  EXPECT_EQ(sink.size(), 40u);
  EXPECT_EQ(db.pending_bytes(kA), 0u);
  // One call queuing more than the bound: the client is reported, as without a sink.
  std::vector<Message> packet(40, notify_double("X", 1, "pub"));
  db.process_packet(kB, packet, kT0);
  const auto drops = db.take_drop_requests();
  ASSERT_EQ(drops.size(), 1u);
  EXPECT_EQ(drops[0].id, kA);
}

TEST_F(DatabaseTest, ProcessMessageIsAPacketOfOneMessage) {
  connect(kA, "async", true);
  connect(kB, "sync", false);
  Database twin{config(), kT0, [](const std::string&) {}};
  ASSERT_TRUE(twin.connect(kA, {identification("async", true)}, kT0));
  ASSERT_TRUE(twin.connect(kB, {identification("sync", false)}, kT0));
  twin.take_output();
  const std::vector<Message> traffic = {registration("X", 0, "async"), registration("X", 0, "sync"),
                                        notify_double("X", 2, "async"), timing(kT0),
                                        notify_string("X", "wrong type", "sync")};
  for (const Message& m : traffic) {
    const ClientId from = m.source == "async" ? kA : kB;
    db_.process_packet(from, {m}, kT0 + 1);
    twin.process_message(from, Message(m), kT0 + 1);
    const auto expected = db_.take_output();
    const auto got = twin.take_output();
    ASSERT_EQ(got.size(), expected.size()) << m.key;
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].to, expected[i].to);
      EXPECT_EQ(got[i].messages, expected[i].messages);
    }
  }
}

TEST_F(DatabaseTest, OutputTakenIntoAKeptListReplacesItsContents) {
  connect(kA, "async", true);
  db_.process_packet(kA, {registration("X", 0, "async")}, kT0);
  db_.process_packet(kA, {notify_double("X", 1, "async")}, kT0);
  std::vector<OutPacket> kept(3);  // stale packets from an earlier call
  db_.take_output(kept);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].to, kA);
  EXPECT_EQ(keys(kept[0].messages), std::vector<std::string>{"X"});
  db_.take_output(kept);
  EXPECT_TRUE(kept.empty());
}

}  // namespace
}  // namespace moos::test
