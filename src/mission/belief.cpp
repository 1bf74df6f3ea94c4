// Belief formulas. Derivations: include/mission/belief.hpp.

#include "mission/belief.hpp"

#include <algorithm>
#include <cmath>

namespace mission {

namespace {
double bounded(double p) { return std::clamp(p, kMinLikelihood, 1.0 - kMinLikelihood); }
}  // namespace

double logit(double p) { return std::log(p / (1.0 - p)); }

double logistic(double log_odds) {
  // Written so that neither branch overflows for large |L|.
  if (log_odds >= 0.0) return 1.0 / (1.0 + std::exp(-log_odds));
  const double e = std::exp(log_odds);
  return e / (1.0 + e);
}

double llr_detection(double pd, double pfa) { return std::log(bounded(pd) / bounded(pfa)); }

double llr_missed_pass(double pd, double pfa) {
  return std::log(bounded(1.0 - pd) / bounded(1.0 - pfa));
}

double llr_classification(bool said_hazard, double pclass) {
  const double ratio = std::log(bounded(pclass) / bounded(1.0 - pclass));
  return said_hazard ? ratio : -ratio;
}

bool should_report(double p_hazard, const Penalties& penalties) {
  return p_hazard * penalties.missed_hazard > (1.0 - p_hazard) * penalties.false_alarm;
}

double expected_penalty(double p_hazard, const Penalties& penalties) {
  return std::min(p_hazard * penalties.missed_hazard, (1.0 - p_hazard) * penalties.false_alarm);
}

double classification_value(double p_hazard, double pclass, const Penalties& penalties,
                            int answers) {
  const double p = p_hazard;
  const double pm = penalties.missed_hazard;
  const double pf = penalties.false_alarm;
  // Sum over k hazard answers of the better decision's expected penalty (file comment).
  double after = 0.0;
  double binomial = 1.0;  // C(n, k), exact in a double for n <= kMaxLookaheadAnswers
  for (int k = 0; k <= answers; ++k) {
    if (k > 0) binomial = binomial * (answers - k + 1) / k;
    const double if_hazard = binomial * std::pow(pclass, k) * std::pow(1.0 - pclass, answers - k);
    const double if_benign = binomial * std::pow(1.0 - pclass, k) * std::pow(pclass, answers - k);
    after += std::min(p * if_hazard * pm, (1.0 - p) * if_benign * pf);
  }
  // Concavity makes this >= 0 mathematically; rounding can leave -1e-17.
  return std::max(0.0, expected_penalty(p, penalties) - after);
}

double classification_priority(double p_hazard, double pclass, const Penalties& penalties,
                               int answers) {
  const double sum = penalties.missed_hazard + penalties.false_alarm;
  const double worst = sum > 0.0 ? penalties.missed_hazard * penalties.false_alarm / sum : 0.0;
  if (!(worst > 0.0)) return 0.0;
  const double voi = classification_value(p_hazard, pclass, penalties, answers);
  return std::clamp(100.0 * voi / worst, 0.0, 100.0);
}

void Evidence::add_detection(double pd, double pfa) {
  log_lr += llr_detection(pd, pfa);
  ++detections;
}

void Evidence::add_missed_pass(double pd, double pfa) {
  log_lr += llr_missed_pass(pd, pfa);
  ++missed_passes;
}

void Evidence::add_classification(bool said_hazard_answer, double pclass) {
  log_lr += llr_classification(said_hazard_answer, pclass);
  ++(said_hazard_answer ? said_hazard : said_benign);
}

}  // namespace mission
