#pragma once
// The engine's cue circles (internal to libhazard; visuals.cpp holds every visual rule).

#include <optional>

#include <glm/vec2.hpp>

#include "hazard/hazard_object.hpp"
#include "hazard/messages/view_circle.hpp"

namespace hazard {

/// The circle of a detection at `now_s`: white, or pink when only the aspect-degraded ROC
/// produced it; it lasts `duration_s` (nullopt: no limit).
ViewCircle detection_circle(glm::dvec2 position, double now_s, std::optional<double> duration_s,
                            bool changed_by_aspect);
/// The pentagon of a released classification answer: yellow for hazard, green for benign;
/// pink and bolder when the aspect effect changed the answer.
ViewCircle classification_circle(glm::dvec2 position, double now_s, ObjectType reported,
                                 bool aspect_affected);

}  // namespace hazard
