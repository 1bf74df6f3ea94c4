#pragma once
// The text layer: every conversion between MOOS strings and typed values goes through here, so the
// rest of libhazard trusts its inputs (style practice 3).
//
// Number formatting follows spec section 0 (FIX, FMT). Number parsing follows the rulings
// ("Numbers"): decimal numbers with optional sign, fraction and exponent; anything non-finite after
// conversion (nan, inf, 1e999) is rejected. Angles are normalised with fmod, never with loops (N3).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hazard {

/// FIX(v, d): C printf("%.*f", d, v). `decimals` in [0, 30].
std::string fix(double value, int decimals);

/// FMT(v, d): FIX(v, d), then (only if the text has a '.') trailing '0's and then a trailing '.'
/// removed, and finally "-0" mapped to "0" (spec section 0). FMT(0.6561, 3) == "0.656".
std::string fmt(double value, int decimals = 5);

/// Blanks and tabs (and CR, LF) removed from both ends.
std::string_view trim(std::string_view text);

/// ASCII case-insensitive equality.
bool iequals(std::string_view a, std::string_view b);
std::string to_lower(std::string_view text);
std::string to_upper(std::string_view text);

/// Strict decimal number: [+-]digits[.digits][(e|E)[+-]digits] (at least one digit before or
/// after the point), blanks trimmed. nullopt for anything else or for a non-finite result.
std::optional<double> parse_number(std::string_view text);

/// A whole number in [0, 2^64 - 1], written with decimal digits only (an optional leading '+').
std::optional<std::uint64_t> parse_unsigned(std::string_view text);

/// Boolean words, case-insensitive: true/yes/on and false/no/off (spec section 0). "toggle" is
/// not a value; callers that support it check for it themselves.
std::optional<bool> parse_bool(std::string_view text);

/// One `key=value` piece of a comma list. `has_equals` is false for a piece without '='
/// (then `key` holds the whole trimmed piece and `value` is empty).
struct KeyValue {
  std::string_view key;
  std::string_view value;
  bool has_equals = true;
};

/// Splits "a=1, b=2" on `separator` (no quoting), each piece at its first '=', both sides trimmed.
/// With `respect_braces`, separators inside {...} do not split (NODE_REPORT, pts={...}).
/// Empty pieces (",,") are skipped.
std::vector<KeyValue> split_key_values(std::string_view text, char separator = ',',
                                       bool respect_braces = false);

/// Splits on every `separator`, trimming each piece; keeps empty pieces.
std::vector<std::string_view> split_trimmed(std::string_view text, char separator);

/// Angle in [0, 360) (never -0.0), exact for every finite input, in one fmod (no loop, N3).
/// Finite input required (guaranteed by parse_number).
double norm360(double angle_deg);
/// Angle in (-180, 180].
double norm180(double angle_deg);

/// For warnings: the text, cut to `max_chars` with " ... (N bytes)" appended when longer, so a
/// 1 MB value never floods a report.
std::string excerpt(std::string_view text, std::size_t max_chars = 160);

}  // namespace hazard
