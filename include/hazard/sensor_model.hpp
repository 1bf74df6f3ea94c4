#pragma once
// The sensor model as free functions of plain numbers, testable alone. Probabilities are in
// [0, 1] unless a caller passes values outside (the parsers never do).

namespace hazard {

/// ROC curve (manual 4.2): pfa = pd^exp. pd in [0, 1], exp >= 1 -> result in [0, 1]. A result
/// below the smallest normal double (2.2e-308) is exactly 0 (no subnormals, N5).
double roc_false_alarm_probability(double pd, double exp);

/// Resemblance on detection (manual 6.1): a benign object with resemblance hr in [0, 1] is
/// falsely detected with (pfa + hr) / 2.
double resemblance_false_alarm_probability(double pfa, double hr);

/// Aspect difference (manual 7, eq. 1): the angle between the vehicle heading and the object's
/// aspect axis, in [0, 90] deg (approaching from either direction counts the same).
double aspect_difference_deg(double heading_deg, double aspect_deg);

/// Degradation g in [0, 1] (manual 7 eq. 2-3, differences.md D6): 0 when diff <= aspect_min, 1 when
/// diff >= aspect_max, linear in between. min == max never divides by zero.
double aspect_degradation(double diff_deg, double aspect_min_deg, double aspect_max_deg);

/// Degraded ROC exponent (manual 7.1, differences.md D5): exp' = exp - g (exp - 1), so g = 1 gives
/// the linear ROC (exp' = 1).
double degraded_exponent(double exp, double degradation);

/// Resemblance on classification (manual 6.2): a benign object with resemblance hr is reported
/// benign with probability pc + (1 - pc)(1 - hr).
double resemblance_classification_probability(double pc, double hr);

/// Aspect on classification (manual 7.2): pc' = 0.5 + (1 - g)(pc - 0.5).
double aspect_classification_probability(double pc, double degradation);

/// Detection die (docs/differences.md, "Random numbers and reproducibility"): detect iff u < p
/// (u = k/10000, k in [0, 9999]).
inline bool detection_succeeds(double u, double p) { return u < p; }
/// Classification die (docs/differences.md, "Random numbers and reproducibility"): correct iff
/// v <= p (v = k/10000, k in [0, 10000]).
inline bool classification_correct(double v, double p) { return v <= p; }

}  // namespace hazard
