#include "mission/random.hpp"

#include <cmath>

#include "hazard/dice.hpp"

namespace mission {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ULL;  // SplitMix64's increment
constexpr double kTwoToMinus53 = 1.0 / 9007199254740992.0;

std::uint64_t key_of(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter) {
  return hazard::mix64(hazard::mix64(seed ^ kGolden) ^ (stream * kGolden)) ^ (counter * kGolden);
}
}  // namespace

double uniform01(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter) {
  return static_cast<double>(hazard::mix64(key_of(seed, stream, counter)) >> 11) * kTwoToMinus53;
}

double standard_normal(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter) {
  // Box-Muller with two uniforms from neighbouring counters of a derived stream; 1 - u keeps
  // the logarithm's argument in (0, 1].
  const double u1 = 1.0 - uniform01(seed, stream, 2 * counter);
  const double u2 = uniform01(seed, stream, 2 * counter + 1);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
}

}  // namespace mission
