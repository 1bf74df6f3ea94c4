// Bad input against the real server: each offender is dropped or its message refused with a
// logged reason naming it, every other client keeps being served, and no accepted message is
// lost (two bystanders, one asynchronous and one synchronous, connected throughout, must see
// every message posted around the incident, in order).

#include <gtest/gtest.h>

#include <atomic>
#include <functional>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "moosdb_server.hpp"
#include "raw_client.hpp"
#include "wire_messages.hpp"

namespace moosdb_lite::test {

using namespace moos::test;
namespace {

using moos::Message;
using test_support::MoosdbServer;
using test_support::steady_now_s;
namespace mt = moos::msg_type;

/// Bystanders stay silent for long stretches: the inactivity limit must not be what drops them.
const std::string kPatientClients = "--moos_timeout=60";

/// Bystanders: an async watcher and a sync poller subscribed to BYSTANDER, and a poster.
class Bystanders {
 public:
  void join(int port) {
    ASSERT_TRUE(watcher_.join(port, "pWatcher", true));
    ASSERT_TRUE(poller_.join(port, "pPoller", false));
    ASSERT_TRUE(poster_.join(port, "pPoster", false));
    ASSERT_TRUE(watcher_.send({registration("BYSTANDER", 0, "pWatcher")}));
    ASSERT_TRUE(poller_.exchange({registration("BYSTANDER", 0, "pPoller")}));
  }

  /// Posts the next number; waits for the poster's reply so it is accepted.
  void post() {
    const auto reply = poster_.exchange({notify_double("BYSTANDER", posted_, "pPoster")});
    ASSERT_TRUE(reply) << "the poster lost its connection";
    ++posted_;
  }

  /// The number the next post must carry, for a post made by another client; call
  /// posted_elsewhere() once that post has been accepted.
  int next_value() const { return posted_; }
  void posted_elsewhere() { ++posted_; }

  /// Every posted number, in order, at both bystanders.
  void expect_everything_received() {
    const auto async_mail = watcher_.read_notifies(static_cast<std::size_t>(posted_ - async_seen_));
    for (const auto& m : async_mail) EXPECT_EQ(m.dval, async_seen_++) << "async watcher";
    EXPECT_EQ(async_seen_, posted_) << "async watcher missed messages";
    const auto reply = poller_.exchange({null_message("pPoller")});
    ASSERT_TRUE(reply) << "the sync poller lost its connection";
    for (std::size_t i = 1; i < reply->size(); ++i) EXPECT_EQ(reply->at(i).dval, sync_seen_++) << "sync poller";
    EXPECT_EQ(sync_seen_, posted_) << "sync poller missed messages";
  }

 private:
  RawClient watcher_;
  RawClient poller_;
  RawClient poster_;
  int posted_ = 0;
  int async_seen_ = 0;
  int sync_seen_ = 0;
};

TEST(MoosdbLiteBadInput, WrongBannerIsClosedWithoutReply_1_4) {
  MoosdbServer server(MOOSDB_LITE_PATH, {kPatientClients});
  ASSERT_TRUE(server.ok());
  Bystanders others;
  others.join(server.port());
  others.post();
  RawClient http;
  ASSERT_TRUE(http.connect(server.port()));
  std::string banner = "GET / HTTP/1.1\r\nHost: x\r\n\r\n";
  banner.resize(moos::kBannerSize, '\0');
  ASSERT_TRUE(http.send_bytes(banner));
  std::size_t received = 0;
  EXPECT_TRUE(http.wait_closed(kArrivalTimeout_s, &received));
  EXPECT_EQ(received, 0u) << "nothing may be sent after a wrong banner";
  EXPECT_TRUE(server.wait_for_log("wrong protocol banner \"GET / HTTP/1.1\\x0d\\x0a", kArrivalTimeout_s));
  others.post();
  others.expect_everything_received();
}

TEST(MoosdbLiteBadInput, PacketClaimingTwoGigabytesDropsTheSender_3_4) {
  MoosdbServer server(MOOSDB_LITE_PATH, {kPatientClients});
  ASSERT_TRUE(server.ok());
  Bystanders others;
  others.join(server.port());
  others.post();
  RawClient liar;
  ASSERT_TRUE(liar.join(server.port(), "pLiar", true));
  ASSERT_TRUE(liar.send_bytes(std::string("\x00\x00\x00\x80\x01\x00\x00\x00\x00", 9)));
  EXPECT_TRUE(liar.wait_closed(kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log(
      "client \"pLiar\" (127.0.0.1:", kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("bad packet (packet header announces 2147483648 bytes (allowed 9 to 268435456)",
                                  kArrivalTimeout_s));
  others.post();
  others.expect_everything_received();
}

TEST(MoosdbLiteBadInput, PacketAboveAConfiguredLimitDropsTheSender_3_4) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--max-packet-bytes=1000", kPatientClients});
  ASSERT_TRUE(server.ok());
  Bystanders others;
  others.join(server.port());
  RawClient big;
  ASSERT_TRUE(big.join(server.port(), "pBig", true));
  ASSERT_TRUE(big.send({notify_string("BIG", std::string(2000, 'x'), "pBig")}));
  EXPECT_TRUE(big.wait_closed(kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("allowed 9 to 1000", kArrivalTimeout_s));
  others.post();
  others.expect_everything_received();
}

TEST(MoosdbLiteBadInput, TruncatedPacketThenDisconnectIsDiscardedWithReason) {
  MoosdbServer server(MOOSDB_LITE_PATH, {kPatientClients});
  ASSERT_TRUE(server.ok());
  Bystanders others;
  others.join(server.port());
  others.post();
  {
    RawClient cut;
    ASSERT_TRUE(cut.join(server.port(), "pCut", true));
    const std::string packet = moos::encode_packet({notify_double("BYSTANDER", 999, "pCut")});
    ASSERT_TRUE(cut.send_bytes(std::string_view(packet).substr(0, packet.size() - 5)));
  }
  EXPECT_TRUE(server.wait_for_log("client \"pCut\"", kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("bytes of an incomplete packet discarded", kArrivalTimeout_s));
  others.post();
  others.expect_everything_received();  // 999 never appears
}

/// `name` joins and sends a NOTIFY of 999 to BYSTANDER made malformed by `corrupt`: it must be
/// dropped with `reason` in the log, and the bystanders must get everything else.
void expect_a_corrupt_packet_drops_its_sender(const std::string& name,
                                              const std::function<void(std::string&)>& corrupt,
                                              const std::string& reason) {
  MoosdbServer server(MOOSDB_LITE_PATH, {kPatientClients});
  ASSERT_TRUE(server.ok());
  Bystanders others;
  others.join(server.port());
  others.post();
  RawClient bad;
  ASSERT_TRUE(bad.join(server.port(), name, true));
  std::string packet = moos::encode_packet({notify_double("BYSTANDER", 999, name)});
  corrupt(packet);
  ASSERT_TRUE(bad.send_bytes(packet));
  EXPECT_TRUE(bad.wait_closed(kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("client \"" + name + "\"", kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log(reason, kArrivalTimeout_s));
  others.post();
  others.expect_everything_received();  // 999 never appears
}

TEST(MoosdbLiteBadInput, StructurallyMalformedMessageDropsTheSender_2_7) {
  expect_a_corrupt_packet_drops_its_sender(
      "pMalformed",
      // the source's length now runs past the end of the message
      [](std::string& packet) { packet[9 + 10] = '\x40'; },
      "bad packet (message 0: string source runs past the end of the message");
}

TEST(MoosdbLiteBadInput, SemanticallyMalformedMessageIsRefusedAndTheClientStays) {
  MoosdbServer server(MOOSDB_LITE_PATH, {kPatientClients});
  ASSERT_TRUE(server.ok());
  Bystanders others;
  others.join(server.port());
  RawClient sloppy;
  ASSERT_TRUE(sloppy.join(server.port(), "pSloppy", false));
  Message bad_type = notify_double("BYSTANDER", 999, "pSloppy");
  bad_type.data_type = '?';
  const auto reply = sloppy.exchange({notify_double("", 1, "pSloppy"), bad_type,
                                      wildcard("AppPattern=*,VarPattern", "pSloppy"),
                                      notify_double("BYSTANDER", others.next_value(), "pSloppy")});
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->front().type, mt::kNull);
  others.posted_elsewhere();  // the well-formed message of the same packet was accepted
  EXPECT_TRUE(server.wait_for_log("client \"pSloppy\": NOTIFY with an empty variable name refused",
                                  kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("client \"pSloppy\": NOTIFY BYSTANDER with data type '?' refused",
                                  kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("client \"pSloppy\": WILDCARD_REGISTER \"AppPattern=*,VarPattern\" refused: item "
                                  "'VarPattern' has no '='",
                                  kArrivalTimeout_s));
  others.post();
  others.expect_everything_received();
  ASSERT_TRUE(sloppy.exchange({null_message("pSloppy")})) << "the sloppy client must still be served";
}

TEST(MoosdbLiteBadInput, SilentConnectionIsDroppedAfterTheBannerTimeout) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--banner-timeout=0.5", kPatientClients});
  ASSERT_TRUE(server.ok());
  Bystanders others;
  others.join(server.port());
  RawClient mute;
  ASSERT_TRUE(mute.connect(server.port()));
  const double start = steady_now_s();
  EXPECT_TRUE(mute.wait_closed(kArrivalTimeout_s));
  EXPECT_GE(steady_now_s() - start, 0.4);
  EXPECT_TRUE(server.wait_for_log("no protocol banner within 0.5 s; connection dropped", kArrivalTimeout_s));
  others.post();
  others.expect_everything_received();
}

TEST(MoosdbLiteBadInput, BannerWithoutIdentificationIsDroppedAfterTheHandshakeTimeout_1_5) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--handshake-timeout=0.5", kPatientClients});
  ASSERT_TRUE(server.ok());
  Bystanders others;
  others.join(server.port());
  RawClient shy;
  ASSERT_TRUE(shy.connect(server.port()));
  ASSERT_TRUE(shy.send_bytes(moos::protocol_banner()));
  EXPECT_TRUE(shy.wait_closed(kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("no identification packet within 0.5 s; connection dropped",
                                  kArrivalTimeout_s));
  others.post();
  others.expect_everything_received();
}

TEST(MoosdbLiteBadInput, SyncClientThatNeverCollectsItsMailIsDroppedAtTheLimit) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--max-output-bytes=100000", kPatientClients});
  ASSERT_TRUE(server.ok());
  Bystanders others;
  others.join(server.port());
  RawClient hoarder;
  ASSERT_TRUE(hoarder.join(server.port(), "pHoarder", false));
  ASSERT_TRUE(hoarder.exchange({registration("HOARD", 0, "pHoarder")}));
  RawClient pub;
  ASSERT_TRUE(pub.join(server.port(), "pHoardPub", false));
  for (int i = 0; i < 100; ++i)
    ASSERT_TRUE(pub.exchange({notify_string("HOARD", std::string(2000, 'h'), "pHoardPub")}));
  EXPECT_TRUE(hoarder.wait_closed(kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("client \"pHoarder\"", kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("undelivered mail would exceed 100000 bytes", kArrivalTimeout_s));
  others.post();
  others.expect_everything_received();
}

TEST(MoosdbLiteBadInput, AsyncClientThatDoesNotReadIsDroppedAtTheOutputLimit) {
  constexpr int kMessages = 3000;
  constexpr std::size_t kPayloadBytes = 4000;
  MoosdbServer server(MOOSDB_LITE_PATH, {"--max-output-bytes=300000", kPatientClients});
  ASSERT_TRUE(server.ok());
  RawClient reader;  // reads everything, in lock step with the publisher
  ASSERT_TRUE(reader.join(server.port(), "pReader", true));
  ASSERT_TRUE(reader.send({registration("BULK", 0, "pReader")}));
  RawClient stuck;  // never reads, with a tiny receive buffer
  ASSERT_TRUE(stuck.connect(server.port(), 4096));
  ASSERT_TRUE(stuck.send_bytes(moos::protocol_banner() +
                               moos::encode_packet({identification("pStuck", true, moos_now())}) +
                               moos::encode_packet({registration("BULK", 0, "pStuck")})));
  RawClient pub;
  ASSERT_TRUE(pub.join(server.port(), "pBulk", false));
  int received = 0;
  for (int i = 0; i < kMessages; ++i) {
    ASSERT_TRUE(pub.exchange({notify_string("BULK", std::string(kPayloadBytes, 'b'), "pBulk")}));
    const auto mail = reader.read_notifies(1);
    ASSERT_EQ(mail.size(), 1u) << "message " << i;
    ++received;
  }
  EXPECT_EQ(received, kMessages);
  EXPECT_TRUE(server.wait_for_log("client \"pStuck\"", kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("connection dropped", kArrivalTimeout_s));
  // Slowed down and warned about first (half the output limit), dropped only at the limit.
  const std::string log = server.stderr_text();
  EXPECT_LT(log.find("client \"pStuck\" (127.0.0.1"), log.find("connection dropped")) << log;
  EXPECT_LT(log.find("its messages are delayed"), log.find("exceed the limit of 300000")) << log;
}

TEST(MoosdbLiteBadInput, FloodOfOneHundredThousandMessagesLosesNothing) {
  constexpr int kFlood = 100000;
  constexpr int kMessagesPerWrite = 1000;
  MoosdbServer server(MOOSDB_LITE_PATH, {kPatientClients});
  ASSERT_TRUE(server.ok());
  Bystanders others;
  others.join(server.port());
  others.post();
  RawClient watcher;
  ASSERT_TRUE(watcher.join(server.port(), "pFloodWatch", true));
  ASSERT_TRUE(watcher.send({registration("FLOOD", 0, "pFloodWatch")}));
  RawClient sync_watcher;
  ASSERT_TRUE(sync_watcher.join(server.port(), "pFloodPoll", false));
  ASSERT_TRUE(sync_watcher.exchange({registration("FLOOD", 0, "pFloodPoll")}));
  RawClient flooder;
  ASSERT_TRUE(flooder.join(server.port(), "pFlooder", true));
  ASSERT_TRUE(watcher.send({timing(moos_now())}));
  ASSERT_TRUE(watcher.read_packet());  // registrations processed

  // The flooder writes one message per packet, many packets per write, from its own thread.
  const double start_s = steady_now_s();
  std::atomic<bool> flood_ok{true};
  std::thread flood([&] {
    std::string batch;
    for (int i = 0; i < kFlood; ++i) {
      batch += moos::encode_packet({notify_double("FLOOD", i, "pFlooder")});
      if ((i + 1) % kMessagesPerWrite == 0) {
        if (!flooder.send_bytes(batch)) flood_ok = false;
        batch.clear();
      }
    }
  });
  int async_next = 0;
  bool in_order = true;
  const double deadline_s = start_s + 60.0;
  while (async_next < kFlood && steady_now_s() < deadline_s) {
    const auto packet = watcher.read_packet(1.0);
    if (!packet) continue;
    for (const auto& m : *packet) {
      if (m.type != mt::kNotify || m.key != "FLOOD") continue;
      in_order = in_order && m.dval == async_next;
      ++async_next;
    }
  }
  const double seconds = steady_now_s() - start_s;
  flood.join();
  EXPECT_TRUE(flood_ok);
  EXPECT_EQ(async_next, kFlood);
  EXPECT_TRUE(in_order);
  const double rate = kFlood / seconds;
  std::cout << "[ flood    ] " << kFlood << " messages delivered in " << seconds << " s = "
            << static_cast<long>(rate) << " messages/s\n";
  ::testing::Test::RecordProperty("flood_messages_per_second", static_cast<int>(rate));

  int sync_next = 0;
  for (int round = 0; round < 100 && sync_next < kFlood; ++round) {
    const auto reply = sync_watcher.exchange({null_message("pFloodPoll")});
    ASSERT_TRUE(reply);
    for (std::size_t i = 1; i < reply->size(); ++i) {
      EXPECT_EQ(reply->at(i).dval, sync_next);
      ++sync_next;
    }
  }
  EXPECT_EQ(sync_next, kFlood);
  others.post();
  others.expect_everything_received();
}

// A name is repeated in DB_CLIENTS, DB_EVENT and every log line about its client.
TEST(MoosdbLiteBadInput, ATenKilobyteClientNameIsPoisonedNamingTheBound_Hardening) {
  MoosdbServer server(MOOSDB_LITE_PATH, {kPatientClients});
  ASSERT_TRUE(server.ok());
  Bystanders others;
  others.join(server.port());
  RawClient verbose;
  ASSERT_TRUE(verbose.connect(server.port()));
  const auto reply = verbose.handshake(std::string(10 * 1024, 'n'), true, moos_now());
  ASSERT_TRUE(reply);
  ASSERT_FALSE(reply->empty());
  EXPECT_EQ(reply->front().type, mt::kPoison);
  EXPECT_EQ(reply->front().sval, "A client name of 10240 bytes is longer than the 1024 allowed");
  EXPECT_TRUE(verbose.wait_closed(kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log(
      "handshake refused: A client name of 10240 bytes is longer than the 1024 allowed",
      kArrivalTimeout_s));
  others.post();
  others.expect_everything_received();
  const std::string log = server.stderr_text();
  EXPECT_EQ(log.find(std::string(2000, 'n')), std::string::npos) << "the name reached the log";
}

TEST(MoosdbLiteBadInput, ANegativeMessageCountDropsTheSender) {
  expect_a_corrupt_packet_drops_its_sender(
      "pNegative",
      [](std::string& packet) { packet.replace(4, 4, "\xff\xff\xff\xff"); },  // count -1
      "bad packet (negative message count -1 at byte 4)");
}

TEST(MoosdbLiteBadInput, GarbageInsteadOfAnIdentificationIsPoisoned) {
  MoosdbServer server(MOOSDB_LITE_PATH, {kPatientClients});
  ASSERT_TRUE(server.ok());
  Bystanders others;
  others.join(server.port());
  RawClient garbled;
  ASSERT_TRUE(garbled.connect(server.port()));
  std::string ident = moos::encode_packet({identification("pGarbled", true, moos_now())});
  ident[9 + 10] = '\x40';  // the first string's length runs past the message
  ASSERT_TRUE(garbled.send_bytes(moos::protocol_banner() + ident));
  const auto reply = garbled.read_packet();
  ASSERT_TRUE(reply);
  ASSERT_FALSE(reply->empty());
  EXPECT_EQ(reply->front().type, mt::kPoison);
  EXPECT_TRUE(garbled.wait_closed(kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("in the handshake", kArrivalTimeout_s));
  others.post();
  others.expect_everything_received();
}

// A few bytes of a header, then nothing: the partial header is no sign of life for ever.
TEST(MoosdbLiteBadInput, PartOfAHeaderThenSilenceIsDroppedAtTheClientTimeout) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--moos_timeout=1"});
  ASSERT_TRUE(server.ok());
  RawClient stall;
  ASSERT_TRUE(stall.join(server.port(), "pStall", true));
  ASSERT_TRUE(stall.send_bytes(std::string("\x40\x00\x00\x00", 4)));
  const double start = steady_now_s();
  EXPECT_TRUE(stall.wait_closed(kArrivalTimeout_s));
  EXPECT_GE(steady_now_s() - start, 0.9);
  EXPECT_TRUE(server.wait_for_log("client \"pStall\"", kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("nothing received for more than 1 s", kArrivalTimeout_s));
  RawClient later;  // the server still serves
  ASSERT_TRUE(later.join(server.port(), "pLater", false));
  EXPECT_TRUE(later.exchange({null_message("pLater")}));
}

// Ever new variable names: the store is bounded (--max-stored-bytes); beyond it a write is
// refused with a logged reason, the writer stays, and the others are served.
TEST(MoosdbLiteBadInput, NewVariablesBeyondTheStoreBoundAreRefusedAndTheWriterStays_Hardening) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--max-stored-bytes=200000", kPatientClients});
  ASSERT_TRUE(server.ok());
  Bystanders others;
  others.join(server.port());
  others.post();
  RawClient hoarder;
  ASSERT_TRUE(hoarder.join(server.port(), "pHoardVars", false));
  for (int i = 0; i < 100; ++i)  // 100 variables of 10 kB: 1 MB asked, 200 kB allowed
    ASSERT_TRUE(hoarder.exchange(
        {notify_string("HOARD_" + std::to_string(i), std::string(10000, 'h'), "pHoardVars")}));
  EXPECT_TRUE(server.wait_for_log("client \"pHoardVars\"", kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("refused: the store would hold more than its 200000 bytes",
                                  kArrivalTimeout_s));
  RawClient reader;
  ASSERT_TRUE(reader.join(server.port(), "pReadVars", false));
  const auto first = reader.exchange({registration("HOARD_0", 0, "pReadVars")});
  ASSERT_TRUE(first);
  EXPECT_EQ(first->size(), 2u) << "the NULL and HOARD_0's snapshot: it was stored";
  const auto last = reader.exchange({registration("HOARD_99", 0, "pReadVars")});
  ASSERT_TRUE(last);
  EXPECT_EQ(last->size(), 1u) << "the NULL only: HOARD_99 was refused";
  ASSERT_TRUE(hoarder.exchange({null_message("pHoardVars")})) << "the writer stays";
  others.post();
  others.expect_everything_received();
}

}  // namespace
}  // namespace moosdb_lite::test
