#pragma once
// Wildcard subscriptions (docs/protocol.md 4.1 and 5.5): the pattern language and the string
// carried by WILDCARD_REGISTER / WILDCARD_UNREGISTER messages.
//
// Contract:
// - wildcard_match: `*` matches any run of characters (including none), `?` exactly one; every
//   other character matches itself, case-sensitively; the whole text must match. Runs in time
//   linear in the text: O(|text| * ceil(|pattern| / 64)) word operations at worst.
// - A registration whose pattern is longer than kMaxWildcardPatternChars is refused by
//   parse_wildcard_spec (a problem is reported) so a server never matches one.
// - format_wildcard_spec writes `AppPattern=<a>,VarPattern=<v>,Interval=<x>` with the interval
//   in C++ default stream formatting (6 significant digits), as libMOOS does.
// - parse_wildcard_spec accepts commas or blanks between items (pymoos2 uses spaces,
//   protocol.md 5.5); a missing pattern is "" (matches only the empty string); a missing or
//   unreadable interval is 0. Like the reference DB it skips what it cannot read; when `problem` is given, the
//   first skipped item is described there (an item without '=', an unknown key — keys are
//   case-sensitive —, or an interval that is not a finite number >= 0), so a server can refuse
//   the registration with a reason instead.
// - WildcardSpec::matches tests a writer and a variable name against both patterns;
//   same_patterns compares the pattern pair only (a filter's identity).

#include <string>
#include <string_view>

namespace moos {

/// The longest AppPattern or VarPattern a server accepts, in characters: MOOS patterns are
/// variable names with a few wildcards; this bounds the cost of matching.
inline constexpr std::size_t kMaxWildcardPatternChars = 256;

bool wildcard_match(std::string_view pattern, std::string_view text);

/// True if `pattern` uses `*` or `?`.
bool has_wildcards(std::string_view pattern);

struct WildcardSpec {
  std::string app_pattern;
  std::string var_pattern;
  double interval_s = 0.0;

  /// True if `writer` matches app_pattern and `variable` matches var_pattern (protocol.md 5.5).
  bool matches(std::string_view writer, std::string_view variable) const {
    return wildcard_match(app_pattern, writer) && wildcard_match(var_pattern, variable);
  }
  /// Same pattern pair, whatever the intervals: a filter's identity (protocol.md 5.5).
  bool same_patterns(const WildcardSpec& other) const {
    return app_pattern == other.app_pattern && var_pattern == other.var_pattern;
  }
};

std::string format_wildcard_spec(const WildcardSpec& spec);
WildcardSpec parse_wildcard_spec(std::string_view text, std::string* problem = nullptr);

}  // namespace moos
