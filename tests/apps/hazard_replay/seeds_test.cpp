// hazard_replay --seeds=A..B: one JSON line per seed, each the same counts as that seed's own
// replay (its .alog's detection and hazard reports).
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "base/text.hpp"
#include "hazard/messages/node_report.hpp"
#include "replay.hpp"
#include "replay_support.hpp"
#include "scenario/config_text.hpp"

namespace hazard_replay {
namespace {

using test_support::alog_entries;
using test_support::ScratchDir;
using test_support::write_file;

// Ten benign and ten hazard objects on a line the vehicle drives along twice; every detection
// asks for a classification, so both counts move with the seed.
void make_study(const ScratchDir& dir) {
  std::string field;
  for (int i = 0; i < 20; ++i) {
    field += "hazard = x=" + std::to_string(i * 10) + ",y=5,label=o" + std::to_string(i) +
             (i % 2 ? ",type=hazard\n" : ",type=benign\n");
  }
  write_file(dir / "field.txt", field);
  write_file(dir / "m.moos", testing::mission("  hazard_file = field.txt\n"
                                              "  sensor_config = width=25, exp=4, pclass=0.7\n"
                                              "  show_hazards = false\n"
                                              "  min_classify_interval = 0\n"));
  std::vector<testing::Line> lines = {{0.0, "UHZ_SENSOR_REQUEST", "vname=v"}};
  for (int k = 0; k <= 280; ++k) {
    hazard::NodeReport r;
    r.name = "v";
    r.x_m = k <= 140 ? k * 1.5 - 10 : (280 - k) * 1.5 - 10;
    r.y_m = 0;
    r.speed_mps = 1.5;
    r.heading_deg = k <= 140 ? 90 : 270;
    lines.push_back({k * 1.0, "NODE_REPORT", hazard::format_node_report(r)});
    for (int i = 0; i < 20; ++i)
      lines.push_back({k + 0.5, "UHZ_CLASSIFY_REQUEST", "vname=v,label=o" + std::to_string(i)});
  }
  write_file(dir / "in.alog", testing::alog(lines));
}

std::string expected_line(const ScratchDir& dir, int seed) {
  const auto r = testing::run(dir, {"m.moos", "in.alog", "--seed=" + std::to_string(seed)});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  int detections = 0, classifications = 0;
  for (const moos::AlogEntry& e : alog_entries(r.out)) {
    detections += e.variable == "UHZ_DETECTION_REPORT";
    classifications += e.variable == "UHZ_HAZARD_REPORT";
  }
  return "{\"seed\":" + std::to_string(seed) + ",\"detections\":" + std::to_string(detections) +
         ",\"classifications\":" + std::to_string(classifications) + "}";
}

TEST(ReplaySeeds, OneLinePerSeedMatchingEachSeedsOwnReplay) {
  ScratchDir dir;
  make_study(dir);
  const auto r = testing::run(dir, {"m.moos", "in.alog", "--seeds=3..6"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string_view> lines = base::split(base::trim(r.out), '\n');
  ASSERT_EQ(lines.size(), 4u) << r.out;
  std::set<std::string> distinct;
  for (int seed = 3; seed <= 6; ++seed) {
    const std::string want = expected_line(dir, seed);
    EXPECT_EQ(lines[static_cast<std::size_t>(seed - 3)], want);
    distinct.insert(want.substr(want.find(',')));
  }
  EXPECT_GT(distinct.size(), 1u);  // the seed matters in this study
  EXPECT_EQ(testing::run(dir, {"m.moos", "in.alog", "--seeds=3..6"}).out, r.out);
}

// --score: the shoreside's metric block grades the recorded reports as uFldHazardMetric would.
// Truth: o1, o3, ... o19 hazards, o0, o2, ... o18 benign (make_study); default penalties:
// worst = 10 x 100 + 10 x 10 = 1100.
void add_metric_and_reports(const ScratchDir& dir, const std::vector<std::string>& reports) {
  write_file(dir / "m.moos",
             testing::mission("  hazard_file = field.txt\n"
                              "  sensor_config = width=25, exp=4, pclass=0.7\n"
                              "  show_hazards = false\n"
                              "  min_classify_interval = 0\n") +
                 "\nProcessConfig = uFldHazardMetric\n{\n  AppTick = 4\n  hazard_file = field.txt\n"
                 "  penalty_missed_hazard = 100\n  penalty_false_alarm = 10\n}\n");
  std::vector<testing::Line> lines = {{0.0, "UHZ_SENSOR_REQUEST", "vname=v"},
                                      {1.0, "HAZARD_SEARCH_START", "true"}};
  double t = 100.0;
  for (const std::string& r : reports) lines.push_back({t += 10.0, "HAZARDSET_REPORT", r});
  lines.push_back({t + 10.0, "NODE_REPORT", "NAME=v,X=0,Y=0,SPD=1.5,HDG=90"});
  write_file(dir / "in.alog", testing::alog(lines));
}

std::string objects(int first, int step) {
  std::string out;
  for (int i = first; i < 20; i += step) {
    out += "#x=" + std::to_string(i * 10) + ",y=5,label=o" + std::to_string(i);
  }
  return out;
}

TEST(ReplaySeeds, ScoreIsTheLastReportsGradeOnEveryLine) {
  ScratchDir dir;
  make_study(dir);
  // archie reports every hazard (score 100); betty then reports half the hazards and half the
  // benign objects: 5 missed x 100 + 5 false alarms x 10 = 550 of 1100, score 50. The
  // MOOSDB's last HAZARD_SEARCH_SCORE is betty's.
  add_metric_and_reports(dir, {"source=archie" + objects(1, 2), "source=betty" + objects(0, 4) +
                                   objects(1, 4)});
  const auto plain = testing::run(dir, {"m.moos", "in.alog", "--seeds=1..2"});
  const auto r = testing::run(dir, {"m.moos", "in.alog", "--seeds=1..2", "--score"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("unknown parameter"), std::string::npos) << r.err;  // AppTick is the app's
  const auto lines = base::split(base::trim(r.out), '\n');
  const auto plain_lines = base::split(base::trim(plain.out), '\n');
  ASSERT_EQ(lines.size(), 2u) << r.out;
  ASSERT_EQ(plain_lines.size(), 2u) << plain.out;
  for (std::size_t i = 0; i < 2; ++i) {
    std::string want(plain_lines[i]);
    want.insert(want.size() - 1, ",\"score\":50");
    EXPECT_EQ(lines[i], want);
  }
  // Reports after --until are not graded: only archie's counts.
  const auto early =
      testing::run(dir, {"m.moos", "in.alog", "--seeds=1..1", "--score", "--until=115"});
  ASSERT_EQ(early.exit_code, 0) << early.err;
  EXPECT_NE(early.out.find(",\"score\":100}"), std::string::npos) << early.out;
}

TEST(ReplaySeeds, ScoreWithoutAReportOrAMetricBlock) {
  ScratchDir dir;
  make_study(dir);
  add_metric_and_reports(dir, {});
  const auto none = testing::run(dir, {"m.moos", "in.alog", "--seeds=0..0", "--score"});
  ASSERT_EQ(none.exit_code, 0) << none.err;
  EXPECT_EQ(none.out.find("score"), std::string::npos) << none.out;
  EXPECT_NE(none.err.find("holds no HAZARDSET_REPORT the metric accepts"), std::string::npos)
      << none.err;

  make_study(dir);  // the mission again, without the metric's block
  const auto no_block = testing::run(dir, {"m.moos", "in.alog", "--seeds=0..0", "--score"});
  EXPECT_EQ(no_block.exit_code, 1);
  EXPECT_NE(no_block.err.find("--score needs a 'ProcessConfig = uFldHazardMetric' block"),
            std::string::npos)
      << no_block.err;
  const auto no_seeds = testing::run(dir, {"m.moos", "in.alog", "--score"});
  EXPECT_EQ(no_seeds.exit_code, 2);
  EXPECT_NE(no_seeds.err.find("--score needs --seeds=A..B"), std::string::npos) << no_seeds.err;
}

// The study builds no posting text its line does not read: its engine posts no VIEW_* at all,
// where the .alog replay's engine (the same mission and seed) draws swaths and circles, and it
// posts the same reports.
TEST(ReplaySeeds, StudyEngineBuildsNoVisualsAndTheSameReports) {
  std::string block = "sensor_config = width=25, exp=4, pclass=0.7\nshow_detections = 30\n"
                      "min_classify_interval = 0\n";
  for (int i = 0; i < 20; ++i) {
    block += "hazard = x=" + std::to_string(i * 10) + ",y=5,label=o" + std::to_string(i) +
             (i % 2 ? ",type=hazard\n" : ",type=benign\n");
  }
  const hazard::Engine built(
      hazard::load_configuration(hazard::config_entries(block, "m.moos"),
                                 [](const std::string&) { return base::Result<std::string>::fail("no file"); }),
      hazard::SeedChoice{});
  std::vector<std::pair<std::string, std::string>> texts;  // the mail's storage
  for (int k = 0; k <= 150; ++k) {
    texts.push_back({"NODE_REPORT", "NAME=v,X=" + std::to_string(k * 1.5 - 10) +
                                        ",Y=0,SPD=1.5,HDG=90"});
    for (int i = 0; i < 20; ++i)
      texts.push_back({"UHZ_CLASSIFY_REQUEST", "vname=v,label=o" + std::to_string(i)});
  }
  std::vector<hazard::Mail> mail = {{"UHZ_SENSOR_REQUEST", "vname=v", 0.0}};
  for (std::size_t n = 0; n < texts.size(); ++n)
    mail.push_back({texts[n].first, texts[n].second, static_cast<double>(n / 21)});
  const Timeline timeline{&mail, 0.0, 160.0, 4.0};
  struct Seen {
    int visuals = 0;
    std::string reports;
  };
  const auto play = [&](hazard::Engine engine) {
    hazard::Driver driver(std::move(engine));
    Seen seen;
    replay(driver, timeline, [&](const hazard::TimedOutputs& t) {
      for (const hazard::Posting& p : t.outputs.postings) {
        if (base::starts_with(p.variable, "VIEW_")) {
          ++seen.visuals;
        } else {
          seen.reports += p.variable + "=" + p.value + "\n";
        }
      }
    });
    return seen;
  };
  for (std::uint64_t seed = 3; seed <= 5; ++seed) {
    const Seen alog = play(built.with_seed({seed, hazard::SeedSource::kCommandLine}));
    const Seen study = play(study_engine(built, seed));
    EXPECT_GT(alog.visuals, 600);  // a swath per iteration, circles per report
    EXPECT_EQ(study.visuals, 0);
    EXPECT_EQ(study.reports, alog.reports);
    EXPECT_NE(alog.reports.find("UHZ_HAZARD_REPORT="), std::string::npos);
  }
}

}  // namespace
}  // namespace hazard_replay
