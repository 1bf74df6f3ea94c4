// The socket loop in-process, with limits a test can reach quickly: the global memory budget
// (docs/robustness.md, "Server bounds"). The loop runs in a thread on a free port and is stopped
// through its wake pipe.

#include <gtest/gtest.h>
#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "event_loop.hpp"
#include "hub.hpp"
#include "moos/clock.hpp"
#include "raw_client.hpp"
#include "wire_messages.hpp"

namespace moosdb_lite::test {
namespace {

using namespace moos::test;

/// A budget small enough for a test, and what three hoarders send of their packets: the
/// first two stay under it, the third passes it only once it holds the most (> 2 MB).
constexpr std::size_t kTestBudgetBytes = 4u * 1024u * 1024u;
constexpr std::size_t kPartialBytes[] = {1000u * 1000u, 1200u * 1000u, 3000u * 1000u};

class LoopUnderTest {
 public:
  explicit LoopUnderTest(std::size_t budget_bytes) {
    EXPECT_EQ(::pipe2(wake_, O_NONBLOCK | O_CLOEXEC), 0);
    HubConfig hub_config;
    hub_config.client_timeout_s = 60;
    hub_ = std::make_unique<Hub>(hub_config, moos::system_clock().unix_now_s(), logger());
    EventLoopConfig config;
    config.bind_address = "127.0.0.1";
    config.max_output_bytes = kDefaultMaxPendingBytes;
    config.memory_budget_bytes = budget_bytes;
    loop_ = std::make_unique<EventLoop>(config, *hub_, logger());
    std::string error;
    EXPECT_TRUE(loop_->listen(&error)) << error;
    // The loop's flag is a signal handler's (one thread): the loop thread sets it itself, after
    // a round, from the atomic the test's thread sets.
    thread_ = std::thread([this] {
      loop_->run(wake_[0], stop_, [this] { stop_ = stopping_.load() ? 1 : 0; });
    });
  }
  ~LoopUnderTest() {
    stopping_ = true;
    const char byte = 1;
    EXPECT_EQ(::write(wake_[1], &byte, 1), 1);
    thread_.join();
    ::close(wake_[0]);
    ::close(wake_[1]);
  }
  int port() const { return loop_->bound_port(); }
  std::string log() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return log_;
  }

 private:
  EventLoop::LogSink logger() {
    return [this](const std::string& line) {
      const std::lock_guard<std::mutex> lock(mutex_);
      log_ += line + "\n";
    };
  }
  int wake_[2] = {-1, -1};
  volatile std::sig_atomic_t stop_ = 0;  // the loop thread's only
  std::atomic<bool> stopping_{false};
  std::mutex mutex_;
  std::string log_;
  std::unique_ptr<Hub> hub_;
  std::unique_ptr<EventLoop> loop_;
  std::thread thread_;
};

/// The start of a packet announcing `announced` bytes, `sent` of them (header included).
std::string packet_start(std::size_t announced, std::size_t sent) {
  std::string bytes(sent, '\0');
  const auto size = static_cast<std::uint32_t>(announced);
  for (std::size_t i = 0; i < 4; ++i) bytes[i] = static_cast<char>(size >> (8 * i));
  return bytes;
}

// Clients that send large partial packets and never finish them cannot take more than the
// budget: the one holding the most is dropped with a warning, the others are served.
TEST(EventLoopBudget, PartialPacketsOverTheBudgetDropTheLargestHolder) {
  LoopUnderTest loop(kTestBudgetBytes);
  std::vector<std::unique_ptr<RawClient>> hoarders;
  for (int i = 0; i < 3; ++i) {
    hoarders.push_back(std::make_unique<RawClient>());
    ASSERT_TRUE(hoarders.back()->join(loop.port(), "pHoard" + std::to_string(i), true));
    const std::size_t sent = kPartialBytes[i];
    ASSERT_TRUE(hoarders.back()->send_bytes(packet_start(2 * sent, sent)));
  }
  RawClient bystander;
  ASSERT_TRUE(bystander.join(loop.port(), "pBystander", false));
  EXPECT_TRUE(hoarders[2]->wait_closed(kArrivalTimeout_s));
  EXPECT_TRUE(bystander.exchange({null_message("pBystander")}));
  const std::string log = loop.log();
  EXPECT_NE(log.find("over the memory budget of " + std::to_string(kTestBudgetBytes)),
            std::string::npos) << log;
  EXPECT_NE(log.find("1 dropped by the budget so far"), std::string::npos) << log;
  EXPECT_NE(log.find("client \"pHoard2\""), std::string::npos) << log;
  EXPECT_FALSE(hoarders[0]->wait_closed(kSilence_s));
}

// Synchronous clients that never send again never collect their mail: what the database keeps
// for them counts against the budget too.
TEST(EventLoopBudget, UncollectedMailOverTheBudgetDropsAHolder) {
  LoopUnderTest loop(kTestBudgetBytes);
  std::vector<std::unique_ptr<RawClient>> hoarders;
  for (int i = 0; i < 3; ++i) {
    hoarders.push_back(std::make_unique<RawClient>());
    const std::string name = "pHoard" + std::to_string(i);
    ASSERT_TRUE(hoarders.back()->join(loop.port(), name, false));
    ASSERT_TRUE(hoarders.back()->exchange({registration("BIG", 0, name)}));
  }
  RawClient poster;
  ASSERT_TRUE(poster.join(loop.port(), "pPoster", true));
  // Each post queues 1 MB for each of the three: the second passes the 4 MiB budget.
  for (int i = 0; i < 2; ++i)
    ASSERT_TRUE(poster.send({notify_string("BIG", std::string(1000u * 1000u, 'b'), "pPoster")}));
  EXPECT_TRUE(hoarders[0]->wait_closed(kArrivalTimeout_s));
  const std::string log = loop.log();
  EXPECT_NE(log.find("over the memory budget"), std::string::npos) << log;
  EXPECT_NE(log.find("client \"pHoard0\""), std::string::npos) << log;
  EXPECT_TRUE(hoarders[1]->exchange({null_message("pHoard1")}));
}

}  // namespace
}  // namespace moosdb_lite::test
