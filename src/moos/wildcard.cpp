// Wildcard pattern matching and the wildcard registration string (docs/protocol.md 4.1, 5.5).
//
// Matching runs in time linear in the text for a bounded pattern (the classic greedy
// matcher with a backtrack point is O(|pattern| x |text|), and a long pattern against a long
// name stalled the server). The pattern is split at its '*'s into segments. Without a '*' the
// text must match the one segment exactly. Otherwise the first segment must match at the start,
// the last at the end, and every middle segment is found at its leftmost place after the
// previous one: leftmost is always right for '*'-separated segments, because taking a segment
// earlier leaves more text for the ones after it. Each segment is found in one pass over the
// text with the Shift-And method, in ceil(|segment| / 64) word operations per character.

#include "moos/wildcard.hpp"

#include <cstdint>
#include <vector>

#include "base/text.hpp"

namespace moos {

namespace {

constexpr std::size_t kBitsPerWord = 64;
constexpr std::size_t kNotFound = std::string_view::npos;

bool segment_matches_at(std::string_view segment, std::string_view text, std::size_t at) {
  if (at + segment.size() > text.size()) return false;
  for (std::size_t i = 0; i < segment.size(); ++i)
    if (segment[i] != '?' && segment[i] != text[at + i]) return false;
  return true;
}

// Shift-And over W = ceil(|segment| / 64) words: bit i of `state` is set when the first i+1
// characters of the segment match the text ending at the current character. One pass over the
// text, W word operations per character ('?' sets its bit in every character's mask).
std::size_t find_segment(std::string_view segment, std::string_view text) {
  if (segment.empty()) return 0;
  if (segment.size() > text.size()) return kNotFound;
  const std::size_t words = (segment.size() + kBitsPerWord - 1) / kBitsPerWord;
  std::vector<std::uint64_t> masks(256 * words, 0);
  for (std::size_t i = 0; i < segment.size(); ++i) {
    const std::uint64_t bit = std::uint64_t{1} << (i % kBitsPerWord);
    const std::size_t word = i / kBitsPerWord;
    if (segment[i] == '?') {
      for (std::size_t c = 0; c < 256; ++c) masks[c * words + word] |= bit;
    } else {
      masks[static_cast<unsigned char>(segment[i]) * words + word] |= bit;
    }
  }
  const std::size_t last_word = (segment.size() - 1) / kBitsPerWord;
  const std::uint64_t done = std::uint64_t{1} << ((segment.size() - 1) % kBitsPerWord);
  std::vector<std::uint64_t> state(words, 0);
  for (std::size_t j = 0; j < text.size(); ++j) {
    const std::uint64_t* mask = &masks[static_cast<unsigned char>(text[j]) * words];
    std::uint64_t carry = 1;  // a match may start at every character
    for (std::size_t w = 0; w < words; ++w) {
      const std::uint64_t next_carry = state[w] >> (kBitsPerWord - 1);
      state[w] = ((state[w] << 1) | carry) & mask[w];
      carry = next_carry;
    }
    if (state[last_word] & done) return j + 1 - segment.size();
  }
  return kNotFound;
}

}  // namespace

bool wildcard_match(std::string_view pattern, std::string_view text) {
  const std::vector<std::string_view> segments = base::split(pattern, '*');
  if (segments.size() == 1) return pattern.size() == text.size() && segment_matches_at(pattern, text, 0);
  const std::string_view first = segments.front();
  const std::string_view last = segments.back();
  if (first.size() + last.size() > text.size()) return false;
  if (!segment_matches_at(first, text, 0)) return false;
  if (!segment_matches_at(last, text, text.size() - last.size())) return false;
  std::string_view middle = text.substr(first.size(), text.size() - first.size() - last.size());
  for (std::size_t i = 1; i + 1 < segments.size(); ++i) {
    const std::size_t at = find_segment(segments[i], middle);
    if (at == kNotFound) return false;
    middle.remove_prefix(at + segments[i].size());
  }
  return true;
}

bool has_wildcards(std::string_view pattern) {
  return pattern.find_first_of("*?") != std::string_view::npos;
}

std::string format_wildcard_spec(const WildcardSpec& spec) {
  return "AppPattern=" + spec.app_pattern + ",VarPattern=" + spec.var_pattern +
         ",Interval=" + base::format_g(spec.interval_s);
}

WildcardSpec parse_wildcard_spec(std::string_view input, std::string* problem) {
  WildcardSpec spec;
  auto note = [problem](std::string text) {
    if (problem && problem->empty()) *problem = std::move(text);
  };
  std::size_t pos = 0;
  while (pos < input.size()) {
    const auto start = input.find_first_not_of(", \t\r\n", pos);
    if (start == std::string_view::npos) break;
    auto end = input.find_first_of(", \t\r\n", start);
    if (end == std::string_view::npos) end = input.size();
    const std::string_view item = input.substr(start, end - start);
    pos = end;
    const auto eq = item.find('=');
    if (eq == std::string_view::npos) {
      note("item '" + std::string(item) + "' has no '='");
      continue;
    }
    const std::string_view key = item.substr(0, eq);
    const std::string_view value = item.substr(eq + 1);
    if (key == "AppPattern" || key == "VarPattern") {
      std::string& pattern = key == "AppPattern" ? spec.app_pattern : spec.var_pattern;
      if (value.size() > kMaxWildcardPatternChars) {
        note(std::string(key) + " of " + std::to_string(value.size()) +
             " characters is longer than " + std::to_string(kMaxWildcardPatternChars));
        pattern.clear();  // matches only the empty string: nothing
      } else {
        pattern = std::string(value);
      }
    } else if (key == "Interval") {
      const auto interval = base::parse_number(value);
      if (!interval || *interval < 0.0)
        note("Interval '" + std::string(value) + "' is not a number >= 0");
      spec.interval_s = interval && *interval > 0 ? *interval : 0.0;
    } else {
      note("unknown item '" + std::string(key) + "' (expected AppPattern, VarPattern, Interval)");
    }
  }
  return spec;
}

}  // namespace moos
