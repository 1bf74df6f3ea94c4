#include "hazard/swath.hpp"

#include <algorithm>
#include <cmath>

#include "base/text.hpp"

namespace hazard {

SinCos sin_cos_deg(double angle_deg) {
  const double a = base::norm360(angle_deg);
  if (a == 0.0) return {0.0, 1.0};
  if (a == 90.0) return {1.0, 0.0};
  if (a == 180.0) return {0.0, -1.0};
  if (a == 270.0) return {-1.0, 0.0};
  return {std::sin(a * kRadPerDeg), std::cos(a * kRadPerDeg)};
}

namespace {

// The inclusive rule's rounding allowance, relative to the size of the numbers involved: 2^-50,
// four units in the last place (swath.hpp).
constexpr double kEdgeRounding = 1.0 / 1125899906842624.0;

// The t in [0, 1] for which |q - t e| <= h, intersected into [lo, hi] (one slab of the swept
// test). e == 0: all t or none.
void clip_slab(double q, double e, double h, double& lo, double& hi) {
  if (e == 0.0) {
    if (std::fabs(q) > h) hi = -1.0;  // empty
    return;
  }
  const double t1 = (q - h) / e, t2 = (q + h) / e;
  lo = std::max(lo, std::min(t1, t2));
  hi = std::min(hi, std::max(t1, t2));
}

}  // namespace

Swath::Swath(glm::dvec2 center_m, double heading_deg, double half_width_m, double length_m)
    : center_(center_m),
      half_width_m_(half_width_m),
      half_length_m_(length_m / 2.0),
      tolerance_m_(kEdgeRounding * (std::fabs(center_m.x) + std::fabs(center_m.y) +
                                    half_width_m + length_m / 2.0)) {
  const SinCos sc = sin_cos_deg(heading_deg);
  forward_ = {sc.sin, sc.cos};     // heading 0 -> +y, 90 -> +x
  starboard_ = {sc.cos, -sc.sin};  // heading 0 -> +x, 90 -> -y
}

bool Swath::contains(glm::dvec2 point_m) const {
  const glm::dvec2 d = point_m - center_;  // exact for nearby points, whatever their size
  const double along = d.x * forward_.x + d.y * forward_.y;
  const double across = d.x * starboard_.x + d.y * starboard_.y;
  return std::fabs(along) <= half_length_m_ + tolerance_m_ &&
         std::fabs(across) <= half_width_m_ + tolerance_m_;
}

bool Swath::swept_contains(glm::dvec2 displacement_m, glm::dvec2 point_m) const {
  const glm::dvec2 d = point_m - center_;
  const double q_along = d.x * forward_.x + d.y * forward_.y;
  const double q_across = d.x * starboard_.x + d.y * starboard_.y;
  const double e_along = displacement_m.x * forward_.x + displacement_m.y * forward_.y;
  const double e_across = displacement_m.x * starboard_.x + displacement_m.y * starboard_.y;
  double lo = 0.0, hi = 1.0;
  clip_slab(q_along, e_along, half_length_m_ + tolerance_m_, lo, hi);
  clip_slab(q_across, e_across, half_width_m_ + tolerance_m_, lo, hi);
  return lo <= hi;
}

std::array<glm::dvec2, 4> Swath::corners() const {
  const glm::dvec2 side = starboard_ * half_width_m_;
  const glm::dvec2 fore = forward_ * half_length_m_;
  return {center_ + side + fore, center_ + side - fore, center_ - side - fore,
          center_ - side + fore};
}

Box Swath::bounds() const {
  // The corners' coordinates as corners() sums them, axis by axis without the array, taken into
  // the box in corners()'s order: the same box, double for double.
  const glm::dvec2 side = starboard_ * half_width_m_;
  const glm::dvec2 fore = forward_ * half_length_m_;
  const auto extent = [](double centre, double side_m, double fore_m, double& lo, double& hi) {
    const double starboard = centre + side_m, port = centre - side_m;
    const double c[4] = {starboard + fore_m, starboard - fore_m, port - fore_m, port + fore_m};
    lo = hi = c[0];
    for (const double v : c) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  };
  Box b;
  extent(center_.x, side.x, fore.x, b.min_x, b.max_x);
  extent(center_.y, side.y, fore.y, b.min_y, b.max_y);
  // contains() rounds differently from the corner sums; a relative margin far above double
  // rounding (1e-16) keeps every contained point inside the box.
  constexpr double kRelativeMargin = 1e-9;
  const double margin = kRelativeMargin * (std::fabs(center_.x) + std::fabs(center_.y) +
                                           half_width_m_ + half_length_m_ + 1.0);
  b.min_x -= margin;
  b.min_y -= margin;
  b.max_x += margin;
  b.max_y += margin;
  return b;
}

}  // namespace hazard
