#include "hazard/dice.hpp"

namespace hazard {

namespace {
constexpr std::uint64_t kFnvOffset = 14695981039346656037ull;
constexpr std::uint64_t kFnvPrime = 1099511628211ull;
// Distinguishes the seed stage from the others, so seed 0 does not start from a zero state.
constexpr std::uint64_t kSeedSalt = 0x9e3779b97f4a7c15ull;
}  // namespace

double detection_success_probability(double p) {
  std::uint64_t k = 0;  // the number of steps k with k / 10000 < p
  while (k < kDetectionDieSteps && static_cast<double>(k) / kDieResolution < p) ++k;
  return static_cast<double>(k) / static_cast<double>(kDetectionDieSteps);
}

double classification_success_probability(double p) {
  std::uint64_t k = 0;  // the number of steps k with k / 10000 <= p
  while (k < kClassificationDieSteps && static_cast<double>(k) / kDieResolution <= p) ++k;
  return static_cast<double>(k) / static_cast<double>(kClassificationDieSteps);
}

std::uint64_t hash_name(std::string_view name) {
  std::uint64_t h = kFnvOffset;
  for (char c : name) {
    h ^= static_cast<unsigned char>(c);
    h *= kFnvPrime;
  }
  return h;
}

std::uint64_t mix64(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  x ^= x >> 31;
  return x;
}

std::uint64_t Dice::draw(std::uint64_t vehicle_hash, std::uint64_t label_hash, std::uint32_t pass,
                         DiePurpose purpose) const {
  std::uint64_t h = mix64(seed_ + kSeedSalt);
  h = mix64(h ^ vehicle_hash);
  h = mix64(h ^ label_hash);
  h = mix64(h ^ pass);
  h = mix64(h ^ static_cast<std::uint64_t>(purpose));
  return h;
}

double Dice::detection_u(std::uint64_t vehicle_hash, std::uint64_t label_hash,
                         std::uint32_t pass) const {
  const std::uint64_t k =
      draw(vehicle_hash, label_hash, pass, DiePurpose::kDetection) % kDetectionDieSteps;
  return static_cast<double>(k) / kDieResolution;
}

double Dice::classification_v(std::uint64_t vehicle_hash, std::uint64_t label_hash,
                              std::uint32_t pass) const {
  const std::uint64_t k =
      draw(vehicle_hash, label_hash, pass, DiePurpose::kClassification) % kClassificationDieSteps;
  return static_cast<double>(k) / kDieResolution;
}

}  // namespace hazard
