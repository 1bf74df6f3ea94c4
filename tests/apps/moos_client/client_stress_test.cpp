// TcpClient under concurrent use against a real moosdb-lite process, so ThreadSanitizer (the
// tsan preset runs this program) sees every public call racing with the comms thread: several
// threads post, hold and release, promise and fetch, register, wake and close at once. Each
// test asserts what must still hold (every posting delivered once, in order per source) and
// waits on conditions with deadlines, never on fixed sleeps.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "moos/tcp_client.hpp"
#include "moosdb_server.hpp"

namespace moos {
namespace {

using test_support::local_client_options;
using test_support::MoosdbServer;

constexpr double kConnect_s = 10.0;
constexpr double kDelivery_s = 30.0;  // a bound, not a wait: the tests end as soon as all arrived
constexpr int kPosters = 3;
constexpr int kPostsPerThread = 1500;

/// Mail a receiver collected on its own thread, woken by the on-mail callback (no polling).
class Collector {
 public:
  explicit Collector(TcpClient& client) : client_(client) {
    client_.set_on_mail([this] { wake(); });
    thread_ = std::thread([this] { run(); });
  }
  ~Collector() { stop(); }

  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    changed_.notify_all();
    if (thread_.joinable()) thread_.join();
    client_.set_on_mail({});  // the callback captures this object: it goes first
  }
  /// Waits until `count` messages arrived or `timeout_s` passed; the number that arrived.
  std::size_t wait_for(std::size_t count, double timeout_s) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait_for(lock, std::chrono::duration<double>(timeout_s),
                      [&] { return mail_.size() >= count; });
    return mail_.size();
  }
  std::vector<Message> mail() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return mail_;
  }

 private:
  void wake() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      woken_ = true;
    }
    changed_.notify_all();
  }
  void run() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stopping_) {
      // A bounded wait: fetch also runs on its own now and then, racing the comms thread.
      changed_.wait_for(lock, std::chrono::milliseconds(20), [&] { return woken_ || stopping_; });
      woken_ = false;
      lock.unlock();
      client_.expect_fetch_within(0.05);
      std::vector<Message> got = client_.fetch();
      lock.lock();
      for (auto& m : got) mail_.push_back(std::move(m));
      changed_.notify_all();
    }
  }

  TcpClient& client_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<Message> mail_;
  bool woken_ = false;
  bool stopping_ = false;
  std::thread thread_;
};

std::unique_ptr<TcpClient> connected(int port, const std::string& name) {
  auto client = std::make_unique<TcpClient>(local_client_options(port, name));
  if (!client->start() || !client->wait_until_connected(kConnect_s)) return nullptr;
  return client;
}

class ClientStress : public ::testing::Test {
 protected:
  void SetUp() override {
    server.emplace(MOOSDB_LITE_PATH);
    ASSERT_TRUE(server->ok()) << "moosdb-lite did not start";
  }
  std::optional<MoosdbServer> server;
};

TEST_F(ClientStress, ThreadsPostingOnOneClientAreAllDeliveredInOrderPerThread) {
  auto poster = connected(server->port(), "pPoster");
  auto receiver = connected(server->port(), "pReceiver");
  ASSERT_TRUE(poster && receiver);
  ASSERT_TRUE(receiver->register_wildcard("STRESS_*", "pPoster"));
  // The subscription is in place once the receiver's own posting comes back to it.
  ASSERT_TRUE(receiver->register_variable("STRESS_READY"));
  Collector collector(*receiver);
  ASSERT_TRUE(receiver->notify("STRESS_READY", 1.0));
  ASSERT_GE(collector.wait_for(1, kConnect_s), 1u);

  std::atomic<int> refused{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kPosters; ++t) {
    threads.emplace_back([&, t] {
      const std::string var = "STRESS_" + std::to_string(t);
      for (int i = 0; i < kPostsPerThread; ++i) {
        const bool batch = i % 7 == 0;  // hold and release race the comms thread's sending
        if (batch) poster->hold_sends();
        if (!poster->notify(var, static_cast<double>(i))) ++refused;
        if (batch) poster->release_sends();
        if (i % 50 == 0) poster->expect_fetch_within(i % 100 == 0 ? 0.02 : 0.0);
        if (i % 97 == 0) poster->fetch();
      }
    });
  }
  // Meanwhile another thread changes the poster's subscriptions and reads its state.
  threads.emplace_back([&] {
    for (int i = 0; i < 200; ++i) {
      poster->register_variable("STRESS_OTHER_" + std::to_string(i % 5));
      poster->unregister_variable("STRESS_OTHER_" + std::to_string((i + 2) % 5));
      (void)poster->is_connected();
      (void)poster->packets_sent();
      (void)poster->skew_s();
    }
  });
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(refused.load(), 0);
  EXPECT_TRUE(poster->flush(kDelivery_s));

  const std::size_t expected = 1 + static_cast<std::size_t>(kPosters) * kPostsPerThread;
  EXPECT_EQ(collector.wait_for(expected, kDelivery_s), expected);
  collector.stop();
  std::map<std::string, int> next;  // per posting thread: the value expected next
  for (const Message& m : collector.mail()) {
    if (m.key == "STRESS_READY") continue;
    EXPECT_EQ(m.dval, next[m.key]) << m.key;
    next[m.key] = static_cast<int>(m.dval) + 1;
  }
  for (int t = 0; t < kPosters; ++t) EXPECT_EQ(next["STRESS_" + std::to_string(t)], kPostsPerThread);
}

TEST_F(ClientStress, ClosingWhileOtherThreadsPostFetchAndWaitLeavesNothingRunning) {
  constexpr int kRounds = 8;
  for (int round = 0; round < kRounds; ++round) {
    std::atomic<int> callbacks{0};  // declared first: it outlives the client's callbacks
    // A new name each round: the server may not have seen the last round's close yet.
    TcpClient client(local_client_options(server->port(), "pCloser" + std::to_string(round)));
    client.set_on_connect([&] { ++callbacks; });
    client.set_on_mail([&] { ++callbacks; });
    ASSERT_TRUE(client.register_variable("CLOSE_ECHO"));
    ASSERT_TRUE(client.start());
    std::atomic<bool> done{false};
    std::vector<std::thread> threads;
    for (int t = 0; t < 3; ++t) {
      threads.emplace_back([&, t] {
        for (int i = 0; !done; ++i) {
          client.notify("CLOSE_ECHO", static_cast<double>(i));
          if (t == 1) client.expect_fetch_within(i % 2 ? 0.01 : 0.0);
          client.fetch();
          if (t == 2) client.flush(0.001);
          if (i > 20000) break;  // a bound in case close never comes
        }
      });
    }
    const bool connected = client.wait_until_connected(kConnect_s);
    client.wait_until_connected(0.02 * (round % 3));
    client.close();
    done = true;
    for (auto& thread : threads) thread.join();
    ASSERT_TRUE(connected) << client.last_error();
    EXPECT_EQ(client.state(), ConnectionState::kClosed);
    EXPECT_FALSE(client.notify("CLOSE_ECHO", -1.0)) << "a closed client accepts nothing";
    EXPECT_GE(callbacks.load(), 1);  // the on-connect callback ran
  }
}

}  // namespace
}  // namespace moos
