// Wildcard matching against long names with the patterns that made the old greedy matcher
// quadratic: many stars whose last segment never matches. Time per byte of name should stay
// flat as the name grows (run: build/release/bench/moos/moos_bench).
#include <benchmark/benchmark.h>

#include <string>

#include "moos/wildcard.hpp"

namespace {

// A segment of `segment_chars` 'a's and a 'b' that almost matches everywhere in a name of 'a's.
std::string adversarial_pattern(std::size_t segment_chars) {
  return "*" + std::string(segment_chars, 'a') + "b*";
}

void match_long_name(benchmark::State& state, std::size_t segment_chars) {
  const std::string name(static_cast<std::size_t>(state.range(0)), 'a');
  const std::string pattern = adversarial_pattern(segment_chars);
  for (auto _ : state) benchmark::DoNotOptimize(moos::wildcard_match(pattern, name));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}

// Segments up to 64 characters: one pass over the name.
void WildcardMatchLongNameShortSegment(benchmark::State& state) { match_long_name(state, 60); }
BENCHMARK(WildcardMatchLongNameShortSegment)->RangeMultiplier(16)->Range(256, 1 << 20);

// The longest segment a pattern may have: bounded by kMaxWildcardPatternChars per byte of name.
void WildcardMatchLongNameLongestSegment(benchmark::State& state) {
  match_long_name(state, moos::kMaxWildcardPatternChars - 3);
}
BENCHMARK(WildcardMatchLongNameLongestSegment)->RangeMultiplier(16)->Range(256, 1 << 20);

void WildcardMatchTypicalName(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(moos::wildcard_match("UHZ_*_REPORT*", "UHZ_DETECTION_REPORT_ARCHIE"));
}
BENCHMARK(WildcardMatchTypicalName);

}  // namespace

BENCHMARK_MAIN();
