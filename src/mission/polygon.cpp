#include "mission/polygon.hpp"

#include <cmath>

#include "base/text.hpp"

namespace mission {

namespace {

constexpr double kPi = 3.14159265358979323846;
/// A convex polygon turns once around: the exterior angles sum to 2*pi. Anything that winds
/// twice (a pentagram has every corner turning the same way) is rejected. Tolerance: far above
/// rounding (1e-15 per corner), far below the smallest real defect (a full extra turn).
constexpr double kWindingTolerance_rad = 1e-6;

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

double signed_area_m2(const std::vector<glm::dvec2>& v) {
  double twice = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) twice += cross(v[i], v[(i + 1) % v.size()]);
  return 0.5 * twice;
}

// The text between "pts={" and its closing brace, or the whole text when there is no "pts=".
base::Result<std::string_view> points_text(std::string_view text) {
  using R = base::Result<std::string_view>;
  const auto pts = text.find("pts=");
  if (pts == std::string_view::npos) return R::ok(base::trim(text));
  const auto open = text.find_first_not_of(" \t", pts + 4);
  if (open == std::string_view::npos || text[open] != '{')
    return R::fail("'pts=' must be followed by '{'");
  const auto close = text.find('}', open);
  if (close == std::string_view::npos) return R::fail("'pts={' has no closing '}'");
  return R::ok(text.substr(open + 1, close - open - 1));
}

}  // namespace

base::Result<ConvexPolygon> ConvexPolygon::make(std::vector<glm::dvec2> vertices_m) {
  using R = base::Result<ConvexPolygon>;
  const std::size_t n = vertices_m.size();
  if (n < 3) return R::fail("a polygon needs at least 3 vertices, got " + std::to_string(n));
  const double area = signed_area_m2(vertices_m);
  if (!(std::abs(area) > 0.0)) return R::fail("the polygon has zero area");
  const double orientation = area > 0.0 ? 1.0 : -1.0;
  double turning_rad = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec2 a = vertices_m[i];
    const glm::dvec2 b = vertices_m[(i + 1) % n];
    const glm::dvec2 c = vertices_m[(i + 2) % n];
    const double turn = cross(b - a, c - b) * orientation;
    if (turn < 0.0) {
      return R::fail("the polygon is not convex at vertex " + std::to_string((i + 1) % n + 1) +
                     " (" + base::fmt(b.x, 2) + "," + base::fmt(b.y, 2) + ")");
    }
    if (b != a && c != b) turning_rad += std::atan2(turn, glm::dot(b - a, c - b));
  }
  if (std::abs(turning_rad - 2.0 * kPi) > kWindingTolerance_rad)
    return R::fail("the polygon winds around more than once");
  return R::ok(ConvexPolygon(std::move(vertices_m), orientation));
}

base::Result<ConvexPolygon> ConvexPolygon::parse(std::string_view text) {
  using R = base::Result<ConvexPolygon>;
  auto points = parse_points(text);
  if (!points) return R::fail(std::move(points.error));
  auto polygon = make(std::move(*points.value));
  if (!polygon) return R::fail("polygon '" + std::string(base::trim(text)) + "': " + polygon.error);
  return polygon;
}

ConvexPolygon::ConvexPolygon(std::vector<glm::dvec2> vertices_m, double orientation)
    : vertices_m_(std::move(vertices_m)), orientation_(orientation) {}

Bounds ConvexPolygon::bounds() const {
  Bounds b{vertices_m_.front(), vertices_m_.front()};
  for (const auto& v : vertices_m_) {
    b.min_m = glm::min(b.min_m, v);
    b.max_m = glm::max(b.max_m, v);
  }
  return b;
}

double ConvexPolygon::area_m2() const { return std::abs(signed_area_m2(vertices_m_)); }

bool ConvexPolygon::contains(glm::dvec2 point_m) const {
  const std::size_t n = vertices_m_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec2 a = vertices_m_[i];
    const glm::dvec2 b = vertices_m_[(i + 1) % n];
    if (cross(b - a, point_m - a) * orientation_ < 0.0) return false;
  }
  return true;
}

std::string ConvexPolygon::spec_pts() const { return format_points(vertices_m_); }

std::vector<glm::dvec2> clip_to_band(const std::vector<glm::dvec2>& convex_vertices_m,
                                     glm::dvec2 axis, double low, double high) {
  // Sutherland-Hodgman against the two half-planes axis.p >= low and axis.p <= high.
  auto clip = [&](const std::vector<glm::dvec2>& in, double sign, double limit) {
    std::vector<glm::dvec2> out;
    const std::size_t n = in.size();
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec2 a = in[i];
      const glm::dvec2 b = in[(i + 1) % n];
      const double da = sign * (glm::dot(axis, a) - limit);
      const double db = sign * (glm::dot(axis, b) - limit);
      if (da >= 0.0) out.push_back(a);
      if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
  };
  return clip(clip(convex_vertices_m, 1.0, low), -1.0, high);
}

std::string format_points(const std::vector<glm::dvec2>& points_m) {
  std::string out = "pts={";
  for (std::size_t i = 0; i < points_m.size(); ++i) {
    if (i > 0) out += ':';
    out += base::fmt(points_m[i].x, 1) + "," + base::fmt(points_m[i].y, 1);
  }
  return out + "}";
}

base::Result<std::vector<glm::dvec2>> parse_points(std::string_view text) {
  using R = base::Result<std::vector<glm::dvec2>>;
  auto refused = [text](const std::string& why) {
    return R::fail("polygon '" + std::string(base::trim(text)) + "': " + why);
  };
  const auto body = points_text(text);
  if (!body) return refused(body.error);
  const std::string_view list = base::trim(*body.value);
  if (list.empty()) return refused("no vertices");
  std::vector<glm::dvec2> points;
  for (std::string_view vertex : base::split_trimmed(list, ':')) {
    const auto coords = base::split_trimmed(vertex, ',');
    const auto x = coords.size() >= 2 ? base::parse_number(coords[0]) : std::nullopt;
    const auto y = coords.size() >= 2 ? base::parse_number(coords[1]) : std::nullopt;
    const bool z_ok = coords.size() == 2 || (coords.size() == 3 && base::parse_number(coords[2]));
    if (!x || !y || !z_ok) {
      return refused("bad vertex '" + std::string(base::trim(vertex)) + "' (expected x,y)");
    }
    points.emplace_back(*x, *y);
  }
  return R::ok(std::move(points));
}

}  // namespace mission
