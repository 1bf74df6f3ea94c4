// Visuals (docs/messages.md, "Visuals"; docs/differences.md D19): object markers and aspect axes,
// the swath polygon, and the detection and classification cue circles.
#include "visuals.hpp"

#include <algorithm>

#include "hazard/engine.hpp"
#include "hazard/messages/view_marker.hpp"
#include "hazard/messages/view_polygon.hpp"
#include "hazard/messages/view_seglist.hpp"
#include "base/text.hpp"

namespace hazard {

namespace {

// Visual constants of the original (docs/messages.md) and the colours of differences.md D19.
constexpr double kCircleRadius_m = 10.0;
constexpr int kDetectionCircleVertices = 12;
constexpr int kClassificationCircleVertices = 5;  // drawn as a pentagon
constexpr double kCircleEdgeSize = 1.0;
constexpr double kCircleTransparency = 0.3;
constexpr double kAffectedEdgeSize = 2.0;        // aspect-affected classification
constexpr double kAffectedTransparency = 0.5;
constexpr double kSwathEdgeSize = 0.0;
constexpr double kMarkerFillWithoutHr = 0.5;     // benign marker fill: 1 - hr, hr absent -> 0.5
constexpr double kSeglistPartialLength_m = 15.0; // aspect axis without a window
constexpr double kSeglistBaseLength_m = 5.0;     // + 25 * (mean window / 90)
constexpr double kSeglistWindowLength_m = 25.0;
constexpr double kQuarterTurnDeg = 90.0;


ViewCircle circle_at(glm::dvec2 position, int vertices, double now_s) {
  ViewCircle c;
  c.x_m = position.x;
  c.y_m = position.y;
  c.radius_m = kCircleRadius_m;
  c.vertices = vertices;
  c.time_s = now_s;
  c.edge_size = kCircleEdgeSize;
  c.fill_transparency = kCircleTransparency;
  return c;
}

glm::dvec2 project(glm::dvec2 from, double heading_deg, double distance_m) {
  const SinCos sc = sin_cos_deg(heading_deg);
  return {from.x + distance_m * sc.sin, from.y + distance_m * sc.cos};
}

}  // namespace

ViewCircle detection_circle(glm::dvec2 position, double now_s, std::optional<double> duration_s,
                            bool changed_by_aspect) {
  ViewCircle c = circle_at(position, kDetectionCircleVertices, now_s);
  c.duration_s = duration_s;
  // Pink when only the degraded ROC produced the detection (manual 7.3, D5).
  c.edge_color = c.fill_color = changed_by_aspect ? "pink" : "white";
  return c;
}

ViewCircle classification_circle(glm::dvec2 position, double now_s, ObjectType reported,
                                 bool aspect_affected) {
  ViewCircle c = circle_at(position, kClassificationCircleVertices, now_s);
  c.edge_color = c.fill_color = reported == ObjectType::kHazard ? "yellow" : "green";
  if (aspect_affected) {
    c.fill_color = "pink";
    c.edge_size = kAffectedEdgeSize;
    c.fill_transparency = kAffectedTransparency;
  }
  return c;
}

void Engine::handle_viewer_connect(Outputs& out) { restart_field_visuals(out); }

void Engine::restart_field_visuals(Outputs& out) {
  if (!effects_.hazard_markers) return;
  visuals_cursor_ = 0;
  post_field_visuals_batch(out);
}

void Engine::post_field_visuals_batch(Outputs& out) {
  const std::size_t end = std::min(field_.size(), visuals_cursor_ + kFieldVisualsPerIteration);
  for (; visuals_cursor_ < end; ++visuals_cursor_) {
    post_object_visuals(static_cast<ObjectId>(visuals_cursor_), out);
  }
}

void Engine::post_object_visuals(ObjectId id, Outputs& out) const {
  const HazardObject o = field_.object(id);
  const bool hazard = o.is_hazard();
  ViewMarker m;
  m.x_m = o.x_m;
  m.y_m = o.y_m;
  m.width_m = o.marker_width_m.value_or(hazard ? config_.hazard_marker_width_m
                                               : config_.benign_marker_width_m);
  m.primary_color = o.color.value_or(hazard ? config_.hazard_color : config_.benign_color);
  m.shape = o.shape.value_or(hazard ? config_.hazard_shape : config_.benign_shape);
  m.label = o.label;
  if (!hazard) m.fill_transparency = 1.0 - o.resemblance.value_or(kMarkerFillWithoutHr);
  out.post("VIEW_MARKER", format_view_marker(m));
  if (!o.aspect_deg) return;
  // The aspect axis (docs/messages.md: every aspect, 0 included).
  const double length_m =
      (o.aspect_min_deg && o.aspect_max_deg)
          ? kSeglistBaseLength_m + kSeglistWindowLength_m *
                                       ((*o.aspect_min_deg + *o.aspect_max_deg) / 2.0) /
                                       kQuarterTurnDeg
          : kSeglistPartialLength_m;
  const glm::dvec2 at{o.x_m, o.y_m};
  ViewSeglist s;
  s.points = {project(at, *o.aspect_deg, length_m), project(at, *o.aspect_deg + 180.0, length_m)};
  s.edge_color = "gray70";
  s.edge_size = 1.0;
  out.post("VIEW_SEGLIST", format_view_seglist(s));
}

void Engine::post_swath(const VehicleState& v, const Swath& swath, bool on, Outputs& out) const {
  const SensorSetting& s = *v.setting;
  // Every vehicle's swath, every iteration: one polygon per thread is reused, so its points,
  // label and msg keep their storage (the text itself is built anew, as always).
  thread_local ViewPolygon p;
  const auto corners = swath.corners();
  p.points.assign(corners.begin(), corners.end());
  p.label.assign("sensor_swath_").append(v.name);
  // Appended into the reused msg (no temporary strings).
  p.msg.clear();
  if (config_.show_pd && config_.show_pfa) {
    base::append_fix(p.msg, s.pd, 2);
    p.msg += '/';
    base::append_fix(p.msg, s.pfa, 2);
  } else if (config_.show_pd) {
    base::append_fix(p.msg, s.pd, 2);
  } else if (config_.show_pfa) {
    p.msg += "pfa=";
    base::append_fix(p.msg, s.pfa, 2);
  } else {
    p.msg = "_null_";  // the original's "no label" word
  }
  p.edge_color = "green";
  p.fill_color = on ? "white" : "red";
  p.vertex_size = 0.0;
  p.edge_size = kSwathEdgeSize;
  p.fill_transparency = config_.swath_transparency;
  out.post("VIEW_POLYGON", format_view_polygon(p));
}

}  // namespace hazard
