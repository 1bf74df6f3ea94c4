// moos::AlogFile, a .alog written while a program runs: whole records, never a wait, and a gap
// marker where records are missing (a file size limit as an unprivileged full disk, a FIFO
// whose reader stalls, a folder deleted while it is written), and times that cannot be placed.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "moos/alog.hpp"
#include "child_process.hpp"
#include "moos/alog_file.hpp"
#include "scratch_files.hpp"
#include "wire_messages.hpp"

namespace moos {
namespace {

using test::kT0;
using test::notify_double;
using test_support::ScratchDir;

/// What a log holds, line by line: every line must be a header, a gap marker or an entry.
struct LogLines {
  std::vector<AlogEntry> entries;
  std::vector<std::uint64_t> gaps;  ///< the counts of the gap markers, in order
  std::vector<std::string> kinds;   ///< "header", "gap" or "entry", in order
  std::vector<double> logstarts;
};

LogLines read_log(const std::string& text) {
  LogLines out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const AlogParse p = parse_alog_line(line);
    EXPECT_NE(p.kind, AlogLineKind::kMalformed) << "'" << line << "'";
    EXPECT_NE(p.kind, AlogLineKind::kBlank) << "a blank line";
    if (const auto gap = alog_gap_count(line)) {
      out.gaps.push_back(*gap);
      out.kinds.push_back("gap");
    } else if (p.kind == AlogLineKind::kEntry) {
      out.entries.push_back(p.entry);
      out.kinds.push_back("entry");
    } else {
      if (const auto start = alog_logstart(line)) out.logstarts.push_back(*start);
      out.kinds.push_back("header");
    }
  }
  EXPECT_TRUE(text.empty() || text.back() == '\n') << "the file ends inside a line";
  return out;
}

/// A record of exactly kRecordBytes bytes (its value pads it).
constexpr std::size_t kRecordBytes = 100;
std::string record(int n) {
  std::string line = format_alog_line({1.0 + n, "X", "p", std::to_string(n)});
  line.insert(line.size() - 1, kRecordBytes - line.size(), '.');
  return line;
}

struct Notices {
  std::vector<std::string> lines;
  AlogFileOptions options(double retry_s = 0.0) {
    AlogFileOptions o;
    o.retry_interval_s = retry_s;
    o.notice = [this](const std::string& text) { lines.push_back(text); };
    return o;
  }
  bool any(const std::string& fragment) const {
    for (const auto& l : lines)
      if (l.find(fragment) != std::string::npos) return true;
    return false;
  }
};

TEST(AlogGapMarker, IsACommentLineReadersSkipWithItsCount) {
  const std::string line = format_alog_gap(1234, "write failed: No space left on device");
  EXPECT_EQ(line, "%% GAP: 1234 records lost (write failed: No space left on device)\n");
  EXPECT_EQ(parse_alog_line(line.substr(0, line.size() - 1)).kind, AlogLineKind::kHeader);
  EXPECT_EQ(alog_gap_count(line), 1234u);
  EXPECT_EQ(format_alog_gap(1, "x\ny"), "%% GAP: 1 record lost (x y)\n");
  EXPECT_FALSE(alog_gap_count("%% LOGSTART 1700000000.000"));
  EXPECT_FALSE(alog_gap_count("1.000 GAP X 3"));
}

TEST(AlogFileTimes, NonFiniteAndAbsurdTimesAreLoggedAtTheWritersClockCountedAndWarnedOnce) {
  const ScratchDir dir;
  Notices notices;
  std::string problem;
  auto log = AlogFile::open((dir / "t.alog").string(), kT0, notices.options(), problem);
  ASSERT_TRUE(log) << problem;
  const double now = kT0 + 10.0;
  const double inf = std::numeric_limits<double>::infinity();
  for (const double bad : {std::nan(""), inf, -inf, 1e300, now + 2 * kAlogMaxClockSkew_s,
                           now - 2 * kAlogMaxClockSkew_s}) {
    log->add(notify_double("BAD", 1.0, "p", bad), now);
  }
  log->add(notify_double("GOOD", 1.0, "p", now - 3600.0), now);
  log->add(notify_double("OLD", 1.0, "p", now - 1e8), now);  // years off, yet a clock's time
  log->pump();
  EXPECT_EQ(log->times_clamped(), 6u);
  ASSERT_TRUE(log->close(problem)) << problem;
  const LogLines lines = read_log(test_support::read_file(dir / "t.alog"));
  ASSERT_EQ(lines.entries.size(), 8u);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(lines.entries[i].time_s, 10.0) << i;
  EXPECT_EQ(lines.entries[6].time_s, 10.0 - 3600.0);
  EXPECT_EQ(lines.entries[7].time_s, 10.0 - 1e8);
  ASSERT_EQ(notices.lines.size(), 1u);
  EXPECT_NE(notices.lines[0].find("BAD"), std::string::npos) << notices.lines[0];
}

/// The soft file size limit of this process, set for one test and put back after it.
class FileSizeLimit {
 public:
  FileSizeLimit() {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    old_handler_ = std::signal(SIGXFSZ, SIG_IGN);  // writes past it fail with EFBIG
  }
  ~FileSizeLimit() {
    lift();
    std::signal(SIGXFSZ, old_handler_);
  }
  bool set(std::uintmax_t bytes) {
    rlimit limit = saved_;
    limit.rlim_cur = static_cast<rlim_t>(bytes);
    return ::setrlimit(RLIMIT_FSIZE, &limit) == 0;
  }
  void lift() { ::setrlimit(RLIMIT_FSIZE, &saved_); }

 private:
  rlimit saved_{};
  void (*old_handler_)(int) = SIG_DFL;
};

TEST(AlogFileFull, ARecordCutShortIsTakenBackAndAGapMarkerCountsTheLostWhenWritingResumes) {
  const ScratchDir dir;
  const std::string path = (dir / "full.alog").string();
  Notices notices;
  std::string problem;
  auto log = AlogFile::open(path, kT0, notices.options(), problem);
  ASSERT_TRUE(log) << problem;
  const auto header_bytes = std::filesystem::file_size(path);
  FileSizeLimit limit;
  // Room for two records and half of the third: the third is cut short by the "full disk".
  ASSERT_TRUE(limit.set(header_bytes + 2 * kRecordBytes + kRecordBytes / 2));
  for (int i = 0; i < 10; ++i) log->add_line(record(i));
  log->pump();
  EXPECT_EQ(std::filesystem::file_size(path), header_bytes + 2 * kRecordBytes)
      << "the file does not end on a record boundary";
  EXPECT_EQ(log->records_written(), 2u);
  EXPECT_EQ(log->records_lost(), 8u);
  EXPECT_TRUE(notices.any("File too large")) << ::testing::PrintToString(notices.lines);

  limit.lift();
  log->pump();  // the retry: the gap marker first
  for (int i = 10; i < 13; ++i) log->add_line(record(i));
  log->pump();
  EXPECT_TRUE(notices.any("writing again"));
  EXPECT_FALSE(log->close(problem));
  EXPECT_NE(problem.find("8 records lost"), std::string::npos) << problem;

  const LogLines lines = read_log(test_support::read_file(path));
  EXPECT_EQ(lines.gaps, std::vector<std::uint64_t>{8});
  const std::vector<std::string> kinds = {"header", "header", "header", "entry", "entry", "gap",
                                          "entry",  "entry",  "entry"};
  EXPECT_EQ(lines.kinds, kinds);
  ASSERT_EQ(lines.entries.size(), 5u);
  EXPECT_EQ(lines.entries[2].value.substr(0, 2), "10");
}

/// A FIFO in `dir` with a reader that reads only when asked.
class StalledFifo {
 public:
  explicit StalledFifo(const ScratchDir& dir) : path_((dir / "fifo.alog").string()) {
    ::mkfifo(path_.c_str(), 0600);
    reader_ = ::open(path_.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  }
  ~StalledFifo() {
    if (reader_ >= 0) ::close(reader_);
  }
  bool ok() const { return reader_ >= 0; }
  const std::string& path() const { return path_; }
  /// Everything the FIFO holds now.
  std::string read_now() {
    std::string out;
    char buffer[65536];
    ssize_t n = 0;
    while ((n = ::read(reader_, buffer, sizeof buffer)) > 0)
      out.append(buffer, static_cast<std::size_t>(n));
    return out;
  }

 private:
  std::string path_;
  int reader_ = -1;
};

TEST(AlogFileFifo, AStalledReaderNeverBlocksTheWriterAndWhatDidNotFitIsCountedAndMarked) {
  const ScratchDir dir;
  StalledFifo fifo(dir);
  ASSERT_TRUE(fifo.ok());
  Notices notices;
  AlogFileOptions options = notices.options();
  options.max_queued_bytes = 50 * kRecordBytes;
  std::string problem;
  auto log = AlogFile::open(fifo.path(), kT0, options, problem);
  ASSERT_TRUE(log) << problem;
  constexpr int kRecords = 5000;  // 500 kB: far more than a pipe and the queue hold
  for (int i = 0; i < kRecords; ++i) {
    log->add_line(record(i));
    if (i % 100 == 0) log->pump();  // (returns at once: this test would hang otherwise)
  }
  EXPECT_GT(log->records_lost(), 0u);
  EXPECT_LE(log->queued_bytes(), options.max_queued_bytes);
  EXPECT_TRUE(notices.any("more slowly than they come")) << ::testing::PrintToString(notices.lines);

  std::string text;
  for (int round = 0; round < 100 && log->queued_bytes() > 0; ++round) {
    text += fifo.read_now();
    log->pump();
  }
  log->add_line(record(kRecords));
  log->pump();
  text += fifo.read_now();
  const LogLines lines = read_log(text);
  // A gap marker wherever records are missing (one per run of drops), counting them all.
  ASSERT_FALSE(lines.gaps.empty());
  EXPECT_EQ(std::accumulate(lines.gaps.begin(), lines.gaps.end(), std::uint64_t{0}),
            log->records_lost());
  EXPECT_EQ(lines.entries.size(), log->records_written());
  EXPECT_EQ(log->records_written() + log->records_lost(), kRecords + 1u);
  EXPECT_EQ(lines.kinds.back(), "entry");
}

TEST(AlogFileFifo, CloseWaitsForAStalledReaderOnlyBrieflyAndCountsWhatIsLeft) {
  const ScratchDir dir;
  StalledFifo fifo(dir);
  ASSERT_TRUE(fifo.ok());
  AlogFileOptions options;
  options.close_wait_s = 0.2;
  std::string problem;
  auto log = AlogFile::open(fifo.path(), kT0, options, problem);
  ASSERT_TRUE(log) << problem;
  for (int i = 0; i < 2000; ++i) log->add_line(record(i));
  log->pump();
  const double start = test_support::steady_now_s();
  EXPECT_FALSE(log->close(problem));
  EXPECT_LT(test_support::steady_now_s() - start, 2.0);
  EXPECT_GT(log->records_lost(), 0u);
  EXPECT_EQ(log->records_written() + log->records_lost(), 2000u);
  EXPECT_NE(problem.find("not taken before the program ended"), std::string::npos) << problem;
}

TEST(AlogFileDeleted, AFolderDeletedWhileLoggingIsCreatedAgainWithItsHeaderAndAGapMarker) {
  const ScratchDir dir;
  const auto folder = dir / "logs";
  std::filesystem::create_directories(folder);
  const std::string path = (folder / "run.alog").string();
  Notices notices;
  std::string problem;
  auto log = AlogFile::open(path, kT0, notices.options(), problem);
  ASSERT_TRUE(log) << problem;
  for (int i = 0; i < 3; ++i) log->add_line(record(i));
  log->pump();
  std::filesystem::remove_all(folder);
  for (int i = 3; i < 5; ++i) log->add_line(record(i));
  log->pump();
  EXPECT_EQ(log->reopened(), 1u);
  EXPECT_EQ(log->records_lost(), 3u);
  EXPECT_TRUE(notices.any("deleted")) << ::testing::PrintToString(notices.lines);
  EXPECT_FALSE(log->close(problem));

  const LogLines lines = read_log(test_support::read_file(path));
  EXPECT_EQ(lines.logstarts, std::vector<double>{kT0});
  EXPECT_EQ(lines.gaps, std::vector<std::uint64_t>{3});
  ASSERT_EQ(lines.entries.size(), 2u);
  EXPECT_EQ(lines.entries[0].value.substr(0, 1), "3");
}

}  // namespace
}  // namespace moos
