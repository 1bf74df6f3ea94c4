// The mission-side pieces together, against a minimal stand-in for the shoreside sensor that
// follows the sensor's rules (without resemblance or aspect; docs/differences.md D1, D2, D7): the
// survey vehicle flies a lawnmower, the stand-in rolls a die when an object enters the swath
// while the sensor is on, the manager keeps its beliefs from the detections, its own passes and
// the classification answers. If the manager's pass bookkeeping counted passes the sensor never
// rolled (or missed some it did), its beliefs would be biased; this checks they are calibrated.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "calibration.hpp"
#include "hazard/heading_history.hpp"
#include "hazard/swath.hpp"
#include "mission/hazard_manager.hpp"
#include "mission/metric.hpp"
#include "mission/random.hpp"
#include "mission/survey.hpp"
#include "mission/vehicle.hpp"

namespace mission {
namespace {

struct TruthObject {
  std::string label;
  glm::dvec2 position_m;
  bool hazard;
};

// The stand-in sensor for one vehicle.
class MiniSensor {
 public:
  MiniSensor(const std::vector<TruthObject>& truth, double w_m, double pd, double pfa,
             double pclass, std::uint64_t seed)
      : truth_(truth), w_m_(w_m), pd_(pd), pfa_(pfa), pclass_(pclass), seed_(seed),
        inside_(truth.size(), false), passes_(truth.size(), 0), grid_(positions(truth)) {}

  // Returns the indices of the objects detected at this pose.
  std::vector<std::size_t> sense(const Pose& pose) {
    headings_.add(pose.heading_deg, pose.time_s);
    std::vector<std::size_t> detected;
    if (headings_.turn_rate_dps() > 1.5 || pose.speed_mps > 2.0) return detected;  // frozen
    const hazard::Swath swath(pose.position_m, pose.heading_deg, w_m_, 5.0);
    std::vector<std::size_t> candidates = inside_list_;
    grid_.for_each_in_box(swath.bounds(),
                          [&](std::uint32_t id, glm::dvec2) { candidates.push_back(id); });
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    inside_list_.clear();
    for (std::size_t i : candidates) {
      const bool now_inside = swath.contains(truth_[i].position_m);
      if (now_inside && !inside_[i]) {
        ++passes_[i];
        const double u = uniform01(seed_, i, static_cast<std::uint64_t>(passes_[i]));
        if (u < (truth_[i].hazard ? pd_ : pfa_)) detected.push_back(i);
      }
      inside_[i] = now_inside;
      if (now_inside) inside_list_.push_back(i);
    }
    return detected;
  }

  bool classify_says_hazard(std::size_t i) const {
    const auto pass = static_cast<std::uint64_t>(passes_[i]);
    const bool correct = uniform01(seed_, 1000000 + i, pass) < pclass_;
    return correct ? truth_[i].hazard : !truth_[i].hazard;
  }

 private:
  const std::vector<TruthObject>& truth_;
  double w_m_, pd_, pfa_, pclass_;
  std::uint64_t seed_;
  hazard::HeadingHistory headings_;
  std::vector<bool> inside_;
  std::vector<int> passes_;
  std::vector<std::size_t> inside_list_;
  hazard::SpatialGrid grid_;

  static std::vector<glm::dvec2> positions(const std::vector<TruthObject>& truth) {
    std::vector<glm::dvec2> out;
    for (const TruthObject& o : truth) out.push_back(o.position_m);
    return out;
  }
};

struct RunResult {
  std::vector<ObjectBelief> beliefs;
  std::vector<TruthObject> truth;
  HazardManager::Counters counters;
};

RunResult run_survey(std::uint64_t seed, int objects, double hazard_fraction, double overlap) {
  constexpr double kPd = 0.9;
  const double pfa = std::pow(kPd, 4);
  constexpr double kPclass = 0.85;
  const auto region = ConvexPolygon::parse("0,0:300,0:300,200:0,200").value.value();
  RunResult result;
  for (int i = 0; i < objects; ++i) {
    const glm::dvec2 p{300.0 * uniform01(seed, 7, 3 * i), 200.0 * uniform01(seed, 7, 3 * i + 1)};
    result.truth.push_back({std::to_string(i), p, uniform01(seed, 7, 3 * i + 2) < hazard_fraction});
  }
  ManagerConfig config;
  config.vname = "archie";
  config.prior_hazard = hazard_fraction;
  HazardManager manager(config);
  manager.on_config_ack({"archie", 25, kPd, pfa, kPclass}, 0.0);
  MiniSensor sensor(result.truth, 25, kPd, pfa, kPclass, seed);
  LawnmowerOptions lawn;
  lawn.swath_half_width_m = 25;
  lawn.overlap = overlap;
  lawn.start_m = glm::dvec2{-30, -30};
  SurveyVehicle vehicle(VehicleParams{}, Pose{{-30, -30}, 0, 0, 0.0});
  vehicle.set_waypoints(plan_lawnmower(region, lawn).value->waypoints_m);
  double t = 0.0;
  for (; t < 20000.0 && !vehicle.done(); t += 0.25) {
    const Pose pose = vehicle.advance_to(t);
    manager.on_pose(pose.position_m, pose.heading_deg, pose.speed_mps, t);
    for (std::size_t i : sensor.sense(pose)) {
      hazard::DetectionReport d;
      d.label = result.truth[i].label;
      d.x_m = result.truth[i].position_m.x;
      d.y_m = result.truth[i].position_m.y;
      manager.on_detection(d, t);
      hazard::HazardReport h;
      h.label = d.label;
      h.x_m = d.x_m;
      h.y_m = d.y_m;
      h.type = sensor.classify_says_hazard(i) ? hazard::ObjectType::kHazard
                                              : hazard::ObjectType::kBenign;
      manager.on_classification(h, t);
    }
    manager.tick(t);
  }
  EXPECT_TRUE(vehicle.done());
  manager.tick(t + 100.0);
  result.beliefs = manager.beliefs();
  result.counters = manager.counters();
  return result;
}

TEST(SurveySimulation, ManagerBeliefsAreCalibratedOnFlownSurveys) {
  // 20 fixed seeds x 5000 objects = 100,000 objects; 50% overlap so that objects are passed
  // over up to three times (misses and hindsight passes matter).
  testing::CalibrationDeciles deciles;
  long missed = 0, hindsight = 0, known = 0, doubtful = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const RunResult run = run_survey(seed, 5000, 0.3, 0.5);
    missed += run.counters.missed_passes;
    hindsight += run.counters.hindsight_passes;
    doubtful += run.counters.doubtful_passes;
    for (const ObjectBelief& b : run.beliefs) {
      const bool hazard = run.truth[static_cast<std::size_t>(std::stoi(b.label))].hazard;
      deciles.add(b.p_hazard, hazard);
      ++known;
    }
  }
  EXPECT_GT(missed, 1000);     // the pass bookkeeping was exercised
  EXPECT_GT(hindsight, 1000);  // and so was hindsight
  EXPECT_GT(known, 50000);
  // Posteriors cluster (few distinct evidence combinations): four well-filled bins near 0.03,
  // 0.46, 0.77 and 0.96 carry 90% of the objects.
  EXPECT_GE(deciles.expect_calibrated(200), 4);
  EXPECT_LT(doubtful, missed / 50);  // doubtful passes (turns) are rare on a lawnmower
}

TEST(SurveySimulation, ChosenSetScoresBetterThanReportingEveryDetection) {
  // Score the manager's set with the grader against reporting every detected object.
  const RunResult run = run_survey(99, 300, 0.3, 0.5);
  std::string truth_text = "region = pts={0,0:300,0:300,200:0,200}\n";
  for (const TruthObject& o : run.truth) {
    truth_text += "hazard = x=" + std::to_string(o.position_m.x) +
                  ",y=" + std::to_string(o.position_m.y) +
                  ",label=" + o.label + ",type=" + (o.hazard ? "hazard" : "benign") + "\n";
  }
  HazardMetric metric;
  ASSERT_TRUE(metric.load_hazard_file("sim.txt", truth_text).empty());
  metric.start(0.0);
  HazardsetReport chosen{"archie", "", std::nullopt, std::nullopt, {}};
  HazardsetReport everything = chosen;
  for (const ObjectBelief& b : run.beliefs) {
    everything.objects.push_back(reported_object(b.label, b.position_m.x, b.position_m.y));
    if (b.reported) chosen.objects.push_back(everything.objects.back());
  }
  const double chosen_score = metric.evaluate(chosen, 10).norm_score;
  const double everything_score = metric.evaluate(everything, 10).norm_score;
  EXPECT_GT(chosen_score, everything_score);
  EXPECT_GT(chosen_score, 80.0);
}

}  // namespace
}  // namespace mission
