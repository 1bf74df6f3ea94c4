#include "hazard/sensing_track.hpp"

#include <algorithm>
#include <cmath>

#include "base/text.hpp"

namespace hazard {

namespace {

bool in_box(const Box& b, glm::dvec2 p) {
  return p.x >= b.min_x && p.x <= b.max_x && p.y >= b.min_y && p.y <= b.max_y;
}

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// Andrew's monotone chain: the convex hull, counter-clockwise, without collinear points.
std::vector<glm::dvec2> convex_hull(std::vector<glm::dvec2> p) {
  std::sort(p.begin(), p.end(), [](glm::dvec2 a, glm::dvec2 b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  });
  std::vector<glm::dvec2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower hull
    while (k >= 2 && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {  // upper hull
    while (k >= t && cross(h[k - 1] - h[k - 2], p[i - 1] - h[k - 2]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

// Inside the hull, or within `tolerance_m` of it (the inclusive rule of swath.hpp).
bool in_hull(const std::vector<glm::dvec2>& hull, glm::dvec2 q, double tolerance_m) {
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const glm::dvec2 a = hull[i], b = hull[(i + 1) % hull.size()];
    const glm::dvec2 e = b - a;
    if (cross(e, q - a) < -tolerance_m * std::hypot(e.x, e.y)) return false;
  }
  return true;
}

TrackPiece piece(glm::dvec2 from, double from_heading, glm::dvec2 to, double to_heading,
                 double heading_deg, double w, double l) {
  TrackPiece p{Swath(from, from_heading, w, l), Swath(to, to_heading, w, l), to - from,
               false, from_heading != to_heading, {}, heading_deg, {}};
  p.moving = p.turning || to != from;
  p.box = merged(p.start.bounds(), p.end.bounds());  // the hull of both lies within their boxes
  if (p.turning) {
    std::vector<glm::dvec2> corners;
    for (const glm::dvec2& c : p.start.corners()) corners.push_back(c - from);
    for (const glm::dvec2& c : p.end.corners()) corners.push_back(c - from);
    p.hull = convex_hull(std::move(corners));
  }
  return p;
}

// The pose at fraction t of a segment; t == 1 gives the report itself, exactly.
glm::dvec2 position_at(const TrackPose& a, const TrackPose& b, double t, bool last) {
  return last ? b.position_m : a.position_m + (b.position_m - a.position_m) * t;
}
double heading_at(const TrackPose& a, const TrackPose& b, double turn_deg, double t, bool last) {
  return last ? b.heading_deg : base::norm360(a.heading_deg + turn_deg * t);
}

}  // namespace

double sweep_turn_error_m(double piece_turn_deg, double half_diagonal_m) {
  return half_diagonal_m * (1.0 - std::cos(std::fabs(piece_turn_deg) * kRadPerDeg / 2.0));
}

int sweep_pieces_for_turn(double turn_deg, double half_diagonal_m) {
  if (kSweepTurnTolerance_m >= half_diagonal_m) return 1;
  // The largest turn per piece within the tolerance: r (1 - cos(d / 2)) = tol.
  const double max_piece_rad = 2.0 * std::acos(1.0 - kSweepTurnTolerance_m / half_diagonal_m);
  const double needed = std::ceil(std::fabs(turn_deg) * kRadPerDeg / max_piece_rad);
  if (!(needed >= 1.0)) return 1;
  return needed >= kMaxSweepPieces ? kMaxSweepPieces : static_cast<int>(needed);
}

std::vector<TrackPiece> track_pieces(const std::vector<TrackPose>& track, bool sense_start,
                                     TrackMode mode, int substeps, double half_width_m,
                                     double length_m) {
  std::vector<TrackPiece> pieces;
  if (track.empty()) return pieces;
  const double w = half_width_m, l = length_m;
  if (sense_start && track.front().sensor_on) {
    const TrackPose& s = track.front();
    pieces.push_back(
        piece(s.position_m, s.heading_deg, s.position_m, s.heading_deg, s.heading_deg, w, l));
  }
  const double half_diagonal_m = std::hypot(w, l / 2.0);
  for (std::size_t k = 1; k < track.size(); ++k) {
    const TrackPose& a = track[k - 1];
    const TrackPose& b = track[k];
    if (!b.sensor_on) continue;  // not sensed: nothing changes over this segment
    if (b.teleport) {  // not swept: only the arrival is sensed
      pieces.push_back(
          piece(b.position_m, b.heading_deg, b.position_m, b.heading_deg, b.heading_deg, w, l));
      pieces.back().after_teleport = true;
      continue;
    }
    const double turn_deg = base::norm180(b.heading_deg - a.heading_deg);
    // Sub-stepping samples N poses; sweeping walks n pieces sharing their junction poses.
    const bool sample = mode == TrackMode::kSubsteps;
    const int n = sample ? substeps : sweep_pieces_for_turn(turn_deg, half_diagonal_m);
    glm::dvec2 from = a.position_m;
    double from_heading = a.heading_deg;
    for (int j = 1; j <= n; ++j) {
      const bool last = j == n;
      const double t = static_cast<double>(j) / n;
      const glm::dvec2 to = position_at(a, b, t, last);
      const double to_heading = heading_at(a, b, turn_deg, t, last);
      if (sample) {
        pieces.push_back(piece(to, to_heading, to, to_heading, to_heading, w, l));
      } else {
        const double middle = heading_at(a, b, turn_deg, (j - 0.5) / n, false);
        pieces.push_back(piece(from, from_heading, to, to_heading,
                               turn_deg == 0.0 ? b.heading_deg : middle, w, l));
      }
      from = to;
      from_heading = to_heading;
    }
  }
  return pieces;
}

bool walk_pieces(const std::vector<TrackPiece>& pieces, glm::dvec2 point_m, bool inside,
                 std::vector<std::uint32_t>& events) {
  for (std::uint32_t i = 0; i < pieces.size(); ++i) {
    const TrackPiece& p = pieces[i];
    if (!in_box(p.box, point_m)) {
      inside = false;
      continue;
    }
    const bool start_in = p.start.contains(point_m);
    const bool end_in = p.moving ? p.end.contains(point_m) : start_in;
    bool covered = start_in || end_in;
    if (!covered && p.turning) {
      covered = in_hull(p.hull, point_m - p.start.center(),
                        std::max(p.start.tolerance_m(), p.end.tolerance_m()));
    } else if (!covered && p.moving) {
      covered = p.start.swept_contains(p.displacement_m, point_m);
    }
    if (covered && !(inside && start_in)) events.push_back(i);
    inside = end_in;
  }
  return inside;
}

}  // namespace hazard
