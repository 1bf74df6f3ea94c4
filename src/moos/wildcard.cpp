// Wildcard pattern matching and the wildcard registration string (wire spec 4.1, 5.5).
// The matcher is the classic greedy two-pointer algorithm with one backtrack point for the last
// `*`, which is linear in practice and never exponential.

#include "moos/wildcard.hpp"

#include "base/text.hpp"

namespace moos {

bool wildcard_match(std::string_view pattern, std::string_view text) {
  std::size_t p = 0;
  std::size_t t = 0;
  std::size_t star = std::string_view::npos;  // position of the last '*' seen in the pattern
  std::size_t star_text = 0;                  // text position that '*' currently covers up to
  while (t < text.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == text[t])) {
      ++p;
      ++t;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      star_text = t;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      t = ++star_text;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
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
    if (key == "AppPattern") {
      spec.app_pattern = std::string(value);
    } else if (key == "VarPattern") {
      spec.var_pattern = std::string(value);
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
