// TcpClient against a scripted fake server on 127.0.0.1 (docs/protocol.md 1.4-1.9, 4.3, 4.4, 4.6
// and the
// vectors E, F, I, N of section 8). Every wait is bounded; the server socket is closed by RAII.
#include <atomic>

#include "tcp_client_fixture.hpp"

namespace moos {
namespace test {
namespace {

TEST_F(TcpClientTest, BannerAndIdentificationMatchVectorE_1_4_1_5) {
  TcpClient client(options());
  ASSERT_TRUE(client.start());
  ASSERT_TRUE(server.accept());
  const auto banner = server.read_exact(32);
  ASSERT_TRUE(banner.has_value());
  EXPECT_EQ(*banner, protocol_banner());
  const auto ident = server.read_packet_bytes();
  ASSERT_TRUE(ident.has_value());
  EXPECT_EQ(*ident, hex_bytes("50 00 00 00 01 00 00 00 00 47 00 00 00 ff ff ff"
                              "ff 69 53 00 00 00 00 00 00 00 00 00 00 00 00 0c"
                              "00 00 00 61 73 79 6e 63 68 72 6f 6e 6f 75 73 00"
                              "00 00 40 fc 54 d9 41 00 00 00 00 00 00 f0 bf 00"
                              "00 00 00 00 00 f0 bf 05 00 00 00 70 54 65 73 74"));
  EXPECT_EQ(client.state(), ConnectionState::kConnecting);
}

TEST_F(TcpClientTest, WelcomeGivesCommunityHostAndSkew_1_7_1_8) {
  TcpClient client(options());
  std::atomic<int> connects{0};
  client.set_on_connect([&] { ++connects; });
  ASSERT_TRUE(client.start());
  handshake(0.001);
  ASSERT_TRUE(client.wait_until_connected(kWait_s));
  EXPECT_EQ(client.community(), "alpha");
  EXPECT_EQ(client.server_hostname(), "dbhost");
  EXPECT_TRUE(client.server_is_asynchronous());
  EXPECT_DOUBLE_EQ(client.skew_s(), 0.001);
  EXPECT_DOUBLE_EQ(client.moos_time(), kT0 + 0.001);
  EXPECT_EQ(client.connection_count(), 1u);
  // The callback runs on the comms thread right after the handshake.
  const double deadline = steady_now_s() + kWait_s;
  while (connects == 0 && steady_now_s() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(connects, 1);
}

TEST_F(TcpClientTest, SameHostWelcomeSkewIsIgnoredLikeLibMoos_1_8) {
  auto o = options();
  o.own_hostname = "dbhost";
  TcpClient client(o);
  ASSERT_TRUE(client.start());
  handshake(5.0);
  ASSERT_TRUE(client.wait_until_connected(kWait_s));
  EXPECT_EQ(client.skew_s(), 0.0);
}

TEST_F(TcpClientTest, SkewPolicyAlwaysAdoptsItEvenOnTheSameHost_1_8) {
  auto o = options();
  o.own_hostname = "dbhost";
  o.skew_policy = SkewPolicy::kAlways;
  TcpClient client(o);
  ASSERT_TRUE(client.start());
  handshake(5.0);
  ASSERT_TRUE(client.wait_until_connected(kWait_s));
  EXPECT_EQ(client.skew_s(), 5.0);
}

TEST_F(TcpClientTest, PoisonStopsTheClientForGood_1_7) {
  auto o = options();
  o.time_warp = 20.0;  // a retry would come after 50 ms
  TcpClient client(o);
  ASSERT_TRUE(client.start());
  ASSERT_TRUE(server.accept());
  ASSERT_TRUE(server.read_exact(32).has_value());
  ASSERT_TRUE(server.read_packet().has_value());
  Message poison;
  poison.type = msg_type::kPoison;
  poison.data_type = data_type::kString;
  poison.time = kT0;
  poison.sval = "A client of this name (\"pTest\") already exists";
  server.send({poison});
  EXPECT_FALSE(client.wait_until_connected(kWait_s));
  EXPECT_EQ(client.state(), ConnectionState::kPoisoned);
  EXPECT_NE(client.last_error().find("already exists"), std::string::npos);
  EXPECT_FALSE(server.accept(0.5));  // no second attempt
  EXPECT_FALSE(client.notify("X", 1.0));
}

TEST_F(TcpClientTest, RegistrationsAndNotificationsGoOutWithIncreasingIds_2_5) {
  TcpClient client(options());
  ASSERT_NO_FATAL_FAILURE(connect(client));
  ASSERT_TRUE(client.register_variable("NAV_X", 0.5));
  ASSERT_TRUE(client.notify("DEPTH", 12.5));
  ASSERT_TRUE(client.notify("MODE", std::string("SURVEY")));
  ASSERT_TRUE(client.notify_binary("BLOB", std::string("\x00\xff\x10\x7f", 4)));
  ASSERT_TRUE(client.flush(kWait_s));
  std::vector<Message> got;
  const double deadline = steady_now_s() + kWait_s;
  while (got.size() < 4 && steady_now_s() < deadline) {
    auto pkt = server.read_packet(deadline - steady_now_s());
    ASSERT_TRUE(pkt.has_value());
    ASSERT_FALSE(pkt->empty());  // never an empty packet (protocol.md 3.4)
    for (auto& m : *pkt)
      if (m.type != msg_type::kTiming) got.push_back(m);
  }
  ASSERT_EQ(got.size(), 4u);
  EXPECT_EQ(got[0].type, msg_type::kRegister);
  EXPECT_EQ(got[0].dval, 0.5);
  EXPECT_EQ(got[0].id, 0);
  EXPECT_EQ(got[1].id, 1);
  EXPECT_EQ(got[1].dval, 12.5);
  EXPECT_EQ(got[1].source, "pTest");
  EXPECT_EQ(got[1].time, kT0 + 0.001);  // MOOS time: local + skew
  EXPECT_EQ(got[2].sval, "SURVEY");
  EXPECT_EQ(got[3].data_type, data_type::kBinary);
  EXPECT_EQ(got[3].sval, std::string("\x00\xff\x10\x7f", 4));
  EXPECT_EQ(got[3].id, 3);
}

TEST_F(TcpClientTest, FirstPacketLeadsWithTimingMatchingVectorI_4_3) {
  TcpClient client(options());
  ASSERT_TRUE(client.start());
  ASSERT_TRUE(server.accept());
  ASSERT_TRUE(server.read_exact(32).has_value());
  ASSERT_TRUE(server.read_packet().has_value());
  server.send({welcome(0.0)});  // skew 0: the TIMING time is then exactly kT0
  const auto first = server.read_packet_bytes();
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(*first, hex_bytes("4c 00 00 00 01 00 00 00 00 43 00 00 00 ff ff ff"
                              "ff 54 44 00 00 00 00 00 00 00 00 00 00 00 00 0d"
                              "00 00 00 5f 61 73 79 6e 63 5f 74 69 6d 69 6e 67"
                              "00 00 00 40 fc 54 d9 41 00 00 00 00 00 00 00 00"
                              "00 00 00 00 00 00 f0 bf 00 00 00 00"));
}

TEST_F(TcpClientTest, IdleClientSendsTimingAtLeastOncePerSecond_4_6) {
  TcpClient client(options());
  ASSERT_TRUE(client.start());
  handshake();
  std::vector<double> arrivals;
  const double deadline = steady_now_s() + 2.6;
  while (steady_now_s() < deadline) {
    auto pkt = server.read_packet(deadline - steady_now_s());
    if (!pkt) break;
    ASSERT_EQ(pkt->size(), 1u);
    EXPECT_EQ(pkt->at(0).type, msg_type::kTiming);
    EXPECT_EQ(pkt->at(0).source, "");
    arrivals.push_back(steady_now_s());
  }
  ASSERT_GE(arrivals.size(), 3u);
  for (std::size_t i = 1; i < arrivals.size(); ++i)
    EXPECT_LT(arrivals[i] - arrivals[i - 1], 1.0);
}

TEST_F(TcpClientTest, LeadingTimingIsConsumedAndRefinesTheSkew_4_4) {
  TcpClient client(options());
  ASSERT_TRUE(client.start());
  handshake(0.0);
  ASSERT_TRUE(client.wait_until_connected(kWait_s));
  Message mail = make_double_notify("X", 1.0, "other", kT0);
  // The manual clock stands still, so Tq = Tr = kT0 and measured = Ts - kT0.
  server.send({timing_echo(kT0, kT0 + 0.2), mail});
  const double deadline = steady_now_s() + kWait_s;
  std::vector<Message> got;
  while (got.empty() && steady_now_s() < deadline) {
    got = client.fetch();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].key, "X");
  EXPECT_NEAR(client.skew_s(), 0.2, 1e-6);  // current skew was exactly 0: adopt the measurement
  server.send({timing_echo(kT0, kT0 + 1.2), mail});
  got.clear();
  while (got.empty() && steady_now_s() < deadline) {
    got = client.fetch();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  // Measured with the new skew: Tq and Tr are local times, so measured = 1.2; 0.9*0.2 + 0.1*1.2.
  EXPECT_NEAR(client.skew_s(), 0.3, 1e-6);
}

TEST_F(TcpClientTest, MailIsDecodedIntoTheStorageOfMailTheAppHasRead) {
  TcpClient client(options());
  std::atomic<bool> mail_waiting{false};
  client.set_on_mail([&] { mail_waiting = true; });
  ASSERT_NO_FATAL_FAILURE(connect(client));
  std::vector<Message> mail;
  // One message at a time, fetched once announced: its value (beyond the small-string buffer)
  // is the storage the test follows.
  auto next = [&](char fill) {
    mail_waiting = false;
    server.send({make_string_notify("REPORT", std::string(200, fill), "s", kT0)});
    const double deadline = steady_now_s() + kWait_s;
    while (!mail_waiting && steady_now_s() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    client.fetch_into(mail);
    return mail.size() == 1 && mail[0].sval == std::string(200, fill);
  };
  ASSERT_TRUE(next('a'));
  const char* first = mail[0].sval.data();
  ASSERT_TRUE(next('b'));  // hands the first back, to be traded for the next decoded message
  const std::string blocker(200, 'x');  // had the first been freed, this would take its storage
  ASSERT_TRUE(next('c'));  // decoded into new storage, traded for the first's
  ASSERT_TRUE(next('d'));  // decoded into the first's storage
  EXPECT_EQ(mail[0].sval.data(), first);
  EXPECT_NE(blocker.data(), first);
}

TEST_F(TcpClientTest, NullsAndStrayTimingsAreDroppedNotSetTypesDelivered_4_6) {
  TcpClient client(options());
  ASSERT_NO_FATAL_FAILURE(connect(client));
  Message null_msg;  // default message: type '.'
  Message not_set = make_double_notify("UNSET", 0.0, "", kT0);
  not_set.data_type = data_type::kNotSet;
  server.send({make_double_notify("A", 1.0, "s", kT0), null_msg, timing_echo(kT0, kT0), not_set});
  server.send({null_msg});
  server.send({make_string_notify("B", "b", "s", kT0)});
  std::vector<Message> got;
  const double deadline = steady_now_s() + kWait_s;
  while (got.size() < 3 && steady_now_s() < deadline) {
    for (auto& m : client.fetch()) got.push_back(m);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0].key, "A");
  EXPECT_EQ(got[1].key, "UNSET");
  EXPECT_EQ(got[1].data_type, data_type::kNotSet);
  EXPECT_EQ(got[2].key, "B");
}

TEST_F(TcpClientTest, MailFollowingWelcomeInTheSameSegmentIsKept_5_1a) {
  TcpClient client(options());
  ASSERT_TRUE(client.start());
  ASSERT_TRUE(server.accept());
  ASSERT_TRUE(server.read_exact(32).has_value());
  ASSERT_TRUE(server.read_packet().has_value());
  server.send_bytes(encode_packet({welcome(0.0)}) +
                    encode_packet({make_double_notify("EARLY", 7.0, "s", kT0)}));
  ASSERT_TRUE(client.wait_until_connected(kWait_s));
  std::vector<Message> got;
  const double deadline = steady_now_s() + kWait_s;
  while (got.empty() && steady_now_s() < deadline) {
    got = client.fetch();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].key, "EARLY");
}

TEST_F(TcpClientTest, ReconnectsAndResendsEveryRegistrationFirst_1_9) {
  auto o = options();
  o.time_warp = 10.0;  // retry after 0.1 s
  TcpClient client(o);
  std::atomic<int> connects{0};
  client.set_on_connect([&] { ++connects; });
  ASSERT_NO_FATAL_FAILURE(connect(client));
  client.register_variable("A", 0.0);
  client.register_wildcard("NAV_*", "*", 0.5);
  client.register_variable("B", 2.0);
  ASSERT_TRUE(client.flush(kWait_s));

  server.drop();  // the server goes away
  const double deadline = steady_now_s() + kWait_s;
  while (client.is_connected() && steady_now_s() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_FALSE(client.is_connected());
  // Postings made while disconnected wait for the reconnect and follow the replay (comms.hpp).
  EXPECT_TRUE(client.notify("X", 1.0));
  EXPECT_TRUE(client.notify("Y", "two"));

  handshake();
  ASSERT_TRUE(client.wait_until_connected(kWait_s));
  EXPECT_EQ(client.connection_count(), 2u);
  const auto pkt = server.read_non_timing();
  ASSERT_TRUE(pkt.has_value());
  std::vector<Message> regs;
  for (const auto& m : *pkt)
    if (m.type != msg_type::kTiming) regs.push_back(m);
  ASSERT_EQ(regs.size(), 5u);
  EXPECT_EQ(regs[0].type, msg_type::kRegister);
  EXPECT_EQ(regs[0].key, "A");
  EXPECT_EQ(regs[1].type, msg_type::kWildcardRegister);
  EXPECT_EQ(regs[1].sval, "AppPattern=*,VarPattern=NAV_*,Interval=0.5");
  EXPECT_EQ(regs[2].key, "B");
  EXPECT_EQ(regs[2].dval, 2.0);
  EXPECT_EQ(regs[3].type, msg_type::kNotify);
  EXPECT_EQ(regs[3].key, "X");
  EXPECT_EQ(regs[4].key, "Y");
  EXPECT_EQ(regs[4].sval, "two");
  const double cb_deadline = steady_now_s() + kWait_s;
  while (connects < 2 && steady_now_s() < cb_deadline) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(connects, 2);
}

TEST_F(TcpClientTest, SilentServerTimesOutTheHandshakeAndIsRetried) {
  auto o = options();
  o.handshake_timeout_real_s = 0.2;
  o.time_warp = 10.0;
  TcpClient client(o);
  ASSERT_TRUE(client.start());
  ASSERT_TRUE(server.accept());
  ASSERT_TRUE(server.read_exact(32).has_value());
  EXPECT_TRUE(server.peer_closed());
  EXPECT_NE(client.last_error().find("no reply"), std::string::npos);
  handshake();  // the retry
  EXPECT_TRUE(client.wait_until_connected(kWait_s));
}

TEST_F(TcpClientTest, GarbageFromTheServerClosesTheConnection_2_7) {
  auto o = options();
  o.time_warp = 10.0;
  TcpClient client(o);
  ASSERT_NO_FATAL_FAILURE(connect(client));
  server.send_bytes(std::string("\x05\x00\x00\x00", 4));  // a header announcing 5 bytes
  EXPECT_TRUE(server.peer_closed());
  EXPECT_NE(client.last_error().find("bad packet"), std::string::npos);
  handshake();
  EXPECT_TRUE(client.wait_until_connected(kWait_s));
}

TEST_F(TcpClientTest, CloseEndsTheThreadAndClosesTheSocket) {
  auto client = std::make_unique<TcpClient>(options());
  ASSERT_TRUE(client->start());
  handshake();
  ASSERT_TRUE(client->wait_until_connected(kWait_s));
  client->close();
  EXPECT_EQ(client->state(), ConnectionState::kClosed);
  EXPECT_TRUE(server.peer_closed());
  EXPECT_FALSE(client->notify("X", 1.0));
  client.reset();  // the destructor after close() is fine
}

TEST_F(TcpClientTest, RefusedConnectionIsRetriedOncePerMoosSecond_1_9) {
  int port = 0;
  {
    FakeServer gone;  // a port that nobody listens on once this scope ends
    port = gone.port();
  }
  auto o = options();
  o.port = port;
  o.time_warp = 10.0;
  TcpClient client(o);
  ASSERT_TRUE(client.start());
  EXPECT_FALSE(client.wait_until_connected(0.5));
  EXPECT_EQ(client.state(), ConnectionState::kConnecting);
  EXPECT_FALSE(client.last_error().empty());
}

TEST(TcpClientOptionsCheck, InvalidOptionsAreRefusedAtStart) {
  TcpClientOptions o;
  o.name = "";
  TcpClient a(o);
  EXPECT_FALSE(a.start());
  EXPECT_NE(a.last_error().find("name"), std::string::npos);
  o.name = "x";
  o.port = 0;
  TcpClient b(o);
  EXPECT_FALSE(b.start());
  o.port = 9000;
  o.time_warp = 0;
  TcpClient c(o);
  EXPECT_FALSE(c.start());
  EXPECT_NE(c.last_error().find("warp"), std::string::npos);
}

}  // namespace
}  // namespace test
}  // namespace moos
