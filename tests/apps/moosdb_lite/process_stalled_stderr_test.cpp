// The server's standard error is a pipe nobody reads (a stalled reader): it keeps serving every
// client and stops at SIGTERM. Its diagnostics go through base::DiagnosticWriter, which drops
// (and counts) what the pipe cannot take instead of waiting for it.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <string>

#include "child_process.hpp"
#include "moosdb_server.hpp"
#include "raw_client.hpp"
#include "scratch_files.hpp"
#include "wire_messages.hpp"

namespace moosdb_lite::test {

using namespace moos::test;
namespace {

using test_support::Child;
using test_support::ScratchDir;
using test_support::steady_now_s;

/// Connections made and closed, each of which the server logs: far more than a pipe holds.
constexpr int kLoggedConnections = 1500;

TEST(MoosdbLiteStalledStderr, AServerWhoseStandardErrorNobodyReadsKeepsServingAndStops) {
  const ScratchDir dir;
  const std::string fifo = (dir / "stalled").string();
  const std::string port_file = (dir / "port").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Descriptor 3 holds the FIFO open for reading and is never read: standard error fills up.
  const std::string command = "exec 3<>" + fifo + " 2>" + fifo + " && exec " + MOOSDB_LITE_PATH +
                              " --moos_port=0 --moos_timeout=60 --port-file=" + port_file;
  auto child = Child::spawn("/bin/sh", {"-c", command});
  ASSERT_TRUE(child);
  const int port = test_support::wait_for_port_file(port_file, 10.0);
  ASSERT_GT(port, 0);

  for (int i = 0; i < kLoggedConnections; ++i) {
    RawClient passer;
    ASSERT_TRUE(passer.join(port, "pPasser" + std::to_string(i), false))
        << "connection " << i << " was not served";
  }
  RawClient last;
  ASSERT_TRUE(last.join(port, "pLast", false));
  EXPECT_TRUE(last.exchange({null_message("pLast")})) << "a client lost service";

  const double stop_start = steady_now_s();
  EXPECT_EQ(child->stop(10.0), 0) << "the server did not stop cleanly at SIGTERM";
  EXPECT_LT(steady_now_s() - stop_start, 5.0);
}

}  // namespace
}  // namespace moosdb_lite::test
