#include "generator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hazard/messages/hazard_line.hpp"
#include "base/text.hpp"
#include "mission/random.hpp"

namespace gen_hazards {

namespace {

/// What a draw is for; with the object's index it names the random stream (see the contract).
enum Purpose : std::uint64_t { kPosition = 0, kLabel = 1, kResemblance = 2, kAspect = 3 };
constexpr std::uint64_t kPurposeCount = 4;
/// Counters one placement attempt uses: region choice, x, y, overlap acceptance.
constexpr std::uint64_t kDrawsPerAttempt = 4;
/// Aspect values are kept in tenths of a degree (the original snapped them to 0.1).
constexpr double kTenthsPerDeg = 10.0;
constexpr long kFullTurnTenths = 3600;
constexpr long kMaxWindowTenths = 900;
/// Growth factor of the label bound (100, 1000, 10000, ...).
constexpr std::uint64_t kLabelBoundGrowth = 10;

/// Uniform in [0, 1) for (object, purpose, counter) under the run's seed.
double draw(std::uint64_t seed, std::uint64_t object_index, Purpose purpose,
            std::uint64_t counter) {
  return mission::uniform01(seed, object_index * kPurposeCount + purpose, counter);
}

/// floor(u * n) in [0, n - 1]. u * n is exact up to one rounding, the same on every IEEE
/// platform; the min guards the one case where it rounds up to n.
std::uint64_t scaled_index(double u, std::uint64_t n) {
  const auto k = static_cast<std::uint64_t>(u * static_cast<double>(n));
  return std::min(k, n - 1);
}

/// Unique integer labels (as the original draws them, without `label_error`).
class LabelPool {
 public:
  LabelPool(std::uint64_t seed, int max_draws) : seed_(seed), max_draws_(max_draws) {}

  std::uint64_t next(std::uint64_t object_index) {
    const std::uint64_t bound = label_bound(issued_);
    if (used_.size() < bound) used_.resize(bound, false);
    for (int d = 0; d < max_draws_; ++d) {
      const std::uint64_t candidate =
          scaled_index(draw(seed_, object_index, kLabel, static_cast<std::uint64_t>(d)), bound);
      if (!used_[candidate]) return take(candidate);
    }
    // Deterministic fallback: labels are never returned, so the lowest free one only grows.
    while (used_[lowest_free_]) ++lowest_free_;
    return take(lowest_free_);
  }

 private:
  std::uint64_t take(std::uint64_t label) {
    used_[label] = true;
    ++issued_;
    return label;
  }

  std::uint64_t seed_;
  int max_draws_;
  std::vector<bool> used_;
  std::uint64_t issued_ = 0;
  std::uint64_t lowest_free_ = 0;
};

/// The regions with what rejection sampling needs: bounding boxes and cumulative areas.
class PointSampler {
 public:
  PointSampler(const std::vector<Region>& regions, std::uint64_t seed, std::uint64_t max_attempts)
      : regions_(regions), seed_(seed), max_attempts_(max_attempts), failures_(regions.size(), 0) {
    double total = 0.0;
    for (const auto& region : regions_) {
      total += region.polygon.area_m2();
      cumulative_area_m2_.push_back(total);
    }
  }

  /// A point inside the union, or nullopt after max_attempts tries.
  std::optional<glm::dvec2> place(std::uint64_t object_index) {
    for (std::uint64_t attempt = 0; attempt < max_attempts_; ++attempt) {
      const std::uint64_t c = attempt * kDrawsPerAttempt;
      const std::size_t i = choose_region(draw(seed_, object_index, kPosition, c));
      const mission::Bounds box = regions_[i].polygon.bounds();
      const glm::dvec2 u{draw(seed_, object_index, kPosition, c + 1),
                         draw(seed_, object_index, kPosition, c + 2)};
      const glm::dvec2 point = box.min_m + u * (box.max_m - box.min_m);
      if (!regions_[i].polygon.contains(point)) {
        ++failures_[i];
        continue;
      }
      const std::size_t overlapping = regions_containing(point);
      if (overlapping > 1 &&
          draw(seed_, object_index, kPosition, c + 3) * static_cast<double>(overlapping) >= 1.0) {
        continue;  // keep with probability 1/k: uniform density where regions overlap
      }
      return point;
    }
    return std::nullopt;
  }

  /// The region that rejected the most candidates (the one to blame when placement fails).
  const Region& worst_region() const {
    const auto worst = std::max_element(failures_.begin(), failures_.end());
    return regions_[static_cast<std::size_t>(worst - failures_.begin())];
  }

 private:
  std::size_t choose_region(double u) const {
    const double target = u * cumulative_area_m2_.back();
    for (std::size_t i = 0; i < cumulative_area_m2_.size(); ++i) {
      if (target < cumulative_area_m2_[i]) return i;
    }
    return cumulative_area_m2_.size() - 1;
  }

  std::size_t regions_containing(glm::dvec2 point) const {
    return static_cast<std::size_t>(std::count_if(
        regions_.begin(), regions_.end(), [&](const Region& r) { return r.polygon.contains(point); }));
  }

  const std::vector<Region>& regions_;
  std::uint64_t seed_;
  std::uint64_t max_attempts_;
  std::vector<double> cumulative_area_m2_;
  std::vector<std::uint64_t> failures_;
};

/// A region whose area is a tiny part of its bounding box would take very many draws per
/// object (the original could spin for ever); reject it up front, naming it.
base::Result<void> check_fill(const Region& region, double min_fill_fraction) {
  const mission::Bounds box = region.polygon.bounds();
  const glm::dvec2 size = box.max_m - box.min_m;
  const double fill = region.polygon.area_m2() / (size.x * size.y);
  if (fill >= min_fill_fraction) return base::Result<void>::ok();  // false for NaN sizes too
  return base::Result<void>::fail("'" + region.argument + "': the polygon covers only " +
                                  base::fmt(fill, 6) + " of its bounding box (at least " +
                                  base::fmt(min_fill_fraction, 6) +
                                  " is needed to place points in it); it is too thin");
}

long tenths(double deg) { return std::lround(deg * kTenthsPerDeg); }

/// The original's aspect draw with the decisions of docs/gen_hazards.md: aspect modulo 360 (a value
/// that rounds to 360.0 becomes 0 rather than being dropped), aspect_max from its own base, and a
/// window that breaks min + max <= 90 resolved instead of printed as an error line.
void draw_aspect(const AspectOptions& a, std::uint64_t seed, std::uint64_t object_index,
                 hazard::HazardObject& object) {
  const double u1 = draw(seed, object_index, kAspect, 0);
  const double u2 = draw(seed, object_index, kAspect, 1);
  const double u3 = draw(seed, object_index, kAspect, 2);
  const long aspect = tenths(base::norm360(a.base_deg + u1 * a.range_deg)) % kFullTurnTenths;
  const double min_deg = std::clamp(a.min_base_deg + u2 * a.min_range_deg, 0.0, kMaxAspectWindowDeg);
  const long min_t = tenths(min_deg);
  const double max_floor_deg =
      std::max(static_cast<double>(min_t) / kTenthsPerDeg, a.max_base_deg.value_or(0.0));
  const long max_t = std::clamp(tenths(max_floor_deg + u3 * a.max_range_deg), min_t, kMaxWindowTenths);
  const AspectWindowTenths window =
      resolve_aspect_window({static_cast<int>(min_t), static_cast<int>(max_t)});
  object.aspect_deg = static_cast<double>(aspect) / kTenthsPerDeg;
  object.aspect_min_deg = window.min_tenths / kTenthsPerDeg;
  object.aspect_max_deg = window.max_tenths / kTenthsPerDeg;
}

}  // namespace

std::uint64_t label_bound(std::uint64_t issued) {
  std::uint64_t bound = kFirstLabelBound;
  const std::uint64_t largest = std::numeric_limits<std::uint64_t>::max() / kLabelBoundGrowth;
  while (issued >= bound && bound <= largest) bound *= kLabelBoundGrowth;
  return bound;
}

double resemblance(int step, double exp) {
  return std::pow(static_cast<double>(step) / kResemblanceSteps, exp);
}

AspectWindowTenths resolve_aspect_window(AspectWindowTenths drawn) {
  const int excess = drawn.min_tenths + drawn.max_tenths - static_cast<int>(kMaxWindowTenths);
  if (excess <= 0) return drawn;
  // min == max implies an even excess, so min <= max still holds afterwards.
  return {drawn.min_tenths - excess / 2, drawn.max_tenths - (excess - excess / 2)};
}

base::Result<void> generate(const GeneratorConfig& config,
                            const std::function<void(const GeneratedObject&)>& sink,
                            const GeneratorLimits& limits) {
  using Outcome = base::Result<void>;
  if (total_objects(config) == 0) return Outcome::ok();
  if (config.regions.empty()) {
    return Outcome::fail("'" + config.sets.front().argument + "': objects need a --polygon");
  }
  for (const auto& region : config.regions) {
    if (auto fill = check_fill(region, limits.min_fill_fraction); !fill) return fill;
  }
  PointSampler sampler(config.regions, config.seed, limits.max_attempts);
  LabelPool labels(config.seed, limits.max_label_draws);
  std::uint64_t index = 0;
  for (std::size_t s = 0; s < config.sets.size(); ++s) {
    const ObjectSet& set = config.sets[s];
    for (std::uint64_t n = 0; n < set.count; ++n, ++index) {
      const auto point = sampler.place(index);
      if (!point) {
        return Outcome::fail("'" + sampler.worst_region().argument +
                             "': could not place object " + std::to_string(n + 1) + " of '" +
                             set.argument + "' in " + std::to_string(limits.max_attempts) +
                             " attempts; the polygon is too thin");
      }
      GeneratedObject out;
      out.drawn_m = *point;
      out.set_index = s;
      out.object.x_m = std::round(point->x);  // whole metres, halves away from zero
      out.object.y_m = std::round(point->y);
      out.object.label = std::to_string(labels.next(index));
      out.object.type = set.type;
      if (config.resemblance_exp) {
        const auto step = static_cast<int>(
            scaled_index(draw(config.seed, index, kResemblance, 0), kResemblanceSteps));
        out.object.resemblance = resemblance(step, *config.resemblance_exp);
      }
      if (config.aspect) draw_aspect(*config.aspect, config.seed, index, out.object);
      sink(out);
    }
  }
  return Outcome::ok();
}

base::Result<std::vector<GeneratedObject>> generate_objects(const GeneratorConfig& config,
                                                            const GeneratorLimits& limits) {
  std::vector<GeneratedObject> objects;
  auto done = generate(config, [&](const GeneratedObject& o) { objects.push_back(o); }, limits);
  if (!done) return base::Result<std::vector<GeneratedObject>>::fail(std::move(done.error));
  return base::Result<std::vector<GeneratedObject>>::ok(std::move(objects));
}

base::Result<std::string> build_hazard_file(const std::string& header,
                                            const GeneratorConfig& config,
                                            const GeneratorLimits& limits) {
  std::string out = header + "\n";
  for (const auto& region : config.regions) out += "region = " + region.polygon.spec_pts() + "\n";
  auto done = generate(
      config,
      [&](const GeneratedObject& o) {
        out += "hazard = " + hazard::format_hazard_line(o.object) + "\n";
      },
      limits);
  if (!done) return base::Result<std::string>::fail(std::move(done.error));
  return base::Result<std::string>::ok(std::move(out));
}

}  // namespace gen_hazards
