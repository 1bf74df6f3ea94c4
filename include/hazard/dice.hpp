#pragma once
// Dice: counter-based random numbers (differences.md "Passes, dice and reproducibility").
//
// Contract: every die is a pure function of (seed, vehicle name, object label, pass, purpose).
// No internal id, load order, time, tick rate or message order enters, so the same seed and the
// same sensor events give the same outcomes however the mail was timed.
// Algorithm: the names are hashed once (FNV-1a 64, stored with the vehicle and the object); the
// key is folded in with the SplitMix64 finaliser after each component (seed, vehicle, label,
// pass, purpose), which avalanches every input bit into the 64-bit result.
// Quantisation keeps the original's (docs/differences.md, "Random numbers and
// reproducibility"), so probabilities behave as before:
//   detection       u = k / 10000, k in [0, 9999], detect iff u < p
//   classification  v = k / 10000, k in [0, 10000], correct iff v <= p
// k is the 64-bit value modulo 10000 (or 10001); the modulo bias is below 1e-15.
// Rejected alternatives: a stateful generator (outcomes would depend on event order) and
// std::hash (not specified, differs between library versions).

#include <cstdint>
#include <string_view>

namespace hazard {

/// Stable 64-bit FNV-1a hash of a name (vehicle name or object label).
std::uint64_t hash_name(std::string_view name);

/// SplitMix64 finaliser: a bijective 64-bit mixer.
std::uint64_t mix64(std::uint64_t x);

enum class DiePurpose : std::uint64_t { kDetection = 1, kClassification = 2 };

/// Detection dice steps: 10000 values 0, 0.0001, ..., 0.9999.
inline constexpr std::uint64_t kDetectionDieSteps = 10000;
/// Classification dice steps: 10001 values 0, 0.0001, ..., 1.
inline constexpr std::uint64_t kClassificationDieSteps = 10001;
inline constexpr double kDieResolution = 10000.0;

/// The exact probability that a detection die succeeds for threshold p: P(u < p) with the
/// quantisation above (for example 0.6561 -> 0.6561, 0.47805 -> 0.4781).
double detection_success_probability(double p);
/// The exact probability that a classification die succeeds: P(v <= p), v over 10001 values.
double classification_success_probability(double p);

class Dice {
 public:
  explicit Dice(std::uint64_t seed) : seed_(seed) {}
  std::uint64_t seed() const { return seed_; }

  /// The raw 64-bit draw for a key.
  std::uint64_t draw(std::uint64_t vehicle_hash, std::uint64_t label_hash, std::uint32_t pass,
                     DiePurpose purpose) const;
  /// u in {0, 0.0001, ..., 0.9999}: detect iff u < p.
  double detection_u(std::uint64_t vehicle_hash, std::uint64_t label_hash,
                     std::uint32_t pass) const;
  /// v in {0, 0.0001, ..., 1}: correct iff v <= p.
  double classification_v(std::uint64_t vehicle_hash, std::uint64_t label_hash,
                          std::uint32_t pass) const;

 private:
  std::uint64_t seed_;
};

}  // namespace hazard
