#pragma once
// Vehicle-side belief about one object, and the two choices made from it: whether to report the
// object as a hazard, and how urgently to ask for a classification.
//
// Belief model (Bayes' rule in log-odds form). For an object, H = "is a hazard". The belief is
//   L = logit(prior) + sum of log-likelihood ratios ln P(obs | H) / P(obs | not H)
// over the independent observations (the simulator rolls a separate die per pass and purpose,
// differences.md "Passes, dice and reproducibility"), with the settings acknowledged by the sensor:
//   detection on a pass            ln(pd / pfa)                 (manual 3.1)
//   a pass without a detection     ln((1 - pd) / (1 - pfa))     (manual 3.1)
//   classification "hazard"        ln(pclass / (1 - pclass))    (manual 3.2)
//   classification "benign"        ln((1 - pclass) / pclass)
// What the model does not know: resemblance (manual 6) and aspect (manual 7) raise a benign
// object's false-alarm rate and lower pclass, so for such objects the belief is overconfident;
// the vehicle cannot observe hr or the aspect window, and the acked numbers are the best it has.
// Probabilities are kept inside [kMinLikelihood, 1 - kMinLikelihood] when forming ratios: a
// single "certain" observation (pfa = 0, pd = 1, pclass = 1) would otherwise make the belief
// infinite and later contradicting evidence would give inf - inf = NaN.
//
// Set choice (the scoring of docs/mission-logic.md, "The grader"). Penalties add up over objects: a
// reported benign object costs
// P_fa, an unreported hazard costs P_missed, everything else costs nothing; the time term does not
// depend on the set. So the expected penalty of a set is the sum over objects of
//   reported:     (1 - p) * P_fa        not reported:  p * P_missed
// and it is minimised by deciding each object alone: report iff p * P_missed > (1 - p) * P_fa,
// i.e. iff L > ln(P_fa / P_missed). Ties are not reported.
//
// Classification priority (manual 3.2: "perhaps tying the priority to the expected information
// gain"): the value of information (VOI) of n answers with accuracy pc, in expected penalty.
// With k "hazard" answers out of n, P(k | H) = C(n,k) pc^k (1-pc)^(n-k) and
// P(k | B) = C(n,k) (1-pc)^k pc^(n-k); deciding after the answers costs
//   E0  = min(p P_m, (1 - p) P_fa)                                   (decide now)
//   En  = sum_k min(p P(k|H) P_m, (1 - p) P(k|B) P_fa)               (decide after n answers)
//   VOI = E0 - En >= 0
// mapped to [0, 100] as 100 * VOI / Emax, Emax = P_m P_fa / (P_m + P_fa), the largest expected
// penalty one object can carry (at the decision threshold). For n = 1 the best priority a
// classifier can earn is 100 (2 pc - 1), at the threshold: 70 for pclass 0.85, 86 for 0.93.
// Why the manager looks two answers ahead by default: under Jake's 100:10 penalties one answer of
// pclass 0.85 never flips a fresh detection (p = 0.58 -> 0.20 after "benign", still reported), so
// every one-answer VOI is 0 and priorities say nothing; but this answer combined with one more
// (a reacquisition pass, Jake's betty) can flip it, and that is what the answer is worth.

#include <string>

namespace mission {

/// Smallest probability used in a likelihood ratio (see the file comment): ln(1e-9) = -20.7, so
/// one observation moves the log-odds by at most about 20.7.
inline constexpr double kMinLikelihood = 1e-9;

/// Default prior P(hazard) of an object the vehicle knows nothing about: 0.5, the uninformed
/// choice. The vehicle does not know the field's make-up (Jake has 5 hazards in 15 objects, but a
/// manager tuned to that would be grading itself against the answer). With Jake's 100:10
/// penalties the report threshold is p > 1/11, so the prior matters little once evidence comes.
inline constexpr double kDefaultPriorHazard = 0.5;

/// The mission's penalties (UHZ_MISSION_PARAMS; uFldHazardMetric defaults, docs/mission-logic.md).
struct Penalties {
  double missed_hazard = 100.0;  ///< >= 0
  double false_alarm = 10.0;     ///< >= 0
};

double logit(double p);            ///< ln(p / (1 - p)); p in (0, 1)
double logistic(double log_odds);  ///< 1 / (1 + e^-L), in [0, 1]

double llr_detection(double pd, double pfa);
double llr_missed_pass(double pd, double pfa);
double llr_classification(bool said_hazard, double pclass);

/// The report rule: p * P_missed > (1 - p) * P_fa.
bool should_report(double p_hazard, const Penalties& penalties);
/// Expected penalty of the better decision now: min(p P_m, (1 - p) P_fa).
double expected_penalty(double p_hazard, const Penalties& penalties);
/// The largest answers-ahead count classification_value accepts (the binomial sum stays exact).
inline constexpr int kMaxLookaheadAnswers = 20;
/// VOI of `answers` classification answers with accuracy pclass (>= 0, penalty units);
/// answers in [1, kMaxLookaheadAnswers].
double classification_value(double p_hazard, double pclass, const Penalties& penalties,
                            int answers = 1);
/// The VOI mapped to [0, 100] (see the file comment); 0 when a penalty is 0.
double classification_priority(double p_hazard, double pclass, const Penalties& penalties,
                               int answers = 1);

/// Evidence about one object, as counts and summed log-likelihood ratios.
struct Evidence {
  double log_lr = 0.0;      ///< sum of the log-likelihood ratios of this vehicle's observations
  int detections = 0;
  int missed_passes = 0;
  int said_hazard = 0;      ///< classification answers "hazard"
  int said_benign = 0;

  void add_detection(double pd, double pfa);
  void add_missed_pass(double pd, double pfa);
  void add_classification(bool said_hazard_answer, double pclass);
};

}  // namespace mission
