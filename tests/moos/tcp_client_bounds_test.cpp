// TcpClient's bounds and batching against the fake server: the inbox bounds and one
// packet per app cycle (Comms::hold_sends).
#include "tcp_client_fixture.hpp"

namespace moos {
namespace test {
namespace {

// An app cycle's postings leave in one packet (Comms::hold_sends), however long the cycle.
TEST_F(TcpClientTest, HeldSendsLeaveTogetherInOnePacket) {
  TcpClient client(options());
  ASSERT_NO_FATAL_FAILURE(connect(client));
  ASSERT_TRUE(server.read_packet(kWait_s).has_value());  // the first TIMING; the next in 0.75 s
  client.hold_sends();
  for (const char* var : {"A", "B", "C"}) {
    ASSERT_TRUE(client.notify(var, 1.0));
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // unheld, A would leave alone
  }
  client.release_sends();
  const double deadline = steady_now_s() + kWait_s;
  std::vector<std::vector<std::string>> packets;  // the notifications of each packet
  std::size_t seen = 0;
  while (seen < 3 && steady_now_s() < deadline) {
    auto pkt = server.read_packet(deadline - steady_now_s());
    ASSERT_TRUE(pkt.has_value());
    std::vector<std::string> keys;
    for (auto& m : *pkt)
      if (m.type == msg_type::kNotify) keys.push_back(m.key);
    seen += keys.size();
    if (!keys.empty()) packets.push_back(keys);
  }
  std::string listed;
  for (const auto& keys : packets) {
    listed += "[";
    for (const auto& k : keys) listed += k + " ";
    listed += "]";
  }
  ASSERT_EQ(packets.size(), 1u) << listed;
  EXPECT_EQ(packets[0], (std::vector<std::string>{"A", "B", "C"}));
}

TEST_F(TcpClientTest, AFullInboxDropsTheOldestMailAndCountsIt_Hardening) {
  TcpClientOptions o = options();
  o.max_inbox_messages = 8;
  TcpClient client(o);
  ASSERT_NO_FATAL_FAILURE(connect(client));
  std::vector<Message> flood;
  for (int i = 0; i < 20; ++i) flood.push_back(make_double_notify("N", i, "s", kT0));
  server.send(flood);
  wait_for_drops(client, 12);
  const std::vector<Message> kept = client.fetch();
  // 20 arrived, the bound is 8: the oldest were dropped down to 3/4 of the bound, the newest kept.
  ASSERT_FALSE(kept.empty());
  EXPECT_LE(kept.size(), 8u);
  EXPECT_EQ(kept.size() + client.mail_dropped(), 20u);
  EXPECT_EQ(kept.back().dval, 19.0);
  EXPECT_EQ(kept.front().dval, 20.0 - static_cast<double>(kept.size()));
}

TEST_F(TcpClientTest, TheInboxByteBoundHoldsForLargeMessages_Hardening) {
  TcpClientOptions o = options();
  o.max_inbox_bytes = 64 * 1024;
  TcpClient client(o);
  ASSERT_NO_FATAL_FAILURE(connect(client));
  for (int i = 0; i < 10; ++i)
    server.send({make_string_notify("BIG", std::string(20000, static_cast<char>('a' + i)), "s", kT0)});
  wait_for_drops(client, 7);
  const std::vector<Message> kept = client.fetch();
  std::size_t bytes = 0;
  for (const Message& m : kept) bytes += m.sval.size();
  EXPECT_LE(bytes, o.max_inbox_bytes);
  EXPECT_EQ(kept.size() + client.mail_dropped(), 10u);
  ASSERT_FALSE(kept.empty());
  EXPECT_EQ(kept.back().sval[0], 'j');  // the newest survives
}

TEST_F(TcpClientTest, AnAppShowsTheDroppedMailAsOneStandingRunWarning_Hardening) {
  TcpClientOptions o = options();
  o.max_inbox_messages = 8;
  TcpClient client(o);
  ASSERT_NO_FATAL_FAILURE(connect(client));
  MoosApp app(AppTraits{"pQuiet", 4.0});
  AppSettings settings;
  settings.app_name = settings.moos_name = "pQuiet";
  ASSERT_TRUE(app.start(client, settings));
  for (int flood = 1; flood <= 2; ++flood) {
    std::vector<Message> burst;
    for (int i = 0; i < 20; ++i) burst.push_back(make_double_notify("N", i, "s", kT0));
    server.send(burst);
    wait_for_drops(client, 14u * static_cast<unsigned>(flood));
    app.cycle();
  }
  EXPECT_EQ(client.mail_dropped(), 28u);
  ASSERT_EQ(app.appcast().run_warning_count(), 1u);  // the count grows in one warning
  EXPECT_EQ(app.appcast().run_warnings().begin()->first,
            "Mail arrived faster than the app read it: 28 oldest unread messages dropped in all "
            "(inbox bounds)");
}

// Postings made before the first connection wait in the bounded outbox; one beyond the bound
// is refused, counted and named; the kept ones follow the handshake in order (comms.hpp).
TEST_F(TcpClientTest, TheOutboxKeepsPostingsUntilConnectedAndCountsWhatItRefuses) {
  auto o = options();
  o.max_outbox_messages = 3;
  TcpClient client(o);
  ASSERT_TRUE(client.register_variable("R"));  // remembered, replayed: never queued
  ASSERT_TRUE(client.start());
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(client.notify("KEPT", static_cast<double>(i)));
  EXPECT_FALSE(client.notify("OVER", 9.0));
  EXPECT_EQ(client.postings_dropped(), 1u);
  EXPECT_NE(client.last_post_error().find("NOTIFY OVER refused: the outbox holds its 3 messages"),
            std::string::npos)
      << client.last_post_error();
  ASSERT_NO_FATAL_FAILURE(handshake());
  ASSERT_TRUE(client.wait_until_connected(kWait_s));
  std::vector<Message> sent;
  const double deadline = steady_now_s() + kWait_s;
  while (sent.size() < 4 && steady_now_s() < deadline) {
    auto pkt = server.read_packet(deadline - steady_now_s());
    ASSERT_TRUE(pkt.has_value());
    for (auto& m : *pkt)
      if (m.type != msg_type::kTiming) sent.push_back(m);
  }
  ASSERT_EQ(sent.size(), 4u);
  EXPECT_EQ(sent[0].type, msg_type::kRegister);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(sent[static_cast<std::size_t>(i) + 1].key, "KEPT");
    EXPECT_EQ(sent[static_cast<std::size_t>(i) + 1].dval, static_cast<double>(i));
  }
  EXPECT_TRUE(client.flush(kWait_s));
  EXPECT_TRUE(client.notify("OVER", 9.0));  // room again
}

// A closed client takes nothing, and does not count it as a drop.
TEST_F(TcpClientTest, AClosedClientRefusesPostingsWithoutCountingThem) {
  TcpClient client(options());
  ASSERT_NO_FATAL_FAILURE(connect(client));
  client.close();
  EXPECT_FALSE(client.notify("X", 1.0));
  EXPECT_EQ(client.postings_dropped(), 0u);
}

}  // namespace
}  // namespace test
}  // namespace moos
