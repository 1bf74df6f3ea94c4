#pragma once
// Convex polygons of the mission: search regions (hazard file `region = ...`, uFldHazardMgr's
// `region`, UHZ_MISSION_PARAMS `search_region=`), survey areas and the grader's transit lane.
//
// Contract
// - Text forms accepted (the MOOS-IvP habits): `x1,y1:x2,y2:...` and `pts={x1,y1:x2,y2:...}`,
//   the latter optionally among other `key=value` fields (`label=`, colours), which are ignored.
//   A vertex is `x,y` or `x,y,z` (z ignored). Numbers follow differences.md "Numbers".
// - A polygon is valid when it has at least 3 vertices, is convex (no reflex corner, either
//   winding) and has a positive area; collinear vertices on an edge are allowed.
// - Containment is inclusive of the boundary (the original's habit; docs/differences.md).
// - The spec text is `pts={x1,y1:...}` with each coordinate FMT(.,1) (gen_hazards' region line),
//   vertices in the order given.

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"

namespace mission {

/// Axis-aligned bounds in metres.
struct Bounds {
  glm::dvec2 min_m{0.0, 0.0};
  glm::dvec2 max_m{0.0, 0.0};
};

class ConvexPolygon {
 public:
  /// The polygon of these vertices, or why they are not a valid convex polygon (the error
  /// names the offending vertex or property).
  static base::Result<ConvexPolygon> make(std::vector<glm::dvec2> vertices_m);

  /// Parses the MOOS text forms described above. The error names the text and the problem.
  static base::Result<ConvexPolygon> parse(std::string_view text);

  const std::vector<glm::dvec2>& vertices() const { return vertices_m_; }
  Bounds bounds() const;
  double area_m2() const;
  /// Inclusive containment (points on an edge or a vertex are inside).
  bool contains(glm::dvec2 point_m) const;
  /// `pts={x1,y1:x2,y2:...}`, coordinates FMT(.,1).
  std::string spec_pts() const;

 private:
  explicit ConvexPolygon(std::vector<glm::dvec2> vertices_m, double orientation);
  std::vector<glm::dvec2> vertices_m_;
  double orientation_ = 1.0;  ///< +1 counter-clockwise, -1 clockwise
};

/// The part of a convex polygon whose coordinate along `axis` (a unit vector) lies in
/// [low, high]: a convex polygon (possibly degenerate or empty), as plain vertices.
std::vector<glm::dvec2> clip_to_band(const std::vector<glm::dvec2>& convex_vertices_m,
                                     glm::dvec2 axis, double low, double high);

/// The vertices of a list of points as `pts={x1,y1:x2,y2}` with FMT(.,1): also the text form of
/// a waypoint list (MOOS seglist).
std::string format_points(const std::vector<glm::dvec2>& points_m);

/// Parses a point list in the forms accepted for polygons, without any shape requirement
/// (a waypoint list may have one point). An empty list is an error.
base::Result<std::vector<glm::dvec2>> parse_points(std::string_view text);

}  // namespace mission
