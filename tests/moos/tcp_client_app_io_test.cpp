// TcpClient's I/O on the app's own thread (tcp_client.hpp) against the promise of fetch() and of
// posting (comms.hpp): after a promise, fetch() reads what the socket holds and the comms thread
// leaves it the reading, or reads it and announces it when fetch() could not; release_sends()
// writes the batch itself; a failure the app's thread meets is handed to the comms thread.
// No test sleeps for mail: each waits for a condition with a deadline, or for the comms thread's
// next TIMING, which it sends only after a whole loop (kNever: it never reads for an echo).
#include <atomic>
#include <condition_variable>
#include <utility>

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

std::vector<std::string> keys_of(const std::vector<Message>& messages) {
  std::vector<std::string> keys;
  for (const auto& m : messages)
    if (m.type != msg_type::kTiming) keys.push_back(m.key);
  return keys;
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

/// A clock whose next reading, once armed, waits until the test opens the gate (at most kWait_s):
/// it holds the comms thread inside its next TIMING, with the socket's I/O lock taken.
class GateClock final : public Clock {
 public:
  double unix_now_s() const override {
    std::unique_lock<std::mutex> lock(mutex_);
    if (armed_) {
      armed_ = false;
      entered_ = true;
      changed_.notify_all();
      changed_.wait_for(lock, std::chrono::duration<double>(kWait_s), [this] { return open_; });
    }
    return kT0;
  }
  void sleep_real_s(double) override {}
  void arm() {
    std::lock_guard<std::mutex> lock(mutex_);
    armed_ = true;
  }
  bool wait_entered() {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, std::chrono::duration<double>(kWait_s), [this] { return entered_; });
  }
  void open() {
    std::lock_guard<std::mutex> lock(mutex_);
    open_ = true;
    changed_.notify_all();
  }

 private:
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  mutable bool armed_ = false;
  mutable bool entered_ = false;
  bool open_ = false;
};

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
  /// fetch() as promised: mail that arrived before it is returned now, or announced (without
  /// another fetch) and returned by the next fetch.
  std::vector<Message> fetch_as_promised(TcpClient& client) {
    const int before = announced.load();
    auto got = client.fetch();
    if (!got.empty()) return got;
    EXPECT_TRUE(eventually([&] { return announced.load() > before; }))
        << "mail was neither fetched nor announced";
    return client.fetch();
  }
  std::atomic<int> announced{0};
};

TEST_F(TcpClientAppIo, AfterAPromiseTheCommsThreadLeavesTheMailToFetch) {
  TcpClient client(uncorrected());
  client.expect_fetch_within(30.0);  // before connecting: the comms thread never polls for input
  ASSERT_NO_FATAL_FAILURE(connect_counting_mail(client));
  server.send({mail("A", 1.0)});
  // The comms thread's next TIMING ends the loop in which A arrived: polling for input, it
  // would have read and announced A before sending it.
  ASSERT_TRUE(server.read_packet().has_value());
  EXPECT_EQ(announced.load(), 0) << "the comms thread read mail the app had promised to fetch";
  EXPECT_EQ(keys_of(fetch_as_promised(client)), std::vector<std::string>{"A"});
}

TEST_F(TcpClientAppIo, WithoutAPromiseTheCommsThreadReadsAndAnnouncesMail) {
  TcpClient client(uncorrected());
  client.expect_fetch_within(30.0);
  ASSERT_NO_FATAL_FAILURE(connect_counting_mail(client));
  client.expect_fetch_within(0.0);  // withdrawn, e.g. before an idle sleep that mail must end
  server.send({mail("B", 2.0)});
  EXPECT_TRUE(eventually([&] { return announced.load() > 0; }));
  EXPECT_EQ(keys_of(client.fetch()), std::vector<std::string>{"B"});
}

TEST_F(TcpClientAppIo, ABrokenPromiseEndsAfterTheGrace) {
  TcpClient client(uncorrected());
  const double promised_at = steady_now_s();
  client.expect_fetch_within(0.01);  // and never fetches
  ASSERT_NO_FATAL_FAILURE(connect_counting_mail(client));
  server.send({mail("C", 3.0)});
  ASSERT_TRUE(eventually([&] { return announced.load() > 0; }));
  // Not before the promise and its grace ran out (less a poll's millisecond rounding).
  EXPECT_GE(steady_now_s() - promised_at, 0.01 + TcpClient::kAppReadGrace_real_s - 0.002);
}

// The promise when fetch() cannot read: the comms thread holds the socket (here, stopped by the
// clock inside its next TIMING), so it reads the mail itself and announces it.
TEST_F(TcpClientAppIo, AFetchThatFindsTheSocketBusyLeavesTheMailToTheCommsThread) {
  GateClock gate;
  TcpClientOptions o = uncorrected();
  o.clock = &gate;
  TcpClient client(o);
  client.expect_fetch_within(30.0);
  ASSERT_NO_FATAL_FAILURE(connect_counting_mail(client));
  gate.arm();  // the next reading of the clock is the comms thread's next TIMING
  ASSERT_TRUE(gate.wait_entered());
  server.send({mail("D", 4.0)});
  EXPECT_TRUE(client.fetch().empty());  // the socket is the comms thread's now
  gate.open();
  EXPECT_TRUE(eventually([&] { return announced.load() > 0; }))
      << "mail fetch() could not read waits for a later fetch, unannounced";
  EXPECT_EQ(keys_of(client.fetch()), std::vector<std::string>{"D"});
}

TEST_F(TcpClientAppIo, AReleasedBatchIsWrittenByTheAppsOwnThread) {
  TcpClient client(uncorrected());
  ASSERT_NO_FATAL_FAILURE(connect_and_settle(client));
  // The comms thread sleeps until its next TIMING: a batch written by the time release_sends()
  // returns was written by the releasing thread. It may still hold the socket for the TIMING it
  // just sent; then it sends the batch, and the next cycle tries again.
  std::vector<std::string> posted;
  bool written_on_release = false;
  for (int cycle = 0; cycle < 20 && !written_on_release; ++cycle) {
    client.hold_sends();
    for (const char* var : {"X", "Y"}) {
      posted.push_back(var + std::to_string(cycle));
      ASSERT_TRUE(client.notify(posted.back(), 1.0));
    }
    client.release_sends();
    written_on_release = client.flush(0.0);
    if (!written_on_release) {
      ASSERT_TRUE(client.flush(kWait_s));
    }
  }
  EXPECT_TRUE(written_on_release);
  std::vector<std::string> received;  // postings leave once each, in posting order
  while (received.size() < posted.size()) {
    const auto packet = server.read_packet();
    ASSERT_TRUE(packet.has_value());
    for (auto& key : keys_of(*packet)) received.push_back(key);
  }
  EXPECT_EQ(received, posted);
}

TEST_F(TcpClientAppIo, WhileTheAppSendsTheTimingRidesInItsPackets) {
  TcpClient client(uncorrected());
  ASSERT_NO_FATAL_FAILURE(connect_and_settle(client));
  // An app cycling every 0.1 real s. A due TIMING waits kAppTimingSlack_real_s for the app's
  // next packet, so it goes alone only after a cycle later than that (a loaded machine).
  std::vector<double> releases;
  const double end = steady_now_s() + 3.0;
  for (int i = 0; steady_now_s() < end; ++i) {
    client.hold_sends();
    ASSERT_TRUE(client.notify("P", static_cast<double>(i)));
    client.release_sends();
    releases.push_back(steady_now_s());
    std::this_thread::sleep_for(std::chrono::milliseconds(100));  // the app's work
  }
  releases.push_back(steady_now_s());
  client.close();  // no TIMING after the app's last cycle
  int late_cycles = 0;
  for (std::size_t i = 1; i < releases.size(); ++i)
    if (releases[i] - releases[i - 1] > TcpClient::kAppTimingSlack_real_s - 0.01) ++late_cycles;
  // The first TIMING is not counted: the comms thread planned it before the app sent anything.
  int riding = 0;
  int alone = 0;
  bool first = true;
  while (auto packet = server.read_packet(1.0)) {
    if (packet->front().type != msg_type::kTiming) continue;
    if (!std::exchange(first, false)) ++(packet->size() > 1 ? riding : alone);
  }
  EXPECT_GE(riding + alone, 1) << "a TIMING at least once per second";
  EXPECT_LE(alone, late_cycles) << riding << " TIMINGs rode in the app's packets";
}

TEST_F(TcpClientAppIo, AFetchThatFindsTheConnectionClosedHandsItToTheCommsThread) {
  TcpClient client(uncorrected());
  client.expect_fetch_within(30.0);
  ASSERT_NO_FATAL_FAILURE(connect_and_settle(client));
  const std::uint64_t packets = client.packets_sent();
  server.drop();  // everything the client sent was read: a FIN, not a reset
  // The comms thread is not reading, and could meet the close only by sending its next TIMING:
  // the app's fetch() meets it, and the comms thread drops the connection and reconnects.
  ASSERT_TRUE(eventually([&] {
    EXPECT_TRUE(client.fetch().empty());
    return !client.is_connected();
  }));
  EXPECT_EQ(client.packets_sent(), packets) << "the close was met by sending, not by fetch()";
  EXPECT_EQ(client.last_error(), "the server closed the connection");
  ASSERT_NO_FATAL_FAILURE(handshake());
  EXPECT_TRUE(client.wait_until_connected(kWait_s));
  EXPECT_EQ(client.connection_count(), 2u);
}

}  // namespace
}  // namespace test
}  // namespace moos
