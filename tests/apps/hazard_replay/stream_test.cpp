// hazard_replay on hostile logs and configurations: times no clock wrote, a log larger than its
// memory through a FIFO, and a line of a million unknown keys. Each run goes on, with a bounded
// number of warnings and memory bounded independently of the input's size.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>

#include <algorithm>
#include <filesystem>
#include <string>
#include <thread>

#include "input_log.hpp"
#include "replay_support.hpp"
#include "text_count.hpp"

namespace hazard_replay {
namespace {

using test_support::alog_entries;
using test_support::count_of;
using test_support::ScratchDir;
using test_support::write_file;
using testing::alog;
using testing::Line;
using testing::mission;
using testing::node_report;
using testing::run;

const char* kBlock =
    "  AppTick = 4\n"
    "  sensor_config = width=25, exp=4, pclass=0.8\n"
    "  hazard = x=0,y=0,label=a,type=hazard\n"
    "  show_hazards = false\n";

std::vector<Line> small_input() {
  return {{0.0, "UHZ_SENSOR_REQUEST", "vname=v1"},
          {0.5, "NODE_REPORT", node_report("v1", 0, -10)},
          {2.0, "NODE_REPORT", node_report("v1", 0, 0)},
          {4.0, "NODE_REPORT", node_report("v1", 0, 10)}};
}

// The largest resident size of the children waited for, in kB (each test runs in its own
// process, and runs one big child).
long peak_child_kb() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  return usage.ru_maxrss;
}

#if defined(__SANITIZE_ADDRESS__)
// ASan's shadow memory and quarantine make resident sizes say nothing: the release run checks
// the bounds, this one the behaviour, on a smaller input.
constexpr bool kMeasureMemory = false;
constexpr std::size_t kScale = 8;
#else
constexpr bool kMeasureMemory = true;
constexpr std::size_t kScale = 1;
#endif

TEST(ReplayStream, UnusableTimesAreSkippedWithOneWarning) {
  ScratchDir dir;
  write_file(dir / "m.moos", mission(kBlock));
  write_file(dir / "in.alog", alog(small_input()));
  std::string text = alog(small_input());
  const std::size_t header_end = text.find("0.000 ");
  text.insert(header_end,
              "nan NODE_REPORT test NAME=v1,X=0,Y=0,SPD=1,HDG=0\n"
              "-inf NODE_REPORT test NAME=v1,X=0,Y=0,SPD=1,HDG=0\n"
              "1e300 NODE_REPORT test NAME=v1,X=0,Y=0,SPD=1,HDG=0\n"
              "%% 12 lines dropped here (writer queue full)\n");
  text += "1e300 UHZ_SENSOR_REQUEST test vname=v1\n";
  write_file(dir / "bad.alog", text);
  const auto r = run(dir, {"m.moos", "bad.alog", "--seed=3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_of(r.err, "unusable times"), 1u) << r.err;
  EXPECT_NE(r.err.find("bad.alog: 4 lines with unusable times (not finite, or beyond 1e10 s) "
                       "skipped"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(count_of(r.err, "bad.alog"), 1u) << r.err;  // no warning a line
  // The usable lines replay as the clean log does.
  const auto clean = run(dir, {"m.moos", "in.alog", "--seed=3"});
  const auto body = [](const std::string& out) { return out.substr(out.find("%% LOGSTART")); };
  ASSERT_NE(clean.out.find("VIEW_POLYGON"), std::string::npos);
  EXPECT_EQ(body(r.out), body(clean.out));
}

// Writes a log of `lines` 1 KB lines (and the small input around them) into the FIFO at `path`
// as it goes, never holding it: the child's peak must not include the test's own memory,
// which a fork copies. (As test_support::write_fifo: waits for the reader, then blocks.)
bool feed_large_log(const std::string& path, std::size_t lines) {
  sigset_t pipe_signal;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_signal, nullptr);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  int fd = -1;
  while ((fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC)) < 0 && errno == ENXIO &&
         std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (fd < 0) return false;
  ::fcntl(fd, F_SETFL, 0);
  bool fed = true;
  std::string chunk = alog(small_input());
  const auto send = [&] {
    for (std::size_t written = 0; fed && written < chunk.size();) {
      const ssize_t n = ::write(fd, chunk.data() + written, chunk.size() - written);
      if (n < 0 && errno == EINTR) continue;
      fed = n > 0;
      written += fed ? static_cast<std::size_t>(n) : 0;
    }
    chunk.clear();
  };
  const std::string filler(1000, 'x');
  for (std::size_t i = 0; i < lines; ++i) {
    chunk += moos::format_alog_line(
        {4.0 + 10.0 * static_cast<double>(i) / static_cast<double>(lines), "UNWATCHED", "test",
         filler});
    if (chunk.size() > (std::size_t{1} << 20)) send();
  }
  chunk += "15.0 NODE_REPORT test " + node_report("v1", 0, 20) + "\n";
  send();
  ::close(fd);
  return fed;
}

// A 100 MB log through a FIFO: read a line at a time, never whole.
TEST(ReplayStream, ALargeLogThroughAFifoIsStreamedInBoundedMemory) {
  ScratchDir dir;
  write_file(dir / "m.moos", mission(kBlock));
  const std::string fifo = (dir / "pipe.alog").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  bool fed = false;
  std::thread writer([&] { fed = feed_large_log(fifo, 100000 / kScale); });  // 100 MB
  const auto r = run(dir, {"m.moos", "pipe.alog", "--seed=3"});
  writer.join();
  EXPECT_TRUE(fed);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto out = alog_entries(r.out);
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.back().time_s, 15.0);  // replayed to the last line
  if (kMeasureMemory) {
    EXPECT_LT(peak_child_kb(), 50 * 1024);
  }
}

// A line over the line bound is skipped and counted; the lines after it replay.
TEST(ReplayStream, ALineOverTheBoundIsSkippedAndCounted) {
  ScratchDir dir;
  write_file(dir / "m.moos", mission(kBlock));
  std::string text = alog(small_input());
  text += "5.0 NODE_REPORT test NAME=v1,X=0,Y=30," + std::string(kMaxInputLineBytes, 'k') + "\n";
  text += "6.0 NODE_REPORT test " + node_report("v1", 0, 40) + "\n";
  write_file(dir / "in.alog", text);
  const auto r = run(dir, {"m.moos", "in.alog", "--seed=3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("in.alog: 1 lines over 1048576 bytes skipped"), std::string::npos) << r.err;
  EXPECT_EQ(alog_entries(r.out).back().time_s, 6.0);
}

// A line of a million unknown keys (a hazard line and a sensor_config of the block, and a hazard
// file's line): eight warnings and a count each, and memory a few times the input's size.
TEST(ReplayStream, AMillionUnknownKeysGiveBoundedWarningsAndMemory) {
  ScratchDir dir;
  const std::size_t count = 1000000 / kScale;
  std::size_t line_bytes = 0;
  {  // (freed before the run: a fork copies the test's memory into the child's peak)
    std::string keys;
    for (std::size_t i = 0; i < count; ++i) keys += ",k" + std::to_string(i) + "=1";
    line_bytes = keys.size();
    write_file(dir / "hazards.txt", "hazard = x=5,y=5,label=f,type=hazard" + keys + "\n");
    write_file(dir / "m.moos",
               mission("  AppTick = 4\n  hazard_file = hazards.txt\n"
                       "  sensor_config = width=25, exp=4, pclass=0.8" + keys + "\n"
                       "  hazard = x=0,y=0,label=a,type=hazard" + keys + "\n"));
  }
  write_file(dir / "in.alog", alog(small_input()));
  const auto r = run(dir, {"m.moos", "in.alog", "--seed=3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_of(r.err, "unknown key"), 3 * base::kMaxWarningsPerLine) << r.err.substr(0, 2000);
  EXPECT_EQ(count_of(r.err, " more warnings on this line"), 3u);
  EXPECT_NE(r.err.find("... and " + std::to_string(count - base::kMaxWarningsPerLine) +
                       " more warnings on this line"),
            std::string::npos);
  EXPECT_LT(r.err.size(), 8192u);
  // The input is three lines of 10 MB (the mission file's two, the hazard file's): the loaders
  // hold them a few times over, the warnings nothing (before the bound: over 1 GB).
  if (kMeasureMemory) {
    EXPECT_LT(peak_child_kb(), 150 * 1024) << line_bytes << "-byte lines";
  }
}

// A usable time far beyond the first input (an epoch time among times since LOGSTART): the line
// is skipped and counted, not the whole run refused for its 4e9 iterations.
TEST(ReplayStream, ALineFarBeyondTheFirstIsSkippedAndTheRunGoesOn) {
  ScratchDir dir;
  write_file(dir / "m.moos", mission(kBlock));
  write_file(dir / "in.alog", alog(small_input()));
  std::vector<Line> far = small_input();
  far.push_back({1.7e9, "NODE_REPORT", node_report("v1", 0, 50)});
  write_file(dir / "far.alog", alog(far));
  const auto r = run(dir, {"m.moos", "far.alog", "--seed=3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("hazard_replay: 1 lines more than 100000000 iterations (25000000 s at "
                       "AppTick) after the first input skipped"),
            std::string::npos)
      << r.err;
  const auto clean = run(dir, {"m.moos", "in.alog", "--seed=3"});
  const auto body = [](const std::string& out) { return out.substr(out.find("%% LOGSTART")); };
  EXPECT_EQ(body(r.out), body(clean.out));
}

// Lines out of order within the reorder window replay as the sorted log does; one out of order
// by more than the window is delivered late, and counted.
TEST(ReplayStream, DisorderIsPutRightWithinTheWindowAndCountedBeyondIt) {
  ScratchDir dir;
  write_file(dir / "m.moos", mission(kBlock));
  write_file(dir / "in.alog", alog(small_input()));
  std::vector<Line> reversed = small_input();
  std::reverse(reversed.begin(), reversed.end());
  write_file(dir / "reversed.alog", alog(reversed));
  const auto sorted = run(dir, {"m.moos", "in.alog", "--seed=3"});
  const auto put_right = run(dir, {"m.moos", "reversed.alog", "--seed=3"});
  ASSERT_EQ(put_right.exit_code, 0) << put_right.err;
  const auto body = [](const std::string& out) { return out.substr(out.find("%% LOGSTART")); };
  EXPECT_EQ(body(put_right.out), body(sorted.out));
  EXPECT_EQ(put_right.err.find("delivered late"), std::string::npos);

  std::vector<Line> beyond = small_input();
  for (std::size_t i = 0; i <= kReorderWindowLines; ++i) beyond.push_back({5.0, "UNWATCHED", "v"});
  beyond.push_back({1.0, "UHZ_SENSOR_REQUEST", "vname=v1"});
  write_file(dir / "beyond.alog", alog(beyond));
  const auto late = run(dir, {"m.moos", "beyond.alog", "--seed=3"});
  ASSERT_EQ(late.exit_code, 0) << late.err;
  EXPECT_NE(late.err.find("beyond.alog: 1 lines out of time order by more than the reorder "
                          "window (10000 lines) delivered late"),
            std::string::npos)
      << late.err;
}

// A log of many malformed lines: the first kMaxWarningsPerKind are printed, the rest counted.
TEST(ReplayStream, MalformedLinesAreWarnedOfUpToTheBoundThenCounted) {
  ScratchDir dir;
  write_file(dir / "m.moos", mission(kBlock));
  std::string text = alog(small_input());
  for (int i = 0; i < 5000; ++i) text += "bad-time X test v\n";
  write_file(dir / "in.alog", text);
  const auto r = run(dir, {"m.moos", "in.alog", "--seed=3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_of(r.err, "warning: time 'bad-time'"), 100u);
  EXPECT_NE(r.err.find("in.alog: ... and 4900 more malformed lines skipped (not printed)"),
            std::string::npos)
      << r.err.substr(r.err.size() - 500);
}

}  // namespace
}  // namespace hazard_replay
