// pLogLite, the binary, when its log cannot be written as it runs: a full disk (a file size
// limit, RLIMIT_FSIZE, lifted later with prlimit: no privileges needed) and a log folder
// deleted while it is written. The log stays whole records, says what it is missing with a gap
// marker, and the exit status says the log is not whole (kExitLogNotWhole). A FIFO whose reader
// leaves: the logger keeps serving and counts what it could not write.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <sstream>
#include <string>
#include <thread>

#include "child_process.hpp"
#include "moos/alog.hpp"
#include "moos/alog_file.hpp"
#include "moosdb_server.hpp"
#include "scratch_files.hpp"

namespace plog_lite {
namespace {

using test_support::Child;
using test_support::MoosdbServer;
using test_support::run_program;
using test_support::steady_now_s;

/// kExitLogNotWhole (LogLite.hpp; the test links only the binary).
constexpr int kExitLogNotWhole = 3;
/// How long something the logger does by itself may take on a loaded machine.
constexpr double kPatience_s = 15.0;

/// The log's lines: each must be a header, a gap marker or an entry.
struct Lines {
  std::uint64_t gap_lost = 0;
  int gaps = 0;
  int logstarts = 0;
  std::vector<std::string> variables;
};

Lines read_lines(const std::string& text) {
  Lines out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const auto p = moos::parse_alog_line(line);
    EXPECT_NE(p.kind, moos::AlogLineKind::kMalformed) << "'" << line << "'";
    if (const auto lost = moos::alog_gap_count(line)) {
      out.gap_lost += *lost;
      ++out.gaps;
    }
    if (moos::alog_logstart(line)) ++out.logstarts;
    if (p.kind == moos::AlogLineKind::kEntry) out.variables.push_back(p.entry.variable);
  }
  EXPECT_TRUE(text.empty() || text.back() == '\n') << "the log ends inside a line";
  return out;
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

class LoggerFaults : public ::testing::Test {
 protected:
  std::string log_path() const { return (dir_ / "logs" / "plog.alog").string(); }

  /// Starts pLogLite logging every variable to log_path(); true once it is connected.
  bool start_logger(const test_support::SpawnOptions& options = {}) {
    test_support::write_file(dir_ / "m.moos",
                             "ServerHost = localhost\nServerPort = " + std::to_string(server_.port()) +
                                 "\nCommunity = logtest\n\nProcessConfig = pLogLite\n{\n  path = " +
                                 (dir_ / "logs").string() +
                                 "\n  file = plog\n  file_timestamp = false\n  wildcard_logging = true\n}\n");
    logger_ = Child::spawn(PLOGLITE_PATH, {(dir_ / "m.moos").string()}, options);
    if (!logger_) return false;
    const double give_up = steady_now_s() + kPatience_s;
    while (steady_now_s() < give_up) {
      const auto watch = run_program(MOOS_CLI_PATH,
                                     {"watch", "--port=" + std::to_string(server_.port()),
                                      "--count=1", "--timeout=2", "DB_CLIENTS"},
                                     5.0);
      if (watch.out.find("pLogLite") != std::string::npos) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
  }

  bool poke(const std::vector<std::string>& assignments) {
    std::vector<std::string> args = {"poke", "--port=" + std::to_string(server_.port()),
                                     "--name=poker"};
    args.insert(args.end(), assignments.begin(), assignments.end());
    return run_program(MOOS_CLI_PATH, args, 10.0).exit_code == 0;
  }

  /// Pokes `variable` until the log holds it (the logger may drop the first ones while it
  /// waits to retry): true once it does.
  bool poke_until_logged(const std::string& variable) {
    const double give_up = steady_now_s() + kPatience_s;
    while (steady_now_s() < give_up) {
      poke({variable + "=1"});
      std::this_thread::sleep_for(std::chrono::milliseconds(300));
      std::error_code ignored;
      if (std::filesystem::exists(log_path(), ignored) &&
          test_support::read_file(log_path()).find(variable) != std::string::npos)
        return true;
    }
    return false;
  }

  bool wait_for_stderr(const std::string& fragment) {
    const double give_up = steady_now_s() + kPatience_s;
    while (steady_now_s() < give_up) {
      if (logger_->stderr_text().find(fragment) != std::string::npos) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
  }

  test_support::ScratchDir dir_{"ploglite_faults"};
  MoosdbServer server_{MOOSDB_LITE_PATH, {"--moos_community=logtest"}};
  std::optional<Child> logger_;
};

TEST_F(LoggerFaults, AFullDiskLeavesWholeRecordsAndAGapMarkerAndTheExitStatusSaysSo) {
  ASSERT_TRUE(server_.ok());
  test_support::SpawnOptions options;
  options.max_file_bytes = 16 * 1024;  // "the disk": room for the header and a little more
  ASSERT_TRUE(start_logger(options)) << (logger_ ? logger_->stderr_text() : "");
  // 40 kB of postings: the log fills up in the middle of them.
  std::vector<std::string> big;
  for (int i = 0; i < 100; ++i) big.push_back("FILL_" + std::to_string(i) + "=" + std::string(400, 'x'));
  ASSERT_TRUE(poke(big));
  ASSERT_TRUE(wait_for_stderr("File too large")) << logger_->stderr_text();

  rlimit limit{};  // the disk has room again
  ASSERT_EQ(::prlimit(logger_->pid(), RLIMIT_FSIZE, nullptr, &limit), 0);
  limit.rlim_cur = limit.rlim_max;
  ASSERT_EQ(::prlimit(logger_->pid(), RLIMIT_FSIZE, &limit, nullptr), 0);
  ASSERT_TRUE(poke_until_logged("AFTER_FULL")) << logger_->stderr_text();
  ASSERT_TRUE(wait_for_stderr("writing again")) << logger_->stderr_text();

  EXPECT_EQ(logger_->stop(), kExitLogNotWhole) << logger_->stderr_text();
  const std::string err = logger_->stderr_text();
  EXPECT_NE(err.find("records lost"), std::string::npos) << err;
  const Lines lines = read_lines(test_support::read_file(log_path()));
  EXPECT_GE(lines.gaps, 1);
  EXPECT_GT(lines.gap_lost, 0u);
  EXPECT_TRUE(contains(lines.variables, "AFTER_FULL"));
  EXPECT_FALSE(contains(lines.variables, "FILL_99")) << "the last postings cannot have fit";
}

TEST_F(LoggerFaults, ALogFolderDeletedWhileLoggingIsCreatedAgainWithAHeaderAndAGapMarker) {
  ASSERT_TRUE(server_.ok());
  ASSERT_TRUE(start_logger()) << (logger_ ? logger_->stderr_text() : "");
  ASSERT_TRUE(poke_until_logged("BEFORE_DELETE"));
  std::filesystem::remove_all(dir_ / "logs");
  ASSERT_TRUE(poke_until_logged("AFTER_DELETE")) << logger_->stderr_text();
  ASSERT_TRUE(wait_for_stderr("deleted")) << logger_->stderr_text();

  EXPECT_EQ(logger_->stop(), kExitLogNotWhole) << logger_->stderr_text();
  const Lines lines = read_lines(test_support::read_file(log_path()));
  EXPECT_EQ(lines.logstarts, 1);
  EXPECT_EQ(lines.gaps, 1);
  EXPECT_GT(lines.gap_lost, 0u);
  EXPECT_FALSE(contains(lines.variables, "BEFORE_DELETE"));
  EXPECT_TRUE(contains(lines.variables, "AFTER_DELETE"));
}

TEST_F(LoggerFaults, AFifoWhoseReaderLeavesKeepsTheLoggerServingAndCountsTheLostRecords) {
  ASSERT_TRUE(server_.ok());
  std::filesystem::create_directories(dir_ / "logs");
  ASSERT_EQ(::mkfifo(log_path().c_str(), 0600), 0);
  // The reader is there first: the logger opens the FIFO without waiting for one.
  // O_CLOEXEC: a child holding the read end too would keep the pipe whole.
  const int reader = ::open(log_path().c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  ASSERT_GE(reader, 0);
  ASSERT_TRUE(start_logger()) << (logger_ ? logger_->stderr_text() : "");
  // The log's header arrives: the logger has the FIFO open.
  char header[4096];
  bool got_header = false;
  for (const double until = steady_now_s() + kPatience_s; !got_header && steady_now_s() < until;) {
    got_header = ::read(reader, header, sizeof header) > 0;
    if (!got_header) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ::close(reader);  // the reader leaves; every later write meets a broken pipe
  ASSERT_TRUE(got_header) << logger_->stderr_text();

  const double give_up = steady_now_s() + kPatience_s;
  while (steady_now_s() < give_up && logger_->stderr_text().find("Broken pipe") == std::string::npos) {
    poke({"AFTER_READER=1"});
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  EXPECT_NE(logger_->stderr_text().find("Broken pipe"), std::string::npos) << logger_->stderr_text();
  ASSERT_TRUE(logger_->running()) << "the logger ended: " << logger_->stderr_text();
  // Still serving its community: a client sees it connected.
  const auto watch = run_program(MOOS_CLI_PATH,
                                 {"watch", "--port=" + std::to_string(server_.port()), "--count=1",
                                  "--timeout=2", "DB_CLIENTS"},
                                 5.0);
  EXPECT_NE(watch.out.find("pLogLite"), std::string::npos) << watch.out;

  EXPECT_EQ(logger_->stop(), kExitLogNotWhole) << logger_->stderr_text();
  EXPECT_NE(logger_->stderr_text().find("records lost"), std::string::npos)
      << logger_->stderr_text();
}

}  // namespace
}  // namespace plog_lite
