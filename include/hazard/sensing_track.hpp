#pragma once
// Sensing along a track: sub-stepping and the swept swath (`swath_substeps`,
// `swath_sweep`). The default, sampling at each iteration's latest pose (docs/accuracy.md), is the
// engine's own path and does not use this file.
//
// Contract (the rule, also in docs/accuracy.md):
// - Track. With either mode on, a vehicle's track is the polyline through its node reports,
//   each kept with its pose and the sensor gates evaluated when it arrived (speed of that
//   report; turn rate over the 2 s before it). The segment ending at a report is sensed only if
//   that report's gates pass; over a segment that is not sensed nothing changes
//   (differences.md "Pass": inside/outside frozen, as in a blackout). Between two reports the
//   pose moves linearly in position and turns linearly along the shorter way (359.9 -> 0.1 is
//   +0.2 deg).
// - Evaluation. At each iteration the engine walks the segments received since the previous one
//   (so outcomes do not depend on the iteration rate, only on the reports), with the setting in
//   force at that iteration. A vehicle's first evaluation, and the first after an iteration at
//   which it was inactive, also senses the track's start pose itself.
// - Sub-stepping (N = swath_substeps): each sensed segment is sampled at N poses, t = 1/N, ...,
//   1 (the last is the report itself). A sensor event is an object inside at a sample and not
//   inside at the previous one: sampling, N times per report interval.
// - Sweeping: each sensed segment is one piece when the heading does not change (a translation:
//   the swept area is the rectangle's Minkowski sum with the segment, which is the convex hull of
//   the start and end rectangles, tested exactly by a slab test, Swath::swept_contains). A
//   turning segment is split into n pieces of equal turn d = |dh| / n, and a piece covers the
//   convex hull of its start and end rectangles (both at their exact interpolated poses, so
//   consecutive pieces share their junction rectangle: the swath never jumps). Error bound: a
//   point of the swath moving from its start to its end position strays from the straight chord
//   between them by the sagitta of its rotation only (the translation is linear), so the hull
//   and the linearly turning swath lie within r (1 - cos(d / 2)) of each other, r =
//   sqrt(W^2 + (L/2)^2) the swath's half diagonal. n is the smallest count that makes this at
//   most kSweepTurnTolerance_m (5 cm: 7.2 deg per piece at r = 25 m), capped at
//   kMaxSweepPieces; only objects that close to the swept area's boundary may be counted
//   differently.
// - Passes. Within a piece an object's time inside is taken as one interval (exact for a
//   translation: a rectangle moving along a line meets a point in a convex set of times; within
//   the bound above for a turning piece). An object covered by a piece enters (a sensor event: a
//   new pass, a new die) unless it was inside before the piece and is inside at its start; its
//   state after the piece is "inside at the piece's end". So an object the swath passed over and
//   left between two reports is an event, and one that stays inside is one pass however many
//   reports it spans. Dice keys are unchanged: (seed, vehicle, label, pass, purpose), so the same
//   sensor events roll the same dice.
// - Teleports. A report marked `teleport` (a jump no vehicle can make, engine.hpp
//   kMaxSweepJump_m) ends an unsensed segment: nothing between the two reports is swept or
//   sampled; the arrival is sensed as one sample (inside/outside there, as a start pose), so a
//   10 km jump over a dense field costs one swath, not the whole jump.
// - Order and heading. Events of one evaluation are rolled in the order of the pieces, then of
//   object load order; the heading used for aspect and for the classification credit is the
//   piece's heading (the reports' heading on a straight segment).
// Rejected alternatives: sweeping the whole track since the last iteration as one polygon (it
// would merge separate passes); turning pieces translated at a fixed heading (the heading jumps
// at every junction, and each jump re-covers objects an edge has just left: phantom passes);
// conservative corner inflation (it adds false events).

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "hazard/spatial_grid.hpp"
#include "hazard/swath.hpp"

namespace hazard {

/// One node report on a vehicle's track (only while a track mode is on).
struct TrackPose {
  glm::dvec2 position_m{0.0, 0.0};
  double heading_deg = 0.0;  ///< [0, 360)
  bool sensor_on = true;     ///< the gates when this report arrived
  /// The vehicle jumped to this report (Engine: kMaxSweepJump_m): the segment before it is not
  /// swept or sub-stepped; the report itself is sensed as one sample, as a start pose is.
  bool teleport = false;
};

enum class TrackMode { kSubsteps, kSweep };

/// Turning segments are swept in pieces whose error is at most this (see the file comment).
inline constexpr double kSweepTurnTolerance_m = 0.05;
/// Bound on the pieces of one turning segment (work per report); beyond it the error bound is
/// r (1 - cos(|dh| / (2 kMaxSweepPieces))): 7.5 mm for a half turn at r = 25 m.
inline constexpr int kMaxSweepPieces = 64;

/// One sensed piece of a track: the swath moving from `start` to `end`. A sample (sub-stepping,
/// or a start pose) is a piece that does not move.
struct TrackPiece {
  Swath start;
  Swath end;
  glm::dvec2 displacement_m{0.0, 0.0};  ///< end centre - start centre
  bool moving = false;                  ///< the centre moves or the heading turns
  bool turning = false;                 ///< the heading turns (the hull test applies)
  /// Turning pieces: the convex hull of both rectangles, counter-clockwise, relative to the
  /// start centre (so it keeps its precision at UTM coordinates).
  std::vector<glm::dvec2> hull;
  double heading_deg = 0.0;  ///< for aspect and credits: the piece's middle heading
  Box box;                   ///< around everything the piece covers
  /// The sample at a teleport's arrival: the area between it and the previous piece is not
  /// covered, so candidates are looked up per run of pieces between teleports.
  bool after_teleport = false;
};

/// The pieces of `track` (track[0] is where the previous evaluation ended): the start pose when
/// `sense_start` and its gates pass, then per sensed segment N samples or the sweep pieces.
/// Swath `half_width_m` W > 0, `length_m` L > 0; `substeps` >= 1 for kSubsteps.
std::vector<TrackPiece> track_pieces(const std::vector<TrackPose>& track, bool sense_start,
                                     TrackMode mode, int substeps, double half_width_m,
                                     double length_m);

/// Walks one object through the pieces from state `inside`; appends the index of every piece
/// in which it enters (a sensor event) to `events`, and returns whether it is inside at the end.
bool walk_pieces(const std::vector<TrackPiece>& pieces, glm::dvec2 point_m, bool inside,
                 std::vector<std::uint32_t>& events);

/// How many pieces sweep a turn of `turn_deg` (any sign) with a swath of half diagonal
/// `half_diagonal_m` r: the fewest n with r (1 - cos(|turn| / (2 n))) <= tol, in
/// [1, kMaxSweepPieces].
int sweep_pieces_for_turn(double turn_deg, double half_diagonal_m);
/// The error bound of a turning piece of `piece_turn_deg`: r (1 - cos(|turn| / 2)), metres.
double sweep_turn_error_m(double piece_turn_deg, double half_diagonal_m);

}  // namespace hazard
