// The Jake mission end to end (manual 13; differences.md D33, D34, "Missions and tests"):
// missions/jake/launch.sh runs once at a high warp on moosdb-lite, then its run folder is
// checked:
// - every process started (connected to the MOOSDB) and stopped (closed its connection), and no
//   process is left running;
// - archie's detection rates over hazards and benign objects agree with the pd and pfa the
//   sensor acknowledged: the live counts against exact binomial bounds (5-sigma tails) over the
//   passes archie really made, and, pooled over many seeds, the run's recorded inputs replayed
//   through hazard_replay (same poses, same passes, other dice) within 5 binomial sigmas. The
//   passes are counted by one more replay in which the recorded requests ask for pd = 1 (then
//   every pass detects: pfa = 1^exp = 1);
// - betty's classification answers came at the configured min_classify_interval;
// - every HAZARDSET_EVAL the grader posted matches the score recomputed here from the logged
//   HAZARDSET_REPORT and the hazard file (docs/mission-logic.md; by hand, not with libmission);
// - summary.json and the picture are in the run folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>

#include "mission_run.hpp"

namespace mission_test {
namespace {

/// High enough to show the point, low enough that two missions (ctest -j2) keep up on 2 cores.
constexpr double kTestWarp = 400;
constexpr int kTestSeed = 7;
/// Real seconds the launcher may take (the mission takes about 15 at warp 400).
constexpr double kLaunchTimeout_s = 170;
/// Real seconds one hazard_replay run may take (well under a second each).
constexpr double kReplayTimeout_s = 60;
/// Seeds pooled in the replay rate check: about 6 hazard and 12 benign passes per seed.
constexpr int kPooledSeeds = 40;
/// Simulated seconds between a sensor cycle and the time stamp of its posting: a few real ms on
/// a loaded 2-core machine, times the warp (10 ms at warp 400).
constexpr double kStampJitter_s = 4.0;
/// Simulated seconds a request may take to be answered when nothing holds it back: mail delivery,
/// the sensor's next iteration (0.25 s) and the stamp jitter; 30 real ms at warp 400.
constexpr double kLatencySlack_s = 12.0;

const std::vector<std::string> kApps = {"uFldHazardSensor",         "uFldHazardMetric",
                                        "pHazardMgr_archie",        "pHazardMgr_betty",
                                        "uSimSurveyVehicle_archie", "uSimSurveyVehicle_betty"};

struct MissionRun {
  fs::path dir;
  std::optional<int> exit_code;
  std::string out, err;
  std::vector<ProcessEntry> processes;
  std::vector<moos::AlogEntry> log;
  std::map<std::string, std::string> truth;
};

class JakeMission : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    run_ = new MissionRun;
    run_->dir = fresh_run_dir("jake");
    const test_support::RunResult launched = test_support::run_program(
        JAKE_LAUNCH, {"--warp=" + std::to_string(static_cast<int>(kTestWarp)),
                      "--seed=" + std::to_string(kTestSeed), "--bin-dir=" + std::string(APPS_DIR),
                      "--run-dir=" + run_->dir.string(), "--quiet"},
        kLaunchTimeout_s);
    run_->exit_code = launched.exit_code;
    run_->out = launched.out;
    run_->err = launched.err;
    run_->processes = read_pids(run_->dir);
    run_->log = read_alog(run_->dir / "jake.alog").entries;
    run_->truth = read_truth(run_->dir / "hazards.txt");
  }
  static void TearDownTestSuite() {
    delete run_;
    run_ = nullptr;
  }
  void SetUp() override {
    ASSERT_EQ(run_->exit_code, 0) << run_->out << run_->err;
  }
  static const MissionRun& run() { return *run_; }

  /// Entries of `var` (optionally from `source`), in log order.
  static std::vector<moos::AlogEntry> entries(const std::string& var, const std::string& source = "") {
    std::vector<moos::AlogEntry> out;
    for (const auto& e : run().log)
      if (e.variable == var && (source.empty() || e.source == source)) out.push_back(e);
    return out;
  }

 private:
  static MissionRun* run_;
};
MissionRun* JakeMission::run_ = nullptr;

// ---- processes ---------------------------------------------------------------------------

TEST_F(JakeMission, EveryProcessStartedConnectedAndStopped) {
  std::set<std::string> names;
  for (const auto& p : run().processes) names.insert(p.name);
  for (const char* n : {"launcher", "moosdb-lite", "progress-watch"}) EXPECT_EQ(names.count(n), 1u) << n;
  const std::string db = read_file(run().dir / "logs/moosdb-lite.err");
  std::map<std::string, int> exits;  // the launcher's exits.txt: name -> exit status
  {
    std::ifstream in(run().dir / "exits.txt");
    std::string name;
    int status = 0;
    while (in >> name >> status) exits[name] = status;
  }
  for (const std::string& app : kApps) {
    EXPECT_EQ(names.count(app), 1u) << app;
    // Started: it said so and the MOOSDB accepted its connection. Stopped: it exited with
    // status 0 after the launcher's SIGTERM (not killed), and the MOOSDB saw its connection
    // end before the MOOSDB itself was stopped (closed, or reset when unread mail was left: an
    // app that reads its own mail at each cycle leaves what came after its last cycle, and the
    // reset meets the MOOSDB's next read or write).
    EXPECT_NE(read_file(run().dir / ("logs/" + app + ".out")).find("launching as " + app),
              std::string::npos) << app;
    EXPECT_TRUE(std::regex_search(db, std::regex("client \"" + app + "\" \\([^)]*\\): connected")))
        << app << "\n" << db;
    EXPECT_TRUE(std::regex_search(
        db, std::regex("client \"" + app +
                       "\" \\([^)]*\\): (closed by the peer|socket error|write failed)")))
        << app << "\n" << db;
    ASSERT_EQ(exits.count(app), 1u) << app;
    EXPECT_EQ(exits[app], 0) << app;
  }
  EXPECT_EQ(exits["moosdb-lite"], 0);
}

TEST_F(JakeMission, NoProcessIsLeftRunning) {
  EXPECT_FALSE(any_alive(run().processes, run().dir.string()));
  EXPECT_EQ(processes_mentioning(run().dir.string()), std::vector<std::string>{});
}

// ---- archie's detection rates (manual 3.1; differences.md "Rate checks on small fields") --------

struct Setting {
  double pd = 0.0, pfa = 0.0;
};

Setting acked_setting(const std::vector<moos::AlogEntry>& acks) {
  EXPECT_FALSE(acks.empty());
  auto f = fields(acks.empty() ? "" : acks.back().value);
  return {std::stod(f["pd"]), std::stod(f["pfa"])};
}

struct Counts {
  int hazard = 0, benign = 0;
};

/// Archie's detections in an .alog's entries, split by ground truth.
Counts archie_detections(const std::vector<moos::AlogEntry>& log,
                         const std::map<std::string, std::string>& truth) {
  Counts c;
  for (const auto& e : log) {
    if (e.variable != "UHZ_DETECTION_REPORT") continue;
    auto f = fields(e.value);
    if (f["vname"] != "archie") continue;
    (truth.at(f["label"]) == "hazard" ? c.hazard : c.benign) += 1;
  }
  return c;
}

/// The sensor's inputs of the run (what hazard_replay needs), with UHZ_CONFIG_REQUEST's pd
/// replaced when `pd` is given.
fs::path write_inputs(const MissionRun& run, const std::string& name, std::optional<std::string> pd) {
  const fs::path path = run.dir / name;
  std::ofstream out(path);
  out << moos::alog_header(name, 0.0);
  for (const auto& e : run.log) {
    if (e.variable != "NODE_REPORT" && e.variable != "UHZ_SENSOR_REQUEST" &&
        e.variable != "UHZ_CONFIG_REQUEST" && e.variable != "UHZ_CLASSIFY_REQUEST")
      continue;
    moos::AlogEntry copy = e;
    if (pd && e.variable == "UHZ_CONFIG_REQUEST")
      copy.value = std::regex_replace(copy.value, std::regex("pd=[0-9.]+"), "pd=" + *pd);
    out << moos::format_alog_line(copy);
  }
  return path;
}

std::vector<moos::AlogEntry> replay(const MissionRun& run, const fs::path& inputs, int seed) {
  const fs::path out = run.dir / ("replay_" + inputs.stem().string() + "_" + std::to_string(seed) + ".alog");
  const test_support::RunResult replayed = test_support::run_program(
      HAZARD_REPLAY_PATH,
      {(run.dir / "targ_jake.moos").string(), inputs.string(), "--seed=" + std::to_string(seed),
       "--output=" + out.string()},
      kReplayTimeout_s);
  EXPECT_EQ(replayed.exit_code, 0) << replayed.err;
  auto log = read_alog(out).entries;
  fs::remove(out);
  return log;
}

TEST_F(JakeMission, ArchieDetectionRatesAgreeWithItsAckedPdAndPfa) {
  const Setting acked = acked_setting(entries("UHZ_CONFIG_ACK_ARCHIE"));
  EXPECT_DOUBLE_EQ(acked.pd, 0.9);
  EXPECT_NEAR(acked.pfa, std::pow(0.9, 4), 5e-4);  // width 25: exp 4 (D23: computed)

  // Passes: with pd = 1 every pass over an object detects it.
  const Counts passes =
      archie_detections(replay(run(), write_inputs(run(), "inputs_pd1.alog", "1"), kTestSeed), run().truth);
  ASSERT_GE(passes.hazard, 5);  // every hazard is inside the lawnmower's coverage
  ASSERT_GE(passes.benign, 10);

  // The live run: exact binomial tails over the passes made (a live pass the replay's sampling
  // missed would only raise n, so n is at least the count).
  const Counts live = archie_detections(run().log, run().truth);
  const int n_h = std::max(passes.hazard, live.hazard), n_b = std::max(passes.benign, live.benign);
  EXPECT_GT(binomial_cdf_at_most(n_h, live.hazard, acked.pd), kFiveSigmaTail) << live.hazard << "/" << n_h;
  EXPECT_GT(binomial_cdf_at_least(n_h, live.hazard, acked.pd), kFiveSigmaTail) << live.hazard << "/" << n_h;
  EXPECT_GT(binomial_cdf_at_most(n_b, live.benign, acked.pfa), kFiveSigmaTail) << live.benign << "/" << n_b;
  EXPECT_GT(binomial_cdf_at_least(n_b, live.benign, acked.pfa), kFiveSigmaTail) << live.benign << "/" << n_b;

  // The same inputs and the same seed give the same detections (differences.md "Passes, dice
  // and reproducibility"): the live sensor decided exactly what hazard_replay decides offline.
  // Which passes happen depends on the poses sampled, and the live sensor samples at its own
  // iterations: one grazing pass may differ, so one detection may differ each way.
  std::multiset<std::string> live_labels, replay_labels;
  for (const auto& e : run().log)
    if (e.variable == "UHZ_DETECTION_REPORT") live_labels.insert(e.value);
  for (const auto& e : replay(run(), write_inputs(run(), "inputs_live.alog", std::nullopt), kTestSeed))
    if (e.variable == "UHZ_DETECTION_REPORT") replay_labels.insert(e.value);
  std::vector<std::string> differ;
  std::set_symmetric_difference(live_labels.begin(), live_labels.end(), replay_labels.begin(),
                                replay_labels.end(), std::back_inserter(differ));
  EXPECT_LE(differ.size(), 2u) << ::testing::PrintToString(differ);

  // Pooled: the recorded inputs with other dice.
  const fs::path inputs = write_inputs(run(), "inputs.alog", std::nullopt);
  Counts pooled;
  for (int seed = 1; seed <= kPooledSeeds; ++seed) {
    const Counts c = archie_detections(replay(run(), inputs, 1000 + seed), run().truth);
    pooled.hazard += c.hazard;
    pooled.benign += c.benign;
  }
  const double trials_h = double(kPooledSeeds) * passes.hazard;
  const double trials_b = double(kPooledSeeds) * passes.benign;
  EXPECT_NEAR(pooled.hazard / trials_h, acked.pd, 5.0 * std::sqrt(acked.pd * (1 - acked.pd) / trials_h));
  EXPECT_NEAR(pooled.benign / trials_b, acked.pfa, 5.0 * std::sqrt(acked.pfa * (1 - acked.pfa) / trials_b));
}

// ---- betty's classifications (manual 3.2; D8, D9) ----------------------------------------

double min_classify_interval(const fs::path& targ) {
  std::smatch m;
  const std::string text = read_file(targ);
  EXPECT_TRUE(std::regex_search(text, m, std::regex(R"(min_classify_interval\s*=\s*([0-9.]+))")));
  return m.empty() ? 0.0 : std::stod(m[1]);
}

TEST_F(JakeMission, BettysClassificationsCameAtTheConfiguredInterval) {
  const double interval_s = min_classify_interval(run().dir / "targ_jake.moos");
  ASSERT_EQ(interval_s, 30.0);
  std::vector<double> requests, answers;
  for (const auto& e : entries("UHZ_CLASSIFY_REQUEST", "pHazardMgr_betty")) requests.push_back(e.time_s);
  for (const auto& e : entries("UHZ_HAZARD_REPORT_BETTY", "uFldHazardSensor")) answers.push_back(e.time_s);
  std::sort(requests.begin(), requests.end());
  ASSERT_GE(answers.size(), 3u);
  EXPECT_EQ(answers.size(), requests.size());  // every request answered before the report
  for (std::size_t i = 1; i < answers.size(); ++i) {
    const double gap = answers[i] - answers[i - 1];
    EXPECT_GE(gap, interval_s - kStampJitter_s) << "answer " << i;  // never faster (D9)
    // Requests waiting when the previous answer left: the next one comes one interval later.
    const long asked = std::upper_bound(requests.begin(), requests.end(), answers[i - 1]) - requests.begin();
    if (asked > static_cast<long>(i)) {
      EXPECT_LE(gap, interval_s + kLatencySlack_s) << "answer " << i << " with a request waiting";
    } else {
      // The queue was empty: the answer comes as soon as the next request allows it.
      const double next_request = requests[i];
      EXPECT_LE(answers[i], std::max(answers[i - 1] + interval_s, next_request) + kLatencySlack_s)
          << "answer " << i;
    }
  }
}

// ---- the grader (docs/mission-logic.md) -------------------------------------------------------

TEST_F(JakeMission, EveryEvaluationMatchesTheScoreRecomputedFromTheLog) {
  constexpr double kMissed = 100.0, kFalseAlarm = 10.0;  // the mission's penalties
  int hazards = 0, benign = 0;
  for (const auto& [label, type] : run().truth) (type == "hazard" ? hazards : benign) += 1;
  ASSERT_EQ(hazards, 5);
  ASSERT_EQ(benign, 10);
  const double worst = kMissed * hazards + kFalseAlarm * benign;

  std::map<std::string, std::string> last_report;  // by source, as the grader keeps them
  int evaluations = 0;
  for (const auto& e : run().log) {
    if (e.variable == "HAZARDSET_REPORT") {
      const std::string source = e.value.substr(7, e.value.find('#') - 7);  // "source=<v>#..."
      last_report[source] = e.value;
    }
    if (e.variable != "HAZARDSET_EVAL") continue;
    ++evaluations;
    auto eval = fields(e.value);
    const std::string& report = last_report.at(eval["vname"]);
    std::set<std::string> reported;
    int objects = 0;
    std::stringstream parts(report);
    for (std::string part; std::getline(parts, part, '#');) {
      if (part.rfind("source", 0) == 0 || part.rfind("name", 0) == 0) continue;
      ++objects;
      reported.insert(fields(part)["label"]);
    }
    int missed = 0, correct = 0, false_alarms = 0;
    for (const auto& [label, type] : run().truth) {
      const bool in = reported.count(label) > 0;
      if (type == "hazard") (in ? correct : missed) += 1;
      if (type == "benign" && in) ++false_alarms;
    }
    const double total = kMissed * missed + kFalseAlarm * false_alarms;
    const double norm = std::clamp(100.0 * (worst - total) / worst, 0.0, 100.0);
    EXPECT_EQ(std::stoi(eval["missed_hazards"]), missed) << e.value;
    EXPECT_EQ(std::stoi(eval["correct_hazards"]), correct) << e.value;
    EXPECT_EQ(std::stoi(eval["false_alarms"]), false_alarms) << e.value;
    EXPECT_EQ(std::stoi(eval["total_objects"]), objects) << e.value;
    EXPECT_NEAR(std::stod(eval["total_score"]), total, 0.005) << e.value;
    EXPECT_NEAR(std::stod(eval["norm_score"]), norm, 0.005) << e.value;
  }
  EXPECT_EQ(evaluations, 2);  // archie's and betty's reports
  const auto scores = entries("HAZARD_SEARCH_SCORE", "uFldHazardMetric");
  ASSERT_EQ(scores.size(), 2u);
  EXPECT_NEAR(std::stod(scores.back().value),
              std::stod(fields(entries("HAZARDSET_EVAL_BETTY").back().value)["norm_score"]), 0.005);
}

TEST_F(JakeMission, TheHandOverCarriedArchiesObjectsToBettysRoute) {
  const auto handovers = entries("HAZARD_HANDOVER_BETTY", "pHazardMgr_archie");
  ASSERT_EQ(handovers.size(), 1u);
  const auto routes = entries("SURVEY_ROUTE_BETTY", "pHazardMgr_betty");
  ASSERT_EQ(routes.size(), 1u);
  EXPECT_GT(routes[0].time_s, handovers[0].time_s - kStampJitter_s);
  // Archie's objects: the hand-over's object parts (label, x, y).
  std::vector<std::pair<double, double>> handed;
  std::stringstream parts(handovers[0].value);
  for (std::string part; std::getline(parts, part, '#');) {
    if (part.rfind("label=", 0) != 0) continue;
    auto f = fields(part);
    handed.emplace_back(std::stod(f["x"]), std::stod(f["y"]));
  }
  // Every object archie detected (twice-detected ones once).
  std::set<std::string> detected_by_archie;
  for (const auto& e : entries("UHZ_DETECTION_REPORT_ARCHIE"))
    detected_by_archie.insert(fields(e.value)["label"]);
  EXPECT_EQ(handed.size(), detected_by_archie.size());
  // Betty's route: straight legs centred on the objects (mission-logic.md), so it passes over
  // every handed-over object (coordinates FMT(.,1): within a few centimetres).
  std::string pts = routes[0].value.substr(routes[0].value.find('{') + 1);
  pts = pts.substr(0, pts.find('}'));
  std::vector<std::pair<double, double>> route;
  std::stringstream points(pts);
  for (std::string p; std::getline(points, p, ':');)
    route.emplace_back(std::stod(p.substr(0, p.find(','))), std::stod(p.substr(p.find(',') + 1)));
  auto distance_to_route = [&](double x, double y) {
    double best = 1e18;
    for (std::size_t i = 1; i < route.size(); ++i) {
      const double ax = route[i - 1].first, ay = route[i - 1].second;
      const double dx = route[i].first - ax, dy = route[i].second - ay;
      const double len2 = dx * dx + dy * dy;
      const double t = len2 > 0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / len2, 0.0, 1.0) : 0.0;
      best = std::min(best, std::hypot(ax + t * dx - x, ay + t * dy - y));
    }
    return best;
  };
  for (const auto& [x, y] : handed) EXPECT_LT(distance_to_route(x, y), 0.2) << x << "," << y;
}

// ---- the result ----------------------------------------------------------------------------

TEST_F(JakeMission, SummaryScoreTableAndPicture) {
  const std::string summary = read_file(run().dir / "summary.json");
  const double betty = std::stod(fields(entries("HAZARDSET_EVAL_BETTY").back().value)["norm_score"]);
  std::smatch score;
  ASSERT_TRUE(std::regex_search(summary, score, std::regex(R"("score": ([0-9.]+))"))) << summary;
  EXPECT_DOUBLE_EQ(std::stod(score[1]), betty);
  EXPECT_NE(summary.find("\"seed\": " + std::to_string(kTestSeed)), std::string::npos);
  EXPECT_NE(run().out.find("Mission score (betty's report): "), std::string::npos) << run().out;
  EXPECT_TRUE(fs::exists(run().dir / "jake.svg"));
  if (std::system("command -v rsvg-convert >/dev/null 2>&1") == 0) {
    EXPECT_TRUE(fs::exists(run().dir / "jake.png"));
    EXPECT_NE(run().out.find("Picture: " + (run().dir / "jake.png").string()), std::string::npos);
  }
}

}  // namespace
}  // namespace mission_test
