#pragma once
// Counter-based random numbers for the mission side (vehicle heading noise, test generators):
// every draw is a pure function of (seed, stream, counter), so a run does not depend on call
// order, tick rate or time warp (the same reason as differences.md "Randomness is reproducible").
// Generator: libhazard's SplitMix64 finaliser (hazard::mix64; Steele, Lea, Flood 2014) applied to
// a key built from the three inputs; it passes BigCrush when fed a counter. Normal deviates by
// Box-Muller.

#include <cstdint>

namespace mission {

/// Uniform in [0, 1) with 53 random bits, from (seed, stream, counter).
double uniform01(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter);

/// Standard normal deviate (mean 0, variance 1), from (seed, stream, counter).
double standard_normal(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter);

}  // namespace mission
