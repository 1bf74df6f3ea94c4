#pragma once
// The hazard-field generator (docs/gen_hazards.md; docs/differences.md D30, D31).
//
// Contract
// - Deterministic: the output is a pure function of the configuration and the seed, the same
//   on every platform. Every draw is mission::uniform01(seed, stream, counter) with the stream
//   naming (object index, purpose), so an object's position, resemblance and aspect do not
//   depend on the options that drive the other purposes (adding --exp moves no object).
// - Position: uniform over the union of the regions, by rejection sampling: a region is chosen
//   with probability proportional to its area, a point is drawn uniformly in its bounding box
//   and kept if the region contains it; where k regions overlap the point is kept with
//   probability 1/k, which makes the density uniform over the union. The kept point is then
//   rounded to whole metres (the original's habit), so each coordinate can
//   move up to 0.5 m, possibly outside the region (N16).
// - Never a hang: a region that fills less than `min_fill_fraction` of its bounding box is
//   rejected before any draw, and each object gets at most `max_attempts` tries.
// - Labels: random integers below a bound that grows with the labels issued so far (as in
//   the original), unique across all sets; after `max_label_draws` collisions the smallest free
//   integer below the bound is used (never `label_error`).
// - Resemblance (manual 6.3): hr = q^exp with q uniform on {0, 0.001, ..., 0.999}.
// - Aspect (manual 7): values in tenths of a degree, so every written value
//   is exact to 0.1 and the window checks of the hazard-line parser hold on the written text.
// Rejected alternative: sampling in the bounding box of all regions (the original) wastes
// almost every draw when two small regions lie far apart.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "hazard/hazard_object.hpp"
#include "base/result.hpp"
#include "options.hpp"

namespace gen_hazards {

/// Draws of one label before falling back to the smallest free one (the original's limit).
inline constexpr int kMaxLabelDraws = 1000;

/// Bounds that keep generation finite. The defaults make a placement failure for an accepted
/// region practically impossible: with fill >= 1e-3 an object fails 1e5 tries with probability
/// below e^-100. Tests lower them to reach the fallback and error paths.
struct GeneratorLimits {
  std::uint64_t max_attempts = 100'000;  ///< placement tries per object
  double min_fill_fraction = 1e-3;       ///< region area / bounding-box area
  int max_label_draws = kMaxLabelDraws;  ///< label draws before the smallest free label
};
/// Steps of the resemblance base q, as in the original: q = k / 1000, k in [0, 999].
inline constexpr int kResemblanceSteps = 1000;
/// The smallest label bound (the original's); it grows tenfold as labels are issued.
inline constexpr std::uint64_t kFirstLabelBound = 100;

/// One generated object.
struct GeneratedObject {
  hazard::HazardObject object;  ///< rounded position, label, type, hr, aspect triple
  glm::dvec2 drawn_m{0.0, 0.0}; ///< the accepted point before rounding (inside a region)
  std::size_t set_index = 0;    ///< which --objects set (argument order)
};

/// Generates every object in output order and hands each to `sink`. Fails (and stops), naming
/// the argument at fault, if a region is too thin or an object cannot be placed.
base::Result<void> generate(const GeneratorConfig& config,
                            const std::function<void(const GeneratedObject&)>& sink,
                            const GeneratorLimits& limits = {});

/// Collects generate()'s objects.
base::Result<std::vector<GeneratedObject>> generate_objects(const GeneratorConfig& config,
                                                            const GeneratorLimits& limits = {});

/// The whole hazard file (D30): `header` + "\n", one `region = pts={...}` line per region,
/// then one `hazard = ...` line per object, each formatted by hazard::format_hazard_line.
base::Result<std::string> build_hazard_file(const std::string& header,
                                            const GeneratorConfig& config,
                                            const GeneratorLimits& limits = {});

// ---- The formulas, exposed for tests ----

/// The label bound after `issued` labels: 100 while fewer than 100 were issued, 1000 while
/// fewer than 1000, and so on (the original stopped at 100000; we continue, so a bound is
/// always above the count and a free label always exists).
std::uint64_t label_bound(std::uint64_t issued);

/// hr = (k / 1000)^exp for k in [0, 999] (manual 6.3).
double resemblance(int step, double exp);

/// An aspect window in tenths of a degree.
struct AspectWindowTenths {
  int min_tenths = 0;
  int max_tenths = 0;
};

/// Makes a drawn window valid for the sensor (aspect_min <= aspect_max, both in [0, 90],
/// sum <= 90): inputs already satisfy 0 <= min <= max <= 900; when min + max > 900 both are
/// lowered by half the excess (max takes the odd tenth), which keeps max - min, the width of
/// the degradation ramp. The original printed `Illegal aspect range` into the file instead.
AspectWindowTenths resolve_aspect_window(AspectWindowTenths drawn);

}  // namespace gen_hazards
