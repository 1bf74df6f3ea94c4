#pragma once
// Test helper: calibration of predicted probabilities against outcomes, in deciles.
// A decile with at least `min_count` cases passes when its outcome frequency lies within five
// binomial standard deviations of its mean prediction (team rule for probabilistic tests).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace mission::testing {

class CalibrationDeciles {
 public:
  void add(double predicted, bool outcome) {
    Bin& b = bins_[std::min(9, static_cast<int>(predicted * 10.0))];
    ++b.n;
    b.hits += outcome ? 1 : 0;
    b.sum_p += predicted;
  }

  /// Checks every decile holding at least `min_count` cases; returns how many were checked.
  int expect_calibrated(int min_count) const {
    int checked = 0;
    for (const Bin& b : bins_) {
      if (b.n < min_count) continue;
      ++checked;
      const double mean_p = b.sum_p / b.n;
      const double frac = static_cast<double>(b.hits) / b.n;
      EXPECT_NEAR(frac, mean_p, 5.0 * std::sqrt(mean_p * (1 - mean_p) / b.n) + 1e-3)
          << "decile with mean prediction " << mean_p << " and " << b.n << " cases";
    }
    return checked;
  }

 private:
  struct Bin {
    int n = 0;
    int hits = 0;
    double sum_p = 0.0;
  };
  Bin bins_[10];
};

}  // namespace mission::testing
