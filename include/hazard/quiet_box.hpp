#pragma once
// A square around a recent pose, known to hold none of a fixed set of points (a field's objects,
// a manager's records): while the square a pose reaches stays inside it, the answer needs no
// index query. The sensor engine (sensing.cpp) and the hazard manager (hazard_manager.cpp) keep
// one per vehicle: a vehicle moves a fraction of a metre per pose, and most poses of a survey
// over a sparse field have nothing near.
//
// Contract: nothing_near(p, reach, slack, holds_nothing) is true only when no point lies within
// `reach` of p on either axis. When that square is not inside the box, the box becomes the square
// of reach + slack around p, and holds_nothing(box) must say whether no point lies in it. Far
// out (beyond 1e9 m, where sums round by metres) or NaN: false, so the caller takes its full
// test. forget() when the set of points changes.

#include <cmath>

#include <glm/vec2.hpp>

#include "hazard/spatial_grid.hpp"

namespace hazard {

class QuietBox {
 public:
  template <typename HoldsNothing>
  bool nothing_near(glm::dvec2 p, double reach_m, double slack_m, HoldsNothing&& holds_nothing) {
    constexpr double kFar_m = 1e9;
    if (!(reach_m < kFar_m && std::fabs(p.x) < kFar_m && std::fabs(p.y) < kFar_m)) return false;
    if (!(box_.min_x <= p.x - reach_m && box_.min_y <= p.y - reach_m &&
          p.x + reach_m <= box_.max_x && p.y + reach_m <= box_.max_y)) {
      const double half_m = reach_m + slack_m;
      box_ = Box{p.x - half_m, p.y - half_m, p.x + half_m, p.y + half_m};
      quiet_ = holds_nothing(static_cast<const Box&>(box_));
    }
    return quiet_;
  }

  /// The next nothing_near() queries again.
  void forget() { *this = QuietBox{}; }

 private:
  Box box_{0.0, 0.0, -1.0, -1.0};  // covers nothing until the first query
  bool quiet_ = false;
};

}  // namespace hazard
