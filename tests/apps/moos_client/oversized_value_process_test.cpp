// A value larger than any client accepts, end to end with the real programs (limits in
// include/moos/codec.hpp): our client refuses to post it, naming it; moosdb-lite refuses to
// store it from a client that sends it anyway, naming it in its log; and a `moos-cli watch` of
// it stays connected and times out with its count. Before the limits agreed, the server stored
// a 130 MiB value, sent it to the watch as one packet the client refused, and the watch
// reconnected every second (13 times in 15 s) to get the same packet again.
#include <gtest/gtest.h>

#include <string>

#include "child_process.hpp"
#include "moos/codec.hpp"
#include "moos/tcp_client.hpp"
#include "moosdb_server.hpp"
#include "raw_client.hpp"

namespace moos {
namespace {

using test_support::Child;
using test_support::local_client_options;
using test_support::MoosdbServer;

constexpr std::size_t kOversized = 130u * 1024u * 1024u;  // above kMaxMessageBytes (128 MiB)
constexpr double kConnect_s = 10.0;
constexpr double kLog_s = 60.0;  // 130 MiB through a sanitizer build on a loaded machine

TEST(OversizedValue, RefusedOnceWhereItEntersAndTheWatchNeverReconnects) {
  static_assert(kOversized > kMaxMessageBytes);
  MoosdbServer server(MOOSDB_LITE_PATH);
  ASSERT_TRUE(server.ok());
  const std::string port_arg = "--port=" + std::to_string(server.port());
  auto watch = Child::spawn(MOOS_CLI_PATH, {"watch", "--host=127.0.0.1", port_arg, "--name=watcher",
                                            "--count=1", "--timeout=8", "BIG"});
  ASSERT_TRUE(watch.has_value());
  TcpClient reader(local_client_options(server.port(), "pReader"));
  ASSERT_TRUE(reader.register_variable("BIG"));
  ASSERT_TRUE(reader.start() && reader.wait_until_connected(kConnect_s));

  // Our own client refuses to post it, naming it, and counts it.
  TcpClient poster(local_client_options(server.port(), "pPoster"));
  ASSERT_TRUE(poster.start() && poster.wait_until_connected(kConnect_s));
  EXPECT_FALSE(poster.notify("BIG", std::string(kOversized, 'b')));
  EXPECT_EQ(poster.postings_dropped(), 1u);
  EXPECT_NE(poster.last_post_error().find("NOTIFY BIG refused"), std::string::npos)
      << poster.last_post_error();

  // A client that sends it anyway (the server takes packets up to 256 MiB) is refused by the
  // server, with a logged reason that names the variable; the client stays connected.
  // Encoded before the handshake: building it may take longer than the server's ClientTimeout.
  const std::string packet =
      encode_packet({make_string_notify("BIG", std::string(kOversized, 'b'), "pRaw", 0)});
  moosdb_lite::test::RawClient raw;
  ASSERT_TRUE(raw.join(server.port(), "pRaw", true));
  ASSERT_TRUE(raw.send_bytes(packet)) << server.stderr_text();
  EXPECT_TRUE(server.wait_for_log("NOTIFY BIG refused: its", kLog_s)) << server.stderr_text();

  // The watch gets nothing, and says so at its timeout; it never lost its connection.
  const auto rc = watch->wait(30.0);
  EXPECT_EQ(rc, 2) << watch->stderr_text();
  EXPECT_NE(watch->stderr_text().find("with 0 of 1 messages"), std::string::npos)
      << watch->stderr_text();
  EXPECT_EQ(watch->stderr_text().find("lost"), std::string::npos) << watch->stderr_text();
  EXPECT_TRUE(reader.is_connected());
  EXPECT_EQ(reader.connection_count(), 1u) << reader.last_error();
  EXPECT_TRUE(reader.fetch().empty());
}

}  // namespace
}  // namespace moos
