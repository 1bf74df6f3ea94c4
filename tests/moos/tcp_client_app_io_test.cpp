// TcpClient's I/O on the app's own thread (tcp_client.hpp): after a promise, fetch()
// reads what the socket holds and the comms thread leaves it the reading; release_sends() writes
// the batch itself; a failure the app's thread meets is handed to the comms thread.
#include <atomic>

#include "tcp_client_fixture.hpp"

namespace moos {
namespace test {
namespace {

Message mail(const std::string& key, double value) {
  Message m;
  m.type = msg_type::kNotify;
  m.data_type = data_type::kDouble;
  m.key = key;
  m.dval = value;
  m.time = kT0;
  return m;
}

/// Polls `done` every 5 ms for up to `timeout_s`.
template <typename Predicate>
bool eventually(Predicate done, double timeout_s = kWait_s) {
  const double deadline = steady_now_s() + timeout_s;
  while (!done()) {
    if (steady_now_s() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

class TcpClientAppIo : public TcpClientTest {
 protected:
  /// No skew correction: the comms thread then never reads for a TIMING echo's sake, so what
  /// it reads depends on the promise alone.
  TcpClientOptions uncorrected() {
    TcpClientOptions o = options();
    o.skew_policy = SkewPolicy::kNever;
    return o;
  }
  /// Connects `client` and lets the server read the first TIMING, so the comms thread then
  /// sleeps until the next one (kTimingInterval_real_s) unless something wakes it.
  void connect_and_settle(TcpClient& client) {
    ASSERT_NO_FATAL_FAILURE(connect(client));
    ASSERT_TRUE(server.read_packet().has_value());
  }
  /// connect_and_settle, counting the comms thread's mail announcements in `announced`.
  void connect_counting_mail(TcpClient& client) {
    client.set_on_mail([this] { ++announced; });
    ASSERT_NO_FATAL_FAILURE(connect_and_settle(client));
  }
  std::atomic<int> announced{0};

  /// A settling pause: long enough for the comms thread to act on a wake, far shorter than the
  /// TIMING interval.
  static void settle() { std::this_thread::sleep_for(std::chrono::milliseconds(100)); }
};

TEST_F(TcpClientAppIo, AfterAPromiseTheCommsThreadLeavesTheMailToFetch) {
  TcpClient client(uncorrected());
  ASSERT_NO_FATAL_FAILURE(connect_counting_mail(client));
  client.expect_fetch_within(30.0);
  settle();
  server.send({mail("A", 1.0)});
  settle();
  EXPECT_EQ(announced.load(), 0) << "the comms thread read mail the app had promised to fetch";
  const auto got = client.fetch();  // reads the socket itself
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].key, "A");
  EXPECT_EQ(announced.load(), 0) << "mail fetch() read for itself is not announced";
}

TEST_F(TcpClientAppIo, WithoutAPromiseTheCommsThreadReadsAndAnnouncesMail) {
  TcpClient client(uncorrected());
  ASSERT_NO_FATAL_FAILURE(connect_counting_mail(client));
  client.expect_fetch_within(30.0);
  client.expect_fetch_within(0.0);  // withdrawn, e.g. before an idle sleep that mail must end
  settle();
  server.send({mail("B", 2.0)});
  EXPECT_TRUE(eventually([&] { return announced.load() > 0; }));
  const auto got = client.fetch();
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].key, "B");
}

TEST_F(TcpClientAppIo, ABrokenPromiseEndsAfterTheGrace) {
  TcpClient client(uncorrected());
  ASSERT_NO_FATAL_FAILURE(connect_counting_mail(client));
  const double promised_at = steady_now_s();
  client.expect_fetch_within(0.01);  // and never fetches
  settle();
  server.send({mail("C", 3.0)});
  ASSERT_TRUE(eventually([&] { return announced.load() > 0; }));
  // Not before the promise and its grace ran out (less a poll's millisecond rounding).
  EXPECT_GE(steady_now_s() - promised_at, 0.01 + TcpClient::kAppReadGrace_real_s - 0.002);
}

TEST_F(TcpClientAppIo, AReleasedBatchIsWrittenByTheAppsOwnThread) {
  TcpClient client(uncorrected());
  ASSERT_NO_FATAL_FAILURE(connect_and_settle(client));
  settle();  // the comms thread may still be finishing the loop that sent that TIMING
  // The comms thread sleeps until its next TIMING: only the releasing thread can have written
  // the batch by the time release_sends() returns.
  client.hold_sends();
  ASSERT_TRUE(client.notify("X", 1.0));
  ASSERT_TRUE(client.notify("Y", 2.0));
  client.release_sends();
  EXPECT_TRUE(client.flush(0.0));
  const auto packet = server.read_non_timing();
  ASSERT_TRUE(packet.has_value());
  std::vector<std::string> keys;
  for (const auto& m : *packet)
    if (m.type != msg_type::kTiming) keys.push_back(m.key);
  EXPECT_EQ(keys, (std::vector<std::string>{"X", "Y"}));
}

TEST_F(TcpClientAppIo, WhileTheAppSendsTheTimingRidesInItsPackets) {
  TcpClient client(uncorrected());
  ASSERT_NO_FATAL_FAILURE(connect_and_settle(client));
  const double end = steady_now_s() + 3.0;
  for (int i = 0; steady_now_s() < end; ++i) {  // an app cycling every 0.1 real s
    client.hold_sends();
    ASSERT_TRUE(client.notify("P", static_cast<double>(i)));
    client.release_sends();
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  int riding = 0;
  int alone = 0;
  while (auto packet = server.read_packet(0.2)) {
    if (packet->front().type == msg_type::kTiming) ++(packet->size() > 1 ? riding : alone);
  }
  // About four TIMINGs in 3 s; one may go alone when a cycle is late (a loaded machine).
  EXPECT_GE(riding + alone, 3);
  EXPECT_GE(riding, 2);
  EXPECT_LE(alone, 1);
}

TEST_F(TcpClientAppIo, AFetchThatFindsTheConnectionClosedHandsItToTheCommsThread) {
  TcpClient client(uncorrected());
  ASSERT_NO_FATAL_FAILURE(connect_and_settle(client));
  client.expect_fetch_within(30.0);
  settle();
  server.drop();  // everything the client sent was read: a FIN, not a reset
  settle();
  // The comms thread is not reading and sends its next TIMING only later: the app's fetch()
  // meets the close, and the comms thread drops the connection at once and reconnects.
  const double fetched_at = steady_now_s();
  EXPECT_TRUE(client.fetch().empty());
  ASSERT_TRUE(eventually([&] { return !client.is_connected(); }, 1.0));
  EXPECT_LT(steady_now_s() - fetched_at, TcpClient::kTimingInterval_real_s / 2);
  EXPECT_EQ(client.last_error(), "the server closed the connection");
  ASSERT_NO_FATAL_FAILURE(handshake());
  EXPECT_TRUE(client.wait_until_connected(kWait_s));
  EXPECT_EQ(client.connection_count(), 2u);
}

}  // namespace
}  // namespace test
}  // namespace moos
