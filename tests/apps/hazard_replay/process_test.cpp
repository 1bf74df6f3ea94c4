// The hazard_replay binary: bad input, reproducibility, seeds, --until, --alias, --output.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <set>
#include <thread>

#include "scenario/reference_scenario.hpp"
#include "base/text.hpp"
#include "fifo_writer.hpp"
#include "replay_support.hpp"

namespace hazard_replay {
namespace {

using test_support::alog_entries;
using test_support::read_file;
using test_support::ScratchDir;
using test_support::write_file;
using testing::alog;
using testing::Line;
using testing::mission;
using testing::node_report;
using testing::run;

const char* kBlock =
    "  AppTick = 4\n"
    "  hazard_file = fields/hazards.txt\n"
    "  sensor_config = width=25, exp=4, pclass=0.8\n"
    "  show_hazards = false\n"
    "  min_classify_interval = 2\n";

const char* kHazards =
    "// test field\n"
    "hazard = x=0,y=0,label=a,type=hazard\n"
    "hazard = x=3,y=1,label=b,type=benign\n"
    "hazard = x=-5,y=-1,label=c,type=benign,hr=0.6\n";

std::vector<Line> small_input() {
  return {{0.0, "UHZ_SENSOR_REQUEST", "vname=v1"},
          {0.5, "NODE_REPORT", node_report("v1", 0, -100)},
          {2.0, "NODE_REPORT", node_report("v1", 0, 0)},
          {3.0, "UHZ_CLASSIFY_REQUEST", "vname=v1,label=a"},
          {3.0, "UHZ_CLASSIFY_REQUEST", "vname=v1,label=b"},
          {9.0, "NODE_REPORT", node_report("v1", 0, 100)}};
}

// A mission folder: m.moos beside fields/hazards.txt, and in.alog.
void make_mission(const ScratchDir& dir, const std::string& block = kBlock) {
  std::filesystem::create_directories(dir / "fields");
  write_file(dir / "m.moos", mission(block));
  write_file(dir / "fields/hazards.txt", kHazards);
  write_file(dir / "in.alog", alog(small_input()));
}

TEST(ReplayProcess, HelpExitsZero) {
  ScratchDir dir;
  const auto r = run(dir, {"--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("Usage: hazard_replay CONFIG.moos INPUT.alog"), std::string::npos);
}

TEST(ReplayProcess, BadOptionExitsTwoNamingIt) {
  ScratchDir dir;
  make_mission(dir);
  const auto r = run(dir, {"m.moos", "in.alog", "--seed=many"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("'--seed=many'"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
}

TEST(ReplayProcess, MissingFilesAndBlockExitOneNamingThem) {
  ScratchDir dir;
  make_mission(dir);
  auto r = run(dir, {"nope.moos", "in.alog"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("cannot read mission file 'nope.moos'"), std::string::npos) << r.err;
  r = run(dir, {"m.moos", "missing.alog"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("cannot read input log 'missing.alog'"), std::string::npos) << r.err;
  r = run(dir, {"m.moos", "in.alog", "--alias=pOther"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("no 'ProcessConfig = pOther' block in 'm.moos'"), std::string::npos);
  r = run(dir, {"m.moos", "in.alog", "--output=no/such/folder/out.alog"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--output: cannot write 'no/such/folder/out.alog'"), std::string::npos)
      << r.err;
}

TEST(ReplayProcess, ALogThatIsNoFileOrPipeIsRefusedWithTheReason) {
  ScratchDir dir;
  make_mission(dir);
  auto r = run(dir, {"m.moos", "/dev/zero"});  // would be read until memory ran out
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("cannot read input log '/dev/zero': is a device, not a regular file"),
            std::string::npos)
      << r.err;
  r = run(dir, {"m.moos", "fields"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("cannot read input log 'fields': is a directory"), std::string::npos)
      << r.err;
}

// A regular log is mapped, a pipe is read to its end: the same replay either way.
TEST(ReplayProcess, ALogFromAPipeReplaysAsTheFileDoes) {
  ScratchDir dir;
  make_mission(dir);
  const std::string fifo = (dir / "pipe.alog").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string log = alog(small_input());
  bool fed = false;
  std::thread writer([&] { fed = test_support::write_fifo(fifo, log); });
  const auto piped = run(dir, {"m.moos", "pipe.alog", "--seed=3"});
  writer.join();
  EXPECT_TRUE(fed);
  const auto mapped = run(dir, {"m.moos", "in.alog", "--seed=3"});
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  ASSERT_EQ(mapped.exit_code, 0) << mapped.err;
  const auto body = [](const std::string& out) { return out.substr(out.find("%% LOGSTART")); };
  ASSERT_NE(mapped.out.find("VIEW_POLYGON"), std::string::npos);
  EXPECT_EQ(body(piped.out), body(mapped.out));  // (the header names the input file)
}

TEST(ReplayProcess, ReplaysMailAndIterationsInTimeOrder) {
  ScratchDir dir;
  make_mission(dir);
  const auto r = run(dir, {"m.moos", "in.alog", "--seed=3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto out = alog_entries(r.out);
  ASSERT_FALSE(out.empty());
  double last = -1;
  int polygons = 0;
  for (const auto& e : out) {
    EXPECT_GE(e.time_s, last);
    last = e.time_s;
    EXPECT_EQ(e.source, "uFldHazardSensor");
    polygons += e.variable == "VIEW_POLYGON";
  }
  EXPECT_EQ(out.front().variable, "UHZ_OPTIONS_SUMMARY");
  EXPECT_EQ(out.front().time_s, 0.0);
  EXPECT_LE(last, 9.0);
  // Iterations at 4 Hz from 0.5 (the first pose) to 9.0 inclusive: 35 swaths.
  EXPECT_EQ(polygons, 35);
  // The first classification answer comes at the iteration of the request (D9).
  bool answered = false;
  for (const auto& e : out) {
    if (e.variable == "UHZ_HAZARD_REPORT_V1" && !answered) {
      answered = true;
      EXPECT_EQ(e.time_s, 3.0);
    }
  }
  EXPECT_TRUE(answered);
  EXPECT_NE(r.err.find("hazard_replay: seed 3 (command line), AppTick 4 Hz"), std::string::npos);
  EXPECT_NE(r.out.find("%% LOGSTART           1700000000.000"), std::string::npos);
}

TEST(ReplayProcess, SameInputsAndSeedSameBytes) {
  ScratchDir dir;
  make_mission(dir);
  const auto a = run(dir, {"m.moos", "in.alog", "--seed=11"});
  const auto b = run(dir, {"m.moos", "in.alog", "--seed=11"});
  ASSERT_EQ(a.exit_code, 0);
  EXPECT_EQ(a.out, b.out);
  const auto c = run(dir, {"m.moos", "in.alog", "--seed=11", "--output=out.alog"});
  ASSERT_EQ(c.exit_code, 0);
  EXPECT_TRUE(c.out.empty());
  EXPECT_EQ(read_file(dir / "out.alog"), a.out);
}

TEST(ReplayProcess, SeedPrecedence_Rulings) {
  ScratchDir dir;
  make_mission(dir, std::string(kBlock) + "  random_seed = 5\n  seed_random = true\n");
  auto r = run(dir, {"m.moos", "in.alog"});
  EXPECT_NE(r.err.find("seed 5 (random_seed)"), std::string::npos) << r.err;
  const auto with_config_seed = r.out;
  r = run(dir, {"m.moos", "in.alog", "--seed=5"});
  EXPECT_NE(r.err.find("seed 5 (command line)"), std::string::npos);
  EXPECT_EQ(r.out, with_config_seed);
  make_mission(dir, std::string(kBlock) + "  seed_random = false\n");
  r = run(dir, {"m.moos", "in.alog"});
  EXPECT_NE(r.err.find("seed 1 (seed_random = false)"), std::string::npos) << r.err;
  make_mission(dir);
  r = run(dir, {"m.moos", "in.alog"});
  EXPECT_NE(r.err.find("(operating system)"), std::string::npos) << r.err;
}

TEST(ReplayProcess, MalformedLogLinesAreSkippedWithFileAndLine) {
  ScratchDir dir;
  make_mission(dir);
  std::string text = alog(small_input());
  text += "not-a-time NODE_REPORT x NAME=v1\n";        // line 10
  text += "12.0 NODE_REPORT\n";                         // line 11
  write_file(dir / "bad.alog", text);
  const auto r = run(dir, {"m.moos", "bad.alog", "--seed=3"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.err.find("bad.alog:10: warning: time 'not-a-time' is not a finite number; line "
                       "skipped"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("bad.alog:11: warning:"), std::string::npos);
  // Every good line was replayed: the postings equal those of the clean log.
  const auto clean = alog_entries(run(dir, {"m.moos", "in.alog", "--seed=3"}).out);
  const auto with_bad = alog_entries(r.out);
  ASSERT_EQ(with_bad.size(), clean.size());
  for (std::size_t i = 0; i < clean.size(); ++i) {
    EXPECT_EQ(with_bad[i].time_s, clean[i].time_s);
    EXPECT_EQ(with_bad[i].variable, clean[i].variable);
    EXPECT_EQ(with_bad[i].value, clean[i].value);
  }
}

TEST(ReplayProcess, ConfigAndMailWarningsGoToStandardError) {
  ScratchDir dir;
  make_mission(dir, std::string(kBlock) + "  swath_transparency = 7\n");
  write_file(dir / "fields/hazards.txt",
             std::string(kHazards) + "hazard = x=1,y=1,label=a,type=hazard\n");
  std::vector<Line> in = small_input();
  in.push_back({4.0, "UHZ_CONFIG_REQUEST", "vname=v1,pd=nan"});
  write_file(dir / "in.alog", alog(in));
  const auto r = run(dir, {"m.moos", "in.alog", "--seed=3"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.err.find("config warning: m.moos:12: parameter 'swath_transparency' value '7': "
                       "outside [0, 1]; ignored"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("config warning: fields/hazards.txt:5: duplicate label 'a'"),
            std::string::npos);
  EXPECT_NE(r.err.find("[4.000] run warning: UHZ_CONFIG_REQUEST: field 'pd' value 'nan'"),
            std::string::npos);
  EXPECT_NE(r.err.find("event: Detection report sent to vehicle: v1"), std::string::npos);
}

TEST(ReplayProcess, UntilStopsEarlyAndAliasNamesTheSource) {
  ScratchDir dir;
  std::filesystem::create_directories(dir / "fields");
  write_file(dir / "m.moos", mission(kBlock, "shoreside_sensor"));
  write_file(dir / "fields/hazards.txt", kHazards);
  write_file(dir / "in.alog", alog(small_input()));
  const auto r = run(dir, {"m.moos", "in.alog", "--alias=shoreside_sensor", "--until=2.6"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto out = alog_entries(r.out);
  ASSERT_FALSE(out.empty());
  for (const auto& e : out) {
    EXPECT_LE(e.time_s, 2.6);
    EXPECT_EQ(e.source, "shoreside_sensor");
    EXPECT_NE(e.variable, "UHZ_HAZARD_REPORT");  // the request at 3.0 is never delivered
  }
}

TEST(ReplayProcess, UntilBeyondTheInputKeepsIterating) {
  ScratchDir dir;
  make_mission(dir);
  const auto r = run(dir, {"m.moos", "in.alog", "--until=20"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(alog_entries(r.out).back().time_s, 20.0);
  EXPECT_EQ(run(dir, {"m.moos", "in.alog", "--until=1e12"}).exit_code, 1);  // guard
}

// The same survey with poses at 2 Hz and at 10 Hz: the same detections (differences.md
// "What is promised"; every object lies well inside the swath).
TEST(ReplayProcess, PoseRateDoesNotChangeTheDetections) {
  ScratchDir dir;
  std::set<std::string> seen[2];
  int index = 0;
  for (double hz : {2.0, 10.0}) {
    const hazard::Scenario s = hazard::reference_survey(hz);
    std::string block = "  AppTick = 10\n";
    for (const auto& e : s.config) block += "  " + e.key + " = " + e.value + "\n";
    write_file(dir / "m.moos", mission(block));
    std::vector<Line> lines;
    for (const auto& m : s.mail) lines.push_back({m.time_s, m.variable, m.value});
    write_file(dir / "in.alog", alog(lines));
    const auto r = run(dir, {"m.moos", "in.alog", "--until=" + base::fmt(s.end_time_s)});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    int detections = 0;
    for (const auto& e : alog_entries(r.out)) {
      if (e.variable == "UHZ_DETECTION_REPORT" || e.variable == "UHZ_HAZARD_REPORT") {
        seen[index].insert(e.variable + " " + e.value);
        detections += e.variable == "UHZ_DETECTION_REPORT";
      }
    }
    EXPECT_GT(detections, 100);
    ++index;
  }
  EXPECT_EQ(seen[0], seen[1]);
}

}  // namespace
}  // namespace hazard_replay
