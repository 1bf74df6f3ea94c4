// The in-process bus under concurrent use, for ThreadSanitizer (the tsan preset runs this
// program): clients post from their own threads while others fetch, subscribe, disconnect and
// reconnect. Each test asserts what must still hold: every posting reaches a steady subscriber
// once and in order per source.
#include <gtest/gtest.h>

#include <atomic>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "moos/bus.hpp"

namespace moos {
namespace {

constexpr int kPosters = 4;
constexpr int kPostsPerThread = 2000;

TEST(BusStress, PostersOnTheirOwnThreadsReachASteadySubscriberInOrderPerSource) {
  ManualClock clock{1000.0};
  InProcessBus bus{clock};
  auto reader = bus.connect("pReader");
  ASSERT_TRUE(reader);
  ASSERT_TRUE(reader->register_wildcard("BUS_*"));
  std::atomic<int> wakeups{0};
  reader->set_on_mail([&] { ++wakeups; });

  std::vector<std::unique_ptr<BusClient>> posters;
  for (int t = 0; t < kPosters; ++t) posters.push_back(bus.connect("pPoster" + std::to_string(t)));
  auto flaky = bus.connect("pFlaky");  // disconnects and reconnects meanwhile
  ASSERT_TRUE(flaky);

  std::atomic<int> refused{0};
  std::atomic<bool> posting{true};
  std::vector<std::thread> threads;
  for (int t = 0; t < kPosters; ++t) {
    threads.emplace_back([&, t] {
      BusClient& client = *posters[static_cast<std::size_t>(t)];
      for (int i = 0; i < kPostsPerThread; ++i)
        if (!client.notify("BUS_" + std::to_string(t), static_cast<double>(i))) ++refused;
    });
  }
  threads.emplace_back([&] {
    for (int i = 0; posting; ++i) {
      flaky->simulate_disconnect();
      flaky->notify("FLAKY", static_cast<double>(i));
      flaky->simulate_reconnect();
      flaky->register_variable("BUS_0");
      flaky->fetch();
    }
  });
  std::vector<Message> mail;  // the reader's thread only, until it is joined
  std::thread reader_thread([&] {
    while (posting)
      for (auto& m : reader->fetch()) mail.push_back(std::move(m));  // races the deliveries
  });
  for (int t = 0; t < kPosters; ++t) threads[static_cast<std::size_t>(t)].join();
  posting = false;
  threads.back().join();
  reader_thread.join();
  for (auto& m : reader->fetch()) mail.push_back(std::move(m));

  EXPECT_EQ(refused.load(), 0);
  ASSERT_EQ(mail.size(), static_cast<std::size_t>(kPosters) * kPostsPerThread);
  std::map<std::string, int> next;
  for (const Message& m : mail) {
    EXPECT_EQ(m.dval, next[m.source]) << m.source;
    next[m.source] = static_cast<int>(m.dval) + 1;
  }
  for (int t = 0; t < kPosters; ++t) EXPECT_EQ(next["pPoster" + std::to_string(t)], kPostsPerThread);
  EXPECT_GE(wakeups.load(), 1);
  reader->set_on_mail({});
}

TEST(BusStress, ThreadsSharingOneClientPostWholeMessagesInOrderPerThread) {
  // One client's notify() from several threads at once: each posting is built whole (one of
  // them in the client's kept message, the others in their own) and delivered once, in order.
  ManualClock clock{1000.0};
  InProcessBus bus{clock};
  auto reader = bus.connect("pReader");
  auto shared = bus.connect("pShared");
  ASSERT_TRUE(reader && shared);
  ASSERT_TRUE(reader->register_wildcard("SHARED_*"));
  std::vector<std::thread> threads;
  for (int t = 0; t < kPosters; ++t) {
    threads.emplace_back([&, t] {
      const std::string var = "SHARED_" + std::to_string(t);
      for (int i = 0; i < kPostsPerThread; ++i)
        shared->notify(var, std::to_string(t) + ":" + std::to_string(i) + std::string(40, '.'));
    });
  }
  std::vector<Message> mail;
  std::vector<Message> batch;  // handed back at each fetch, as an app does
  std::atomic<bool> posting{true};
  std::thread reader_thread([&] {
    while (posting) {
      reader->fetch_into(batch);
      mail.insert(mail.end(), batch.begin(), batch.end());
    }
  });
  for (auto& t : threads) t.join();
  posting = false;
  reader_thread.join();
  for (auto& m : reader->fetch()) mail.push_back(std::move(m));

  ASSERT_EQ(mail.size(), static_cast<std::size_t>(kPosters) * kPostsPerThread);
  std::map<std::string, int> next;
  for (const Message& m : mail) {
    EXPECT_EQ(m.source, "pShared");
    const std::string thread = m.key.substr(std::string("SHARED_").size());
    EXPECT_EQ(m.sval, thread + ":" + std::to_string(next[thread]) + std::string(40, '.'));
    ++next[thread];
  }
}

}  // namespace
}  // namespace moos
