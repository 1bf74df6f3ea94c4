// Unit tests of the connection state machine (protocol.md 5.1a) without sockets: bytes in, actions
// out. Timeouts are driven by the `now` given to tick().

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "hub.hpp"
#include "moos/codec.hpp"
#include "wire_messages.hpp"

namespace moosdb_lite {
namespace {

using moos::Message;
using namespace moos::test;
namespace mt = moos::msg_type;

constexpr double kStart = kT0;

class HubTest : public ::testing::Test {
 protected:
  static HubConfig config() {
    HubConfig c;
    c.database.community = "alpha";
    c.database.hostname = "dbhost";
    c.max_packet_bytes = 4096;
    c.banner_timeout_s = 1.0;
    c.handshake_timeout_s = 2.0;
    c.client_timeout_s = 3.0;
    return c;
  }

  /// Sends decoded, in order, and closes seen for `id` since the last call.
  struct Seen {
    std::vector<std::vector<Message>> packets;
    bool closed = false;
    bool closed_after_send = false;
  };
  Seen seen(ConnectionId id) {
    Seen s;
    for (const auto& a : hub_.take_actions()) {
      if (a.id != id) continue;
      EXPECT_FALSE(s.closed || s.closed_after_send) << "action after close";
      if (a.kind == Action::Kind::kSend) {
        auto packet = moos::decode_packet(a.bytes);
        EXPECT_TRUE(packet.has_value());
        if (packet) s.packets.push_back(*packet);
      } else if (a.kind == Action::Kind::kClose) {
        s.closed = true;
      } else {
        s.closed_after_send = true;
      }
    }
    return s;
  }

  static std::string handshake_bytes(const std::string& name, bool async) {
    return moos::protocol_banner() + moos::encode_packet({identification(name, async, kStart)});
  }

  /// A connected client; its actions so far are discarded.
  ConnectionId connected(const std::string& name, bool async) {
    const ConnectionId id = hub_.open("127.0.0.1:" + name, kStart);
    hub_.receive(id, handshake_bytes(name, async), kStart);
    hub_.take_actions();
    return id;
  }

  bool logged(const std::string& fragment) const {
    return std::any_of(logs_.begin(), logs_.end(), [&](const std::string& line) {
      return line.find(fragment) != std::string::npos;
    });
  }

  std::vector<std::string> logs_;
  Hub hub_{config(), kStart, [this](const std::string& line) { logs_.push_back(line); }};
};

TEST_F(HubTest, BannerIdentificationAndFirstPacketInOneSegmentAreAllProcessed_5_1a) {
  const ConnectionId id = hub_.open("peer", kStart);
  const std::string bytes =
      handshake_bytes("pA", true) +
      moos::encode_packet({registration("X", 0, "pA"), notify_double("X", 5, "pA")});
  hub_.receive(id, bytes, kStart);
  const Seen s = seen(id);
  ASSERT_EQ(s.packets.size(), 2u);
  EXPECT_EQ(s.packets[0][0].type, mt::kWelcome);
  ASSERT_EQ(s.packets[1].size(), 1u);
  EXPECT_EQ(s.packets[1][0].key, "X");
  EXPECT_EQ(s.packets[1][0].dval, 5.0);
}

TEST_F(HubTest, ByteByByteDeliveryGivesTheSameResult_5_1a) {
  const ConnectionId id = hub_.open("peer", kStart);
  const std::string bytes = handshake_bytes("pA", false) + moos::encode_packet({null_message("pA")});
  for (char c : bytes) hub_.receive(id, std::string_view(&c, 1), kStart);
  const Seen s = seen(id);
  ASSERT_EQ(s.packets.size(), 2u);
  EXPECT_EQ(s.packets[0][0].type, mt::kWelcome);
  EXPECT_EQ(s.packets[1][0].type, mt::kNull);
}

TEST_F(HubTest, BannerIsComparedCaseInsensitively_1_4) {
  const ConnectionId id = hub_.open("peer", kStart);
  std::string banner = "elks can't dance 2/8/10";
  banner.resize(moos::kBannerSize, '\0');
  hub_.receive(id, banner + moos::encode_packet({identification("pA", true)}), kStart);
  const Seen s = seen(id);
  ASSERT_EQ(s.packets.size(), 1u);
  EXPECT_EQ(s.packets[0][0].type, mt::kWelcome);
}

TEST_F(HubTest, WrongBannerClosesWithoutAnyReplyAndIsLogged_1_4) {
  const ConnectionId id = hub_.open("10.0.0.9:1234", kStart);
  std::string old_banner = "ELKS CAN'T DANCE 30/7/10";
  old_banner.resize(moos::kBannerSize, '\0');
  hub_.receive(id, old_banner + moos::encode_packet({identification("pA", true)}), kStart);
  const Seen s = seen(id);
  EXPECT_TRUE(s.packets.empty());
  EXPECT_TRUE(s.closed);
  EXPECT_TRUE(logged("(10.0.0.9:1234): wrong protocol banner \"ELKS CAN'T DANCE 30/7/10"));
  EXPECT_EQ(hub_.connection_count(), 0u);
}

TEST_F(HubTest, DuplicateNameGetsPoisonThenCloseAfterSend_1_6) {
  connected("pA", true);
  const ConnectionId id = hub_.open("peer", kStart);
  hub_.receive(id, handshake_bytes("pA", true), kStart);
  const Seen s = seen(id);
  ASSERT_EQ(s.packets.size(), 1u);
  EXPECT_EQ(s.packets[0][0].type, mt::kPoison);
  EXPECT_EQ(s.packets[0][0].sval, "A client of this name (\"pA\") already exists");
  EXPECT_TRUE(s.closed_after_send);
  EXPECT_TRUE(logged("handshake refused: A client of this name (\"pA\") already exists"));
}

TEST_F(HubTest, IdentificationPacketWithoutMessagesGetsPoison_1_5) {
  const ConnectionId id = hub_.open("peer", kStart);
  hub_.receive(id, moos::protocol_banner() + moos::encode_packet({}), kStart);
  const Seen s = seen(id);
  ASSERT_EQ(s.packets.size(), 1u);
  EXPECT_EQ(s.packets[0][0].sval, "Failed to read receive client's name");
  EXPECT_TRUE(s.closed_after_send);
}

TEST_F(HubTest, UndecodableIdentificationGetsPoisonAndTheReasonIsLogged_1_5) {
  const ConnectionId id = hub_.open("peer", kStart);
  std::string packet = moos::encode_packet({identification("pA", true)});
  packet[9 + 10] = '\x7f';  // the source string's length byte now runs past the message
  hub_.receive(id, moos::protocol_banner() + packet, kStart);
  const Seen s = seen(id);
  ASSERT_EQ(s.packets.size(), 1u);
  EXPECT_EQ(s.packets[0][0].type, mt::kPoison);
  EXPECT_TRUE(logged("bad packet (message 0: string source runs past the end of the message"));
}

TEST_F(HubTest, PacketFollowedByEndOfStreamIsStillProcessed_5_6) {
  const ConnectionId watcher = connected("watcher", true);
  hub_.receive(watcher, moos::encode_packet({registration("POKE", 0, "watcher")}), kStart);
  hub_.take_actions();
  const ConnectionId poker = hub_.open("peer", kStart);
  hub_.receive(poker,
               handshake_bytes("uPokeDB", true) +
                   moos::encode_packet({notify_string("POKE", "now", "uPokeDB")}),
               kStart);
  hub_.end_of_stream(poker, kStart);
  const Seen s = seen(watcher);
  ASSERT_EQ(s.packets.size(), 1u);
  EXPECT_EQ(s.packets[0][0].sval, "now");
}

TEST_F(HubTest, EndOfStreamFreesTheNameAtOnce_1_9) {
  const ConnectionId first = connected("pA", true);
  hub_.end_of_stream(first, kStart);
  const ConnectionId second = hub_.open("peer", kStart);
  hub_.receive(second, handshake_bytes("pA", true), kStart);
  EXPECT_EQ(seen(second).packets.at(0).at(0).type, mt::kWelcome);
}

TEST_F(HubTest, TruncatedPacketAtEndOfStreamIsDiscardedWithAReason) {
  const ConnectionId id = connected("pA", true);
  const std::string packet = moos::encode_packet({notify_double("X", 1, "pA")});
  hub_.receive(id, std::string_view(packet).substr(0, 20), kStart);
  hub_.end_of_stream(id, kStart);
  EXPECT_TRUE(seen(id).closed_after_send);
  EXPECT_TRUE(logged("client \"pA\" (127.0.0.1:pA): closed by the peer; 20 bytes of an incomplete packet discarded"));
}

TEST_F(HubTest, HeaderAnnouncingTwoGigabytesDropsTheClientBeforeAllocating_3_4) {
  const ConnectionId id = connected("pA", true);
  const std::string header("\x00\x00\x00\x80\x01\x00\x00\x00\x00", 9);
  hub_.receive(id, header, kStart);
  EXPECT_TRUE(seen(id).closed);
  EXPECT_TRUE(logged("client \"pA\" (127.0.0.1:pA): bad packet (packet header announces 2147483648 bytes"));
}

// The server's packet limit is sized from libMOOS (2,048 queued messages sent as one packet):
// core-moos's app_test sends ~205 MB packets of 100 kB messages, which must be taken.
TEST(HubLimits, DefaultPacketLimitTakesALibmoosBacklogOf100kBMessages) {
  constexpr std::size_t kLibmoosOutboxMessages = 2048;
  constexpr std::size_t kAppTestMessageBytes = 100 * 1000 + 64;
  EXPECT_GE(HubConfig{}.max_packet_bytes, kLibmoosOutboxMessages * kAppTestMessageBytes);
  Hub hub(HubConfig{}, kStart, [](const std::string&) {});
  const ConnectionId id = hub.open("peer", kStart);
  hub.receive(id, moos::protocol_banner() + moos::encode_packet({identification("pA", true)}),
              kStart);
  hub.take_actions();
  const std::uint32_t announced = kLibmoosOutboxMessages * kAppTestMessageBytes;
  std::string header(9, '\0');
  for (std::size_t i = 0; i < 4; ++i) header[i] = static_cast<char>(announced >> (8 * i));
  hub.receive(id, header, kStart);
  for (const auto& action : hub.take_actions()) EXPECT_NE(action.kind, Action::Kind::kClose);
  EXPECT_EQ(hub.held_bytes(id), header.size());
}

TEST_F(HubTest, MalformedMessageInsideAWellFramedPacketDropsTheClient_2_7) {
  const ConnectionId id = connected("pA", true);
  std::string packet = moos::encode_packet({notify_double("X", 1, "pA")});
  packet[9] = '\x30';  // the message length field no longer matches its content
  hub_.receive(id, packet, kStart);
  EXPECT_TRUE(seen(id).closed);
  EXPECT_TRUE(logged("client \"pA\" (127.0.0.1:pA): bad packet (message 0:"));
}

TEST_F(HubTest, SilentNewConnectionIsDroppedAfterTheBannerTimeout) {
  const ConnectionId id = hub_.open("peer", kStart);
  hub_.tick(kStart + 0.9);
  EXPECT_FALSE(seen(id).closed);
  hub_.tick(kStart + 1.1);
  EXPECT_TRUE(seen(id).closed);
  EXPECT_TRUE(logged("no protocol banner within 1 s"));
}

TEST_F(HubTest, MissingIdentificationIsDroppedAfterTheHandshakeTimeout_1_5) {
  const ConnectionId id = hub_.open("peer", kStart);
  hub_.receive(id, moos::protocol_banner(), kStart + 0.5);
  hub_.tick(kStart + 2.4);
  EXPECT_FALSE(seen(id).closed);
  hub_.tick(kStart + 2.6);
  EXPECT_TRUE(seen(id).closed);
  EXPECT_TRUE(logged("no identification packet within 2 s"));
}

TEST_F(HubTest, InactiveClientIsDroppedAfterClientTimeoutAndActiveOneIsKept_1_9) {
  const ConnectionId quiet = connected("quiet", true);
  const ConnectionId talker = connected("talker", true);
  hub_.receive(talker, moos::encode_packet({timing(kStart)}), kStart + 2.0);
  hub_.tick(kStart + 3.5);
  hub_.take_actions();
  EXPECT_FALSE(hub_.database().is_connected(quiet));
  EXPECT_TRUE(hub_.database().is_connected(talker));
  EXPECT_TRUE(logged(
      "client \"quiet\" (127.0.0.1:quiet): nothing received for more than 3 s (ClientTimeout)"));
}

// Liveness is what the client sent, not complete packets: the first bytes of a large packet
// that is still arriving keep its sender alive.
TEST_F(HubTest, AnyByteReceivedKeepsAClientAlive) {
  const ConnectionId id = connected("pBig", true);
  const std::string packet = moos::encode_packet({notify_string("BIG", "0123456789", "pBig")});
  hub_.receive(id, std::string_view(packet).substr(0, 8), kStart + 2.5);
  hub_.tick(kStart + 5.0);
  EXPECT_TRUE(hub_.database().is_connected(id));
  EXPECT_EQ(hub_.held_bytes(id), 8u);
  hub_.tick(kStart + 5.6);
  EXPECT_FALSE(hub_.database().is_connected(id));
}

// While the transport does not read a connection (back-pressure) it is not judged silent;
// after the resumption its silence counts from then.
TEST_F(HubTest, PausedConnectionIsNotJudgedSilentUntilResumed) {
  const ConnectionId id = connected("pSlow", true);
  hub_.set_reading_paused(id, true, kStart + 1);
  hub_.tick(kStart + 60);
  EXPECT_TRUE(hub_.database().is_connected(id));
  hub_.set_reading_paused(id, false, kStart + 60);
  hub_.tick(kStart + 62.9);
  EXPECT_TRUE(hub_.database().is_connected(id));
  hub_.tick(kStart + 63.1);
  EXPECT_FALSE(hub_.database().is_connected(id));
}

// A newline in a client name cannot end a log line.
TEST_F(HubTest, ClientNameIsEscapedInTheLog) {
  const ConnectionId id = connected("p\nEvil\nforged", true);
  EXPECT_EQ(hub_.describe(id), "client \"p\\x0AEvil\\x0Aforged\" (127.0.0.1:p\nEvil\nforged)");
  EXPECT_TRUE(logged("client \"p\\x0AEvil\\x0Aforged\""));
}

TEST(HubNoTimeout, ClientTimeoutUnsetMeansNever_1_9) {
  HubConfig config;
  config.client_timeout_s.reset();
  Hub hub(config, kStart, [](const std::string&) {});
  const ConnectionId id = hub.open("peer", kStart);
  hub.receive(id, moos::protocol_banner() + moos::encode_packet({identification("pA", true)}), kStart);
  hub.tick(kStart + 3600);
  EXPECT_TRUE(hub.database().is_connected(id));
}

TEST_F(HubTest, DbVariablesAreRefreshedByTheTimer_5_6) {
  const ConnectionId id = connected("pA", true);
  hub_.receive(id, moos::encode_packet({registration("DB_UPTIME", 0, "pA")}), kStart);
  hub_.take_actions();
  hub_.tick(kStart + 0.5);
  EXPECT_TRUE(seen(id).packets.empty());
  hub_.tick(kStart + kDbVariableRefreshInterval_s + 0.01);
  const Seen s = seen(id);
  ASSERT_EQ(s.packets.size(), 1u);
  EXPECT_EQ(s.packets[0][0].key, "DB_UPTIME");
  EXPECT_NEAR(s.packets[0][0].dval, kDbVariableRefreshInterval_s + 0.01, 1e-6);
}

TEST(HubWarp, MoosTimeIsRealTimeTimesWarp_0_3) {
  HubConfig config;
  config.time_warp = 10.0;
  Hub hub(config, kStart, [](const std::string&) {});
  const ConnectionId id = hub.open("peer", kStart);
  hub.receive(id, moos::protocol_banner() + moos::encode_packet({identification("pA", false)}),
              kStart + 1);
  hub.take_actions();
  hub.receive(id, moos::encode_packet({null_message("pA")}), kStart + 2);
  const auto actions = hub.take_actions();
  ASSERT_EQ(actions.size(), 1u);
  const auto reply = moos::decode_packet(actions[0].bytes);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->at(0).dval, (kStart + 2) * 10.0);
}

}  // namespace
}  // namespace moosdb_lite

namespace moosdb_lite {
namespace {

// The transport's per-source turns (event_loop.hpp) need each Send to name its source, and a
// large packet of one source cut into short turns: 40 messages of 4 KiB to an asynchronous
// subscriber leave as packets of at most kFairPacketBytes, in order, each naming the poster.
TEST(HubFairness, MailToAnAsyncClientIsCutIntoFairPacketsThatNameTheirSource) {
  HubConfig c;
  c.max_packet_bytes = 1024 * 1024;
  Hub hub(c, kT0, [](const std::string&) {});
  const auto join = [&](const std::string& name) {
    const ConnectionId id = hub.open("127.0.0.1:" + name, kT0);
    hub.receive(id, moos::protocol_banner() + moos::encode_packet({identification(name, true)}),
                kT0);
    return id;
  };
  const ConnectionId subscriber = join("pSub");
  const ConnectionId poster = join("pPoster");
  hub.receive(subscriber, moos::encode_packet({registration("BIG", 0, "pSub")}), kT0);
  hub.take_actions();

  constexpr int kPosts = 40;
  std::vector<Message> posts;
  for (int i = 0; i < kPosts; ++i)
    posts.push_back(notify_string("BIG", std::to_string(i) + std::string(4096, 'x'), "pPoster"));
  hub.receive(poster, moos::encode_packet(posts), kT0);
  int next = 0;
  int packets = 0;
  for (const Action& a : hub.take_actions()) {
    if (a.id != subscriber) continue;
    ++packets;
    EXPECT_EQ(a.source, poster);
    EXPECT_LE(a.bytes.size(), kFairPacketBytes + moos::kPacketHeaderSize);
    const auto packet = moos::decode_packet(a.bytes);
    ASSERT_TRUE(packet.has_value());
    for (const Message& m : *packet) EXPECT_EQ(std::stoi(m.sval), next++);
  }
  EXPECT_EQ(next, kPosts);
  EXPECT_GT(packets, 1);
}

}  // namespace
}  // namespace moosdb_lite
