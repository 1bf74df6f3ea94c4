// Hardening of the real server: a server stall does not drop healthy clients,
// descriptor exhaustion neither spins nor floods the log, client text cannot forge log lines,
// and a client whose output piles up is slowed down and warned before it is dropped.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "base/text.hpp"
#include "child_process.hpp"
#include "event_loop.hpp"
#include "moosdb_server.hpp"
#include "raw_client.hpp"
#include "scratch_files.hpp"
#include "text_count.hpp"
#include "wire_messages.hpp"

namespace moosdb_lite::test {

using namespace moos::test;
namespace {

using moos::Message;
using test_support::Child;
using test_support::count_of;
using test_support::MoosdbServer;
using test_support::ScratchDir;
using test_support::steady_now_s;

/// Variables the stalling client creates, and wildcard filters it then registers: each
/// filter is matched against every variable, so the packet keeps the server busy. The number
/// of filters doubles until one packet stalls the server for kStallFactor x the timeout
/// (measured, and asserted, so the test cannot pass without a stall on any machine).
constexpr int kStallVariables = 20000;
constexpr int kFirstStallFilters = 800;
constexpr int kMostStallFilters = 800 * 16;
constexpr double kStallTimeout_s = 1.0;
constexpr double kStallFactor = 1.5;

/// One packet of `count` WILDCARD_REGISTERs that match no variable, all different.
std::vector<Message> non_matching_filters(int first, int count) {
  std::vector<Message> filters;
  for (int i = first; i < first + count; ++i)
    filters.push_back(wildcard(
        "AppPattern=*,VarPattern=NO_MATCH_" + std::to_string(i) + "_*,Interval=0", "pStall"));
  return filters;
}

bool contains(const std::string& text, const std::string& fragment) {
  return text.find(fragment) != std::string::npos;
}

// A client that keeps talking (a TIMING every 100 ms, replies left unread) while the server
// is busy with another client's packet must not be dropped as silent afterwards.
TEST(MoosdbLiteHardening, ServerStallDoesNotDropClientsWhoseInputWaited) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--moos_timeout=" + base::format_g(kStallTimeout_s)});
  ASSERT_TRUE(server.ok());
  RawClient staller;
  ASSERT_TRUE(staller.join(server.port(), "pStall", false));
  std::vector<Message> create;
  for (int i = 0; i < kStallVariables; ++i)
    create.push_back(notify_double("STALL_" + std::to_string(i), i, "pStall"));
  ASSERT_TRUE(staller.exchange(create));

  RawClient heart;
  ASSERT_TRUE(heart.join(server.port(), "pHeart", true));
  std::atomic<bool> beating{true};
  std::thread beats([&] {
    while (beating) {
      heart.send({timing(moos_now())});
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  double stall_s = 0;
  bool replied = true;
  int sent = 0;
  for (int count = kFirstStallFilters;
       replied && stall_s <= kStallFactor * kStallTimeout_s && count <= kMostStallFilters;
       count *= 2) {
    const auto filters = non_matching_filters(sent, count);
    sent += count;
    const double start = steady_now_s();
    replied = staller.exchange(filters).has_value();
    stall_s = steady_now_s() - start;
  }
  // Rounds after the stall, well within the timeout for the staller that waited for its reply.
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const std::string log = server.stderr_text();
  beating = false;
  beats.join();

  ASSERT_TRUE(replied) << "the stalling client itself was dropped";
  ASSERT_GT(stall_s, kStallFactor * kStallTimeout_s) << "no packet stalled the server long enough";
  EXPECT_FALSE(contains(log, "nothing received")) << log;
  EXPECT_TRUE(staller.exchange({null_message("pStall")})) << "pStall lost its connection";
}

// moosdb-lite limited to a few descriptors (ulimit in a shell that then execs it), flooded
// with connections: it sheds the excess at once, keeps serving, and logs a few lines only.
TEST(MoosdbLiteHardening, DescriptorExhaustionShedsConnectionsAndKeepsServing) {
  constexpr int kDescriptorLimit = 24;
  constexpr int kFloodConnections = 100;
  const ScratchDir dir;
  const std::string port_file = (dir / "port").string();
  const std::string command = "ulimit -n " + std::to_string(kDescriptorLimit) + " && exec " +
                              MOOSDB_LITE_PATH + " --moos_port=0 --moos_timeout=60 --port-file=" +
                              port_file;
  auto child = Child::spawn("/bin/sh", {"-c", command});
  ASSERT_TRUE(child);
  const int port = test_support::wait_for_port_file(port_file, 10.0);
  ASSERT_GT(port, 0) << child->stderr_text();
  RawClient keeper;
  ASSERT_TRUE(keeper.join(port, "pKeeper", false));

  std::vector<std::unique_ptr<RawClient>> flood;
  for (int i = 0; i < kFloodConnections; ++i) {
    flood.push_back(std::make_unique<RawClient>());
    flood.back()->connect(port);
  }
  std::this_thread::sleep_for(std::chrono::seconds(1));
  EXPECT_TRUE(keeper.exchange({null_message("pKeeper")})) << "the connected client lost service";
  const std::string log = child->stderr_text();
  EXPECT_TRUE(contains(log, "cannot accept connections")) << log;
  // One warning per 10 s, and one line per connection that got in: a few kB, not millions.
  EXPECT_LE(count_of(log, "cannot accept connections"), 2u) << log;
  EXPECT_LT(log.size(), 20000u);

  flood.clear();  // descriptors come back as the server sees the closes
  // Until the server has seen the closes, a newcomer may still be shed: retry (bounded).
  bool joined = false;
  for (const double start = steady_now_s(); !joined && steady_now_s() - start < 5;) {
    RawClient late;
    const auto welcome = late.connect(port) ? late.handshake("pLate", false, moos_now())
                                            : std::nullopt;
    joined = welcome && !welcome->empty() && welcome->front().type == moos::msg_type::kWelcome &&
             late.exchange({null_message("pLate")});
    if (!joined) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_TRUE(joined) << "no new client could connect after the flood";
  EXPECT_TRUE(child->running()) << "the server died";
  child->stop();
}

// A newline in a client name, a variable name or a wildcard pattern reaches the log escaped:
// no client can end a log line or forge one.
TEST(MoosdbLiteHardening, ClientTextReachesTheLogEscaped) {
  MoosdbServer server(MOOSDB_LITE_PATH);
  ASSERT_TRUE(server.ok());
  const std::string forged = "\nmoosdb-lite: forged line";
  RawClient evil;
  ASSERT_TRUE(evil.join(server.port(), "pEvil" + forged, false));
  Message bad_type = notify_double("KEY" + forged, 1, "pEvil");
  bad_type.data_type = 'Z';
  Message bad_pattern = wildcard(std::string(300, '*') + forged, "pEvil");
  ASSERT_TRUE(evil.exchange({bad_type, bad_pattern}));
  RawClient twin;  // the duplicate name is quoted in the refusal
  const auto poison = [&] {
    twin.connect(server.port());
    return twin.handshake("pEvil" + forged, false, moos_now());
  }();
  ASSERT_TRUE(poison);
  evil.close();
  ASSERT_TRUE(server.wait_for_log("closed by the peer", kArrivalTimeout_s));

  const std::string log = server.stderr_text();
  EXPECT_FALSE(contains(log, "\nmoosdb-lite: forged")) << log;
  EXPECT_TRUE(contains(log, "client \"pEvil\\x0Amoosdb-lite: forged line\"")) << log;
  EXPECT_TRUE(contains(log, "NOTIFY KEY\\x0Amoosdb-lite: forged line with data type 'Z'")) << log;
  EXPECT_TRUE(contains(log, "already exists")) << log;
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);)
    EXPECT_EQ(line.rfind("moosdb-lite: ", 0), 0u) << "a line the server did not write: " << line;
}

/// Posts `count` messages of `bytes` each to `key`, one packet each, from a sync client.
void post_large(RawClient& poster, const std::string& key, int count, std::size_t bytes) {
  for (int i = 0; i < count; ++i)
    ASSERT_TRUE(poster.exchange({notify_string(key, std::string(bytes, 'x'), poster.name())}));
}

constexpr std::size_t kLargeMessageBytes = 1024 * 1024;
/// Enough 1 MiB messages to pass the back-pressure threshold.
const int kMessagesOverPauseThreshold =
    static_cast<int>(kPauseReadingOutputBytes / kLargeMessageBytes) + 8;

/// `subscriber` joins as "pSlow" (asynchronous, 64 KiB receive buffer, subscribed to BIG) and
/// `poster` as "pPoster" (synchronous); returns once the subscription is in place.
void join_subscriber_and_poster(int port, RawClient& subscriber, RawClient& poster) {
  ASSERT_TRUE(subscriber.connect(port, 64 * 1024));
  ASSERT_TRUE(subscriber.handshake("pSlow", true, moos_now()));
  ASSERT_TRUE(subscriber.send({registration("BIG", 0, "pSlow")}));
  ASSERT_TRUE(poster.join(port, "pPoster", false));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the REGISTER is processed
}

// A subscriber that does not read for a while is slowed down and warned about, not dropped,
// and gets every message once it reads again.
TEST(MoosdbLiteHardening, SlowReaderIsWarnedAndKeptUnderTheOutputBound) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--moos_timeout=3"});
  ASSERT_TRUE(server.ok());
  RawClient slow;
  RawClient poster;
  join_subscriber_and_poster(server.port(), slow, poster);
  post_large(poster, "BIG", kMessagesOverPauseThreshold, kLargeMessageBytes);
  EXPECT_TRUE(server.wait_for_log("its messages are delayed", kArrivalTimeout_s));
  const auto mail = slow.read_notifies(static_cast<std::size_t>(kMessagesOverPauseThreshold), 30);
  EXPECT_EQ(mail.size(), static_cast<std::size_t>(kMessagesOverPauseThreshold));
  EXPECT_FALSE(contains(server.stderr_text(), "connection dropped")) << server.stderr_text();
}

// Past the per-client output bound the client is dropped, but only after the warning.
TEST(MoosdbLiteHardening, OutputBoundDropsOnlyAfterTheWarning) {
  const std::size_t bound = kPauseReadingOutputBytes + 16 * kLargeMessageBytes;
  MoosdbServer server(MOOSDB_LITE_PATH,
                      {"--moos_timeout=60", "--max-output-bytes=" + std::to_string(bound)});
  ASSERT_TRUE(server.ok());
  RawClient slow;
  RawClient poster;
  join_subscriber_and_poster(server.port(), slow, poster);
  post_large(poster, "BIG", static_cast<int>(bound / kLargeMessageBytes) + 8, kLargeMessageBytes);
  ASSERT_TRUE(server.wait_for_log("exceed the limit", kArrivalTimeout_s));
  const std::string log = server.stderr_text();
  EXPECT_LT(log.find("its messages are delayed"), log.find("exceed the limit")) << log;
  EXPECT_TRUE(slow.wait_closed(kArrivalTimeout_s));
}

// A client that takes nothing for kSendStall_s while a little output waits (far below every
// byte bound) is dropped, as by the reference DB's send timeout.
TEST(MoosdbLiteHardening, ClientThatTakesNothingForTheSendTimeoutIsDropped) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--moos_timeout=0"});
  ASSERT_TRUE(server.ok());
  RawClient stuck;  // never reads
  RawClient poster;
  join_subscriber_and_poster(server.port(), stuck, poster);
  // More than the kernel's socket buffers take, far less than the back-pressure threshold.
  post_large(poster, "BIG", 16, kLargeMessageBytes);
  const std::string reason =
      "nothing could be written for " + std::to_string(static_cast<int>(kSendStall_s)) + " s";
  EXPECT_TRUE(server.wait_for_log(reason, kSendStall_s + kArrivalTimeout_s))
      << server.stderr_text();
  EXPECT_TRUE(server.wait_for_log("client \"pSlow\"", kArrivalTimeout_s));
  EXPECT_TRUE(poster.exchange({null_message("pPoster")}));
}

}  // namespace
}  // namespace moosdb_lite::test
