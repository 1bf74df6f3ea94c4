#include <gtest/gtest.h>

#include <cmath>

#include "calibration.hpp"
#include "mission/belief.hpp"
#include "mission/random.hpp"

namespace mission {
namespace {

// Jake's archie setting (differences.md "Jake's sensor options": width 25, exp 4, pclass 0.85;
// pd 0.9).
constexpr double kPd = 0.9;
const double kPfa = std::pow(0.9, 4);  // 0.6561
constexpr double kPclass = 0.85;

TEST(Belief, LikelihoodRatiosFollowBayes_Manual3) {
  EXPECT_NEAR(llr_detection(kPd, kPfa), std::log(0.9 / 0.6561), 1e-12);
  EXPECT_NEAR(llr_missed_pass(kPd, kPfa), std::log(0.1 / 0.3439), 1e-12);
  EXPECT_NEAR(llr_classification(true, kPclass), std::log(0.85 / 0.15), 1e-12);
  EXPECT_NEAR(llr_classification(false, kPclass), -std::log(0.85 / 0.15), 1e-12);
  // By hand: prior 0.5, one detection -> 0.9 / (0.9 + 0.6561) = 0.57838.
  Evidence e;
  e.add_detection(kPd, kPfa);
  EXPECT_NEAR(logistic(logit(0.5) + e.log_lr), 0.9 / (0.9 + 0.6561), 1e-12);
  // Then a "benign" answer: 0.57838 * 0.15 / (0.57838 * 0.15 + 0.42162 * 0.85) = 0.19490.
  e.add_classification(false, kPclass);
  const double p1 = 0.9 / (0.9 + 0.6561);
  EXPECT_NEAR(logistic(logit(0.5) + e.log_lr), p1 * 0.15 / (p1 * 0.15 + (1 - p1) * 0.85), 1e-12);
  EXPECT_EQ(e.detections, 1);
  EXPECT_EQ(e.said_benign, 1);
}

TEST(Belief, CertainObservationsStayFiniteAndContradictionsDoNotGiveNaN) {
  Evidence e;
  e.add_detection(0.9, 0.0);          // pfa 0: a detection "proves" a hazard
  e.add_classification(false, 1.0);   // pclass 1: the answer "proves" benign
  EXPECT_TRUE(std::isfinite(e.log_lr));
  EXPECT_NEAR(e.log_lr, std::log(0.9), 1e-6);  // ln(0.9/1e-9) + ln(1e-9/(1-1e-9)): they cancel
  EXPECT_LE(std::abs(llr_detection(1.0, 0.0)), -std::log(kMinLikelihood) + 1e-9);
  EXPECT_EQ(logistic(1000.0), 1.0);
  EXPECT_EQ(logistic(-1000.0), 0.0);
}

TEST(Belief, ReportRuleIsTheExpectedPenaltyThreshold) {
  const Penalties jake{100, 10};
  // Threshold p = P_fa / (P_m + P_fa) = 1/11.
  EXPECT_FALSE(should_report(1.0 / 11.0 - 1e-9, jake));
  EXPECT_TRUE(should_report(1.0 / 11.0 + 1e-9, jake));
  EXPECT_FALSE(should_report(0.5, Penalties{10, 10}));  // a tie is not reported
  EXPECT_FALSE(should_report(0.99, Penalties{0, 10}));  // missing costs nothing
  EXPECT_TRUE(should_report(1e-6, Penalties{100, 0}));  // false alarms cost nothing
  EXPECT_NEAR(expected_penalty(0.3, jake), 7.0, 1e-12);  // min(30, 7)
}

TEST(Belief, OneAnswerPriorityPeaksAtTheThresholdAt100TimesTwoPcMinusOne) {
  const Penalties jake{100, 10};
  const double threshold = 10.0 / 110.0;
  EXPECT_NEAR(classification_priority(threshold, 0.85, jake), 100 * (2 * 0.85 - 1), 1e-9);
  EXPECT_NEAR(classification_priority(threshold, 0.93, jake), 100 * (2 * 0.93 - 1), 1e-9);
  EXPECT_NEAR(classification_priority(threshold, 1.0, jake), 100.0, 1e-9);
  EXPECT_EQ(classification_priority(threshold, 0.5, jake), 0.0);  // a coin says nothing
  for (double p = 0.0; p <= 1.0; p += 0.01) {
    const double prio = classification_priority(p, 0.85, jake);
    EXPECT_GE(prio, 0.0);
    EXPECT_LE(prio, 70.0 + 1e-9);
  }
  EXPECT_EQ(classification_priority(0.3, 0.85, Penalties{0, 0}), 0.0);
}

TEST(Belief, OneAnswerValueByHand) {
  // p = 0.3, pc = 0.85, 100:10. E0 = min(30, 7) = 7.
  // "hazard" answer: min(0.3*0.85*100, 0.7*0.15*10) = min(25.5, 1.05) = 1.05
  // "benign" answer: min(0.3*0.15*100, 0.7*0.85*10) = min(4.5, 5.95) = 4.5
  // VOI = 7 - 5.55 = 1.45; Emax = 1000/110; priority = 100 * 1.45 * 110 / 1000 = 15.95.
  const Penalties jake{100, 10};
  EXPECT_NEAR(classification_value(0.3, 0.85, jake), 1.45, 1e-12);
  EXPECT_NEAR(classification_priority(0.3, 0.85, jake), 15.95, 1e-9);
}

TEST(Belief, TwoAnswerLookaheadValuesAFreshJakeDetection) {
  // After one archie detection p = 0.578: one answer cannot flip the decision (VOI 0), two can.
  const Penalties jake{100, 10};
  const double p = 0.9 / (0.9 + 0.6561);
  EXPECT_EQ(classification_value(p, 0.85, jake, 1), 0.0);
  // By hand, n = 2: k=2 min(p .7225 100, q .0225 10), k=1 min(p .255 100, q .255 10),
  // k=0 min(p .0225 100, q .7225 10), q = 1 - p.
  const double q = 1 - p;
  const double e2 = std::min(p * 0.7225 * 100, q * 0.0225 * 10) +
                    std::min(p * 0.255 * 100, q * 0.255 * 10) +
                    std::min(p * 0.0225 * 100, q * 0.7225 * 10);
  EXPECT_NEAR(classification_value(p, 0.85, jake, 2), q * 10 - e2, 1e-12);
  EXPECT_GT(classification_priority(p, 0.85, jake, 2), 10.0);
  // More answers are never worth less.
  for (int n = 1; n < 8; ++n)
    EXPECT_LE(classification_value(p, 0.85, jake, n),
              classification_value(p, 0.85, jake, n + 1) + 1e-12);
}

// Calibration: objects drawn with P(hazard) = prior, each seen on 1..3 passes with Jake's archie
// setting, a classification answer for every detection. Among objects the vehicle knows (at least
// one detection), the posterior must be calibrated: in each decile of posterior with n >= 200
// objects, the hazard fraction lies within 5 binomial standard deviations of the mean posterior.
TEST(Belief, PosteriorIsCalibratedOver100000Objects) {
  constexpr int kObjects = 100000;
  constexpr double kPrior = 0.3;
  constexpr std::uint64_t kSeed = 20240601;
  testing::CalibrationDeciles deciles;
  int known = 0;
  std::uint64_t draw = 0;
  auto u = [&] { return uniform01(kSeed, 1, draw++); };
  for (int i = 0; i < kObjects; ++i) {
    const bool hazard = u() < kPrior;
    const int passes = 1 + static_cast<int>(u() * 3.0);
    Evidence e;
    for (int k = 0; k < passes; ++k) {
      if (u() < (hazard ? kPd : kPfa)) {
        e.add_detection(kPd, kPfa);
        const bool correct = u() < kPclass;
        e.add_classification(correct ? hazard : !hazard, kPclass);
      } else {
        e.add_missed_pass(kPd, kPfa);
      }
    }
    if (e.detections == 0) continue;  // the vehicle never learns of this object
    ++known;
    deciles.add(logistic(logit(kPrior) + e.log_lr), hazard);
  }
  EXPECT_GE(deciles.expect_calibrated(200), 6);
  EXPECT_GT(known, kObjects / 2);
}

// The report rule minimises the realised penalty against simpler rules (100,000 objects).
TEST(Belief, ReportRuleBeatsReportAllAndHalfThresholdOnAverage) {
  constexpr int kObjects = 100000;
  const Penalties jake{100, 10};
  double rule = 0, all = 0, half = 0;
  std::uint64_t draw = 0;
  auto u = [&] { return uniform01(7, 2, draw++); };
  for (int i = 0; i < kObjects; ++i) {
    const bool hazard = u() < 0.3;
    Evidence e;
    if (!(u() < (hazard ? kPd : kPfa))) continue;
    e.add_detection(kPd, kPfa);
    e.add_classification(u() < kPclass ? hazard : !hazard, kPclass);
    e.add_classification(u() < 0.93 ? hazard : !hazard, 0.93);  // a reacquisition answer
    const double p = logistic(logit(0.3) + e.log_lr);
    auto cost = [&](bool report) { return report ? (hazard ? 0 : 10) : (hazard ? 100 : 0); };
    rule += cost(should_report(p, jake));
    all += cost(true);
    half += cost(p > 0.5);
  }
  EXPECT_LT(rule, all);
  EXPECT_LT(rule, half);
}

}  // namespace
}  // namespace mission
