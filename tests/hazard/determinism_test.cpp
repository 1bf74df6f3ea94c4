// Reproducibility (differences.md "Passes, dice and reproducibility"): outcomes do not depend on
// tick rate or on how often poses arrive along the same tracks.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "hazard/driver.hpp"
#include "scenario/reference_scenario.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

struct ReplayRun {
  std::vector<std::string> tuples;  // "vehicle label pass purpose outcome", sorted
  int detections = 0;
  int answers = 0;
};

// Replays a scenario the way hazard_replay does: mail stamped at or before an iteration's time
// is delivered before it; iterations at `tick_hz`.
ReplayRun replay(const Scenario& s, double tick_hz, std::uint64_t seed = 2024) {
  hazard::Driver driver(
      load_configuration(s.config, testing::no_files),
      SeedChoice{seed, SeedSource::kRandomSeed});
  ReplayRun run;
  driver.set_decision_observer(
      [&](const Decision& d) { run.tuples.push_back(testing::decision_tuple(d)); });
  driver.start(0);
  play_mail(driver, s.mail, tick_hz, s.end_time_s, {}, [&](const Outputs& out) {
    for (const auto& p : out.postings) {
      run.detections += p.variable == "UHZ_DETECTION_REPORT";
      run.answers += p.variable == "UHZ_HAZARD_REPORT";
    }
  });
  const auto violations = driver.engine().invariant_violations();
  EXPECT_TRUE(violations.empty()) << violations.front();
  std::sort(run.tuples.begin(), run.tuples.end());
  return run;
}

std::uint64_t hash_of(const std::vector<std::string>& tuples) {
  std::uint64_t h = hash_name("");
  for (const auto& t : tuples) h = mix64(h ^ hash_name(t));
  return h;
}

// The pinned value: a change means every run of every mission changes. Update it only together
// with a deliberate change of the dice or the model, and say so in the change.
constexpr std::uint64_t kPinnedHash = 2384394574304110035ull;

TEST(Determinism, PinnedHashSameAtFourAndTenHertz_Style11) {
  const Scenario s = reference_survey(2.0);
  const ReplayRun four = replay(s, 4.0);
  const ReplayRun ten = replay(s, 10.0);
  EXPECT_EQ(four.tuples, ten.tuples);
  EXPECT_GT(four.detections, 100);
  EXPECT_GT(four.answers, 50);
  EXPECT_EQ(hash_of(four.tuples), kPinnedHash) << "actual: " << hash_of(four.tuples);
}

TEST(Determinism, PoseRateDoesNotChangeDetections_Reproducibility) {
  const ReplayRun slow = replay(reference_survey(2.0), 10.0);
  const ReplayRun fast = replay(reference_survey(10.0), 10.0);
  EXPECT_EQ(slow.tuples, fast.tuples);
  // Every object was passed over twice (archie once, betty once).
  std::set<std::string> seen;
  for (const auto& t : slow.tuples) {
    if (t.find(" detect ") != std::string::npos) seen.insert(t.substr(0, t.find(" detect ")));
  }
  EXPECT_EQ(seen.size(), 400u);
}

TEST(Determinism, DifferentSeedsGiveDifferentOutcomes) {
  const Scenario s = reference_survey(2.0);
  const ReplayRun a = replay(s, 4.0, 2024);
  const ReplayRun b = replay(s, 4.0, 99);
  EXPECT_NE(a.tuples, b.tuples);
  EXPECT_NE(a.detections, 0);
  EXPECT_NE(b.detections, 0);
}

}  // namespace
}  // namespace hazard
