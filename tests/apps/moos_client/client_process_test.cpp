// libmoos's TcpClient against a real moosdb-lite process (docs/protocol.md sections 1, 4 and 5):
// two of our clients exchange 10,000 messages of each data type in order; registration
// snapshots, wildcard subscriptions and throttled intervals behave as section 5 says; a client
// survives the server being killed and restarted and gets its subscriptions back.
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <thread>

#include "moos/tcp_client.hpp"
#include "moosdb_server.hpp"

namespace moos {
namespace {

using test_support::local_client_options;
using test_support::MoosdbServer;
using test_support::steady_now_s;

constexpr double kConnect_s = 10.0;
constexpr double kDelivery_s = 60.0;  // upper bound for 30,000 messages on a loaded 2-core box
constexpr int kMessagesPerType = 10000;

std::unique_ptr<TcpClient> connect_client(int port, const std::string& name) {
  auto c = std::make_unique<TcpClient>(local_client_options(port, name));
  if (!c->start() || !c->wait_until_connected(kConnect_s)) return nullptr;
  return c;
}

/// Collects mail until `done(all)` holds or `timeout_s` passes.
template <typename Done>
std::vector<Message> collect(TcpClient& c, double timeout_s, Done done) {
  std::vector<Message> all;
  const double deadline = steady_now_s() + timeout_s;
  while (!done(all) && steady_now_s() < deadline) {
    auto mail = c.fetch();
    if (mail.empty()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      continue;
    }
    for (auto& m : mail) all.push_back(std::move(m));
  }
  return all;
}

std::vector<Message> only(const std::vector<Message>& mail, const std::string& key) {
  std::vector<Message> out;
  for (const auto& m : mail)
    if (m.key == key) out.push_back(m);
  return out;
}

std::string binary_payload(int i) {
  std::string bytes(8, '\0');
  std::memcpy(bytes.data(), &i, sizeof i);  // includes NUL bytes on purpose
  bytes[7] = static_cast<char>(0xff);
  return bytes;
}

class ClientWithServer : public ::testing::Test {
 protected:
  void SetUp() override {
    server.emplace(MOOSDB_LITE_PATH);
    ASSERT_TRUE(server->ok()) << "moosdb-lite did not start";
    a = connect_client(server->port(), "pA");
    b = connect_client(server->port(), "pB");
    ASSERT_TRUE(a && b);
  }
  void TearDown() override {
    a.reset();
    b.reset();
    if (server) server->stop();
  }
  std::optional<MoosdbServer> server;
  std::unique_ptr<TcpClient> a;
  std::unique_ptr<TcpClient> b;
};

TEST_F(ClientWithServer, TenThousandMessagesOfEachTypeArriveInOrder_5_3) {
  ASSERT_TRUE(b->register_variable("D_VAR"));
  ASSERT_TRUE(b->register_variable("S_VAR"));
  ASSERT_TRUE(b->register_variable("B_VAR"));
  ASSERT_TRUE(a->register_variable("D_VAR"));  // the publisher hears itself (protocol.md 5.3)
  ASSERT_TRUE(b->flush(kConnect_s) && a->flush(kConnect_s));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // registrations processed
  for (int i = 0; i < kMessagesPerType; ++i) {
    ASSERT_TRUE(a->notify("D_VAR", static_cast<double>(i)));
    ASSERT_TRUE(a->notify("S_VAR", "s" + std::to_string(i)));
    ASSERT_TRUE(a->notify_binary("B_VAR", binary_payload(i)));
  }
  const auto mail = collect(*b, kDelivery_s, [](const std::vector<Message>& m) {
    return m.size() >= 3u * kMessagesPerType;
  });
  ASSERT_EQ(mail.size(), 3u * kMessagesPerType);
  for (int i = 0; i < kMessagesPerType; ++i) {
    const auto k = static_cast<std::size_t>(3 * i);
    ASSERT_EQ(mail[k].key, "D_VAR") << i;
    ASSERT_EQ(mail[k].dval, i);
    ASSERT_EQ(mail[k + 1].key, "S_VAR") << i;
    ASSERT_EQ(mail[k + 1].sval, "s" + std::to_string(i));
    ASSERT_TRUE(mail[k + 1].is_string());
    ASSERT_EQ(mail[k + 2].key, "B_VAR") << i;
    ASSERT_TRUE(mail[k + 2].is_binary());
    ASSERT_EQ(mail[k + 2].sval, binary_payload(i));
    ASSERT_EQ(mail[k].source, "pA");
  }
  const auto own = collect(*a, kDelivery_s, [](const std::vector<Message>& m) {
    return m.size() >= static_cast<std::size_t>(kMessagesPerType);
  });
  ASSERT_EQ(own.size(), static_cast<std::size_t>(kMessagesPerType));
  EXPECT_EQ(own.back().dval, kMessagesPerType - 1);
}

TEST_F(ClientWithServer, RegisterGetsASnapshotOfTheLastWrite_5_4) {
  ASSERT_TRUE(a->notify("SNAP", std::string("first")));
  ASSERT_TRUE(a->notify("SNAP", std::string("latest"), 1700000000.5, "aux-a"));
  ASSERT_TRUE(a->flush(kConnect_s));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ASSERT_TRUE(b->register_variable("SNAP"));
  const auto mail = collect(*b, kConnect_s, [](const std::vector<Message>& m) { return !m.empty(); });
  ASSERT_EQ(only(mail, "SNAP").size(), 1u);
  const Message snap = only(mail, "SNAP")[0];
  EXPECT_EQ(snap.sval, "latest");
  EXPECT_EQ(snap.source, "pA");
  EXPECT_EQ(snap.source_aux, "aux-a");
  EXPECT_EQ(snap.time, 1700000000.5);
  EXPECT_EQ(snap.id, kUnsetId);
}

TEST_F(ClientWithServer, WildcardSubscriptionsMatchNamesAndWriters_5_5) {
  ASSERT_TRUE(a->notify("W_OLD", 1.0));  // exists before the wildcard registration
  ASSERT_TRUE(a->flush(kConnect_s));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ASSERT_TRUE(b->register_wildcard("W_*", "*"));
  ASSERT_TRUE(b->register_wildcard("*_FROM_A", "pA"));
  ASSERT_TRUE(b->flush(kConnect_s));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  auto c = connect_client(server->port(), "pC");
  ASSERT_TRUE(c);
  ASSERT_TRUE(a->notify("W_NEW", 2.0));
  ASSERT_TRUE(a->notify("V_NEW", 3.0));
  ASSERT_TRUE(a->notify("X_FROM_A", 4.0));
  ASSERT_TRUE(a->flush(kConnect_s));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_TRUE(c->notify("Y_FROM_A", 5.0));  // first writer pC: not matched
  ASSERT_TRUE(c->notify("W_C", 6.0));       // any app matches W_*
  const auto mail = collect(*b, 3.0, [](const std::vector<Message>& m) { return m.size() >= 4; });
  std::vector<std::string> keys;
  for (const auto& m : mail) keys.push_back(m.key);
  EXPECT_EQ(keys, (std::vector<std::string>{"W_OLD", "W_NEW", "X_FROM_A", "W_C"}));
}

TEST_F(ClientWithServer, ThrottledIntervalDropsUpdates_5_3) {
  ASSERT_TRUE(b->register_variable("THROTTLED", 1.0));
  ASSERT_TRUE(b->register_variable("THROTTLE_END"));
  ASSERT_TRUE(b->flush(kConnect_s));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const double started = steady_now_s();
  for (int i = 0; i < 25; ++i) {
    ASSERT_TRUE(a->notify("THROTTLED", static_cast<double>(i)));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  const double span_s = steady_now_s() - started;
  // The server forwards A's postings in order: once THROTTLE_END is in, every update it passed is.
  ASSERT_TRUE(a->notify("THROTTLE_END", 1.0));
  const auto mail = only(collect(*b, kConnect_s, [](const std::vector<Message>& m) {
                           return !only(m, "THROTTLE_END").empty();
                         }),
                         "THROTTLED");
  // One delivery per started second of posting: t = 0, >= 1, >= 2 (more only if the loop ran slow).
  ASSERT_GE(mail.size(), 2u);
  EXPECT_LE(mail.size(), static_cast<std::size_t>(span_s / 1.0) + 1);
  EXPECT_EQ(mail[0].dval, 0.0);
  for (std::size_t i = 1; i < mail.size(); ++i) EXPECT_GE(mail[i].time - mail[i - 1].time, 1.0 - 1e-3);
}

// The delivery contract (moos/comms.hpp) with a real server: a posting made while the server
// is down waits in the outbox and leaves after the reconnect, behind the replayed registrations.
TEST(ClientServerRestart, ClientSurvivesAKilledServerAndGetsItsSubscriptionsBack_1_9) {
  MoosdbServer server(MOOSDB_LITE_PATH);
  ASSERT_TRUE(server.ok());
  const int port = server.port();
  auto b = connect_client(port, "pB");
  ASSERT_TRUE(b);
  ASSERT_TRUE(b->register_variable("AFTER_RESTART"));
  ASSERT_TRUE(b->register_wildcard("WILD_*"));
  ASSERT_TRUE(b->register_variable("WHILE_DOWN"));
  ASSERT_TRUE(b->flush(kConnect_s));

  server.process().kill_now();  // SIGKILL: no goodbye
  double deadline = steady_now_s() + kConnect_s;
  while (b->is_connected() && steady_now_s() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_FALSE(b->is_connected());
  EXPECT_TRUE(b->notify("WHILE_DOWN", 1.0));  // kept for the reconnect
  EXPECT_TRUE(b->notify("WHILE_DOWN", 2.0));

  MoosdbServer restarted(MOOSDB_LITE_PATH, {}, port);  // same port: the client keeps retrying it
  ASSERT_TRUE(restarted.ok());
  ASSERT_TRUE(b->wait_until_connected(kConnect_s));
  EXPECT_EQ(b->connection_count(), 2u);
  // Its own postings come back to it: the registrations were replayed before them.
  const auto kept = collect(*b, kConnect_s, [](const std::vector<Message>& m) { return m.size() >= 2; });
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].key, "WHILE_DOWN");
  EXPECT_EQ(kept[0].dval, 1.0);
  EXPECT_EQ(kept[1].dval, 2.0);
  EXPECT_EQ(b->postings_dropped(), 0u);
  auto a = connect_client(port, "pA");
  ASSERT_TRUE(a);
  ASSERT_TRUE(a->notify("AFTER_RESTART", 7.0));
  ASSERT_TRUE(a->notify("WILD_ONE", 8.0));
  const auto mail = collect(*b, kConnect_s, [](const std::vector<Message>& m) { return m.size() >= 2; });
  ASSERT_EQ(mail.size(), 2u);
  EXPECT_EQ(mail[0].key, "AFTER_RESTART");
  EXPECT_EQ(mail[1].key, "WILD_ONE");
  a.reset();
  b.reset();
  restarted.stop();
}

TEST(ClientServerPoison, SecondClientWithTheSameNameIsRefusedForGood_1_6) {
  MoosdbServer server(MOOSDB_LITE_PATH);
  ASSERT_TRUE(server.ok());
  auto first = connect_client(server.port(), "pSame");
  ASSERT_TRUE(first);
  TcpClient second(local_client_options(server.port(), "pSame"));
  ASSERT_TRUE(second.start());
  EXPECT_FALSE(second.wait_until_connected(kConnect_s));
  EXPECT_EQ(second.state(), ConnectionState::kPoisoned);
  EXPECT_NE(second.last_error().find("pSame"), std::string::npos) << second.last_error();
  EXPECT_TRUE(first->is_connected());
  second.close();
  first.reset();
  server.stop();
}

}  // namespace
}  // namespace moos
