// moosdb-lite's --log when the log cannot take what comes: a FIFO whose reader never reads (the
// server keeps serving every client and stops promptly at SIGTERM) and a full disk (a file size
// limit, RLIMIT_FSIZE: no privileges needed). The log holds whole records and the exit status
// says it is not whole (3).

#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <sstream>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "moos/alog.hpp"
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

/// main.cpp's exit code for a log that is not whole.
constexpr int kExitLogNotWhole = 3;
/// Postings of kValueBytes each: 2 MB, far more than a pipe holds.
constexpr int kRounds = 40;
constexpr int kPerRound = 50;
constexpr std::size_t kValueBytes = 1000;

/// Posts kRounds x kPerRound NOTIFYs as `name`: false if the server stopped answering.
bool post_a_lot(int port, const std::string& name) {
  RawClient poster;
  if (!poster.join(port, name, false)) return false;
  for (int round = 0; round < kRounds; ++round) {
    std::vector<moos::Message> packet;
    for (int i = 0; i < kPerRound; ++i)
      packet.push_back(notify_string("BULK_" + std::to_string(i), std::string(kValueBytes, 'v'), name,
                                     moos_now()));
    if (!poster.exchange(packet)) return false;
  }
  return true;
}

/// Every complete line of `text` is a header, a gap marker or an entry; it ends with a newline.
void expect_whole_lines(const std::string& text) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    EXPECT_NE(moos::parse_alog_line(line).kind, moos::AlogLineKind::kMalformed) << line.substr(0, 80);
  EXPECT_TRUE(text.empty() || text.back() == '\n') << "the log ends inside a line";
}

/// moosdb-lite on a free port with `args`; 0 when it did not come up.
int start_server(std::optional<Child>& server, const ScratchDir& dir,
                 const std::vector<std::string>& args, const test_support::SpawnOptions& options = {}) {
  const std::string port_file = (dir / "port").string();
  std::vector<std::string> all = {"--moos_port=0", "--port-file=" + port_file};
  all.insert(all.end(), args.begin(), args.end());
  server = Child::spawn(MOOSDB_LITE_PATH, all, options);
  return server ? test_support::wait_for_port_file(port_file, 10.0) : 0;
}

TEST(MoosdbLiteLogFaults, ALogFifoNobodyReadsNeverStopsTheServerAndSigtermEndsItPromptly) {
  const ScratchDir dir;
  const std::string fifo = (dir / "log.fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // A reader that never reads (this process; not inherited by the server).
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  ASSERT_GE(reader, 0);
  std::optional<Child> server;
  const int port = start_server(server, dir, {"--log=" + fifo});
  ASSERT_GT(port, 0) << (server ? server->stderr_text() : "");

  ASSERT_TRUE(post_a_lot(port, "pPoster")) << "the server stopped serving while its log stalled";
  RawClient other;
  ASSERT_TRUE(other.join(port, "pOther", false)) << "a new client was not served";
  EXPECT_TRUE(other.exchange({null_message("pOther")})) << "a client lost service";

  const double stop_start = steady_now_s();
  EXPECT_EQ(server->stop(10.0), kExitLogNotWhole) << server->stderr_text();
  EXPECT_LT(steady_now_s() - stop_start, 5.0) << "SIGTERM did not end the server promptly";
  EXPECT_NE(server->stderr_text().find("is not whole"), std::string::npos) << server->stderr_text();

  // What the FIFO holds: the header and whole records only.
  std::string text;
  char buffer[65536];
  for (ssize_t n = 0; (n = ::read(reader, buffer, sizeof buffer)) > 0;)
    text.append(buffer, static_cast<std::size_t>(n));
  ::close(reader);
  EXPECT_EQ(text.rfind("%% LOG FILE:", 0), 0u);
  expect_whole_lines(text);
}

TEST(MoosdbLiteLogFaults, AFullDiskLeavesWholeRecordsAndTheExitStatusSaysTheLogIsNotWhole) {
  const ScratchDir dir;
  const std::string log = (dir / "full.alog").string();
  test_support::SpawnOptions options;
  options.max_file_bytes = 64 * 1024;  // "the disk"
  std::optional<Child> server;
  const int port = start_server(server, dir, {"--log=" + log}, options);
  ASSERT_GT(port, 0) << (server ? server->stderr_text() : "");
  ASSERT_TRUE(post_a_lot(port, "pPoster")) << "the server stopped serving when its disk filled";
  EXPECT_EQ(server->stop(10.0), kExitLogNotWhole) << server->stderr_text();
  const std::string err = server->stderr_text();
  EXPECT_NE(err.find("File too large"), std::string::npos) << err;
  EXPECT_NE(err.find("records lost"), std::string::npos) << err;
  expect_whole_lines(test_support::read_file(log));
}

}  // namespace
}  // namespace moosdb_lite::test
