#pragma once
// The text grammar every library and program shares: trimming, case, splitting, numbers,
// booleans, angles and number formatting. One definition of "what is a number" for the engine,
// the MOOS layer, the mission logic and the apps (design.md, part 0).
//
// Contract:
// - Numbers follow differences.md "Numbers": [+-]digits[.digits][(e|E)[+-]digits] with at least
//   one digit in the mantissa, blanks trimmed; anything else, and anything non-finite after
//   conversion (nan, inf, 1e999), is nullopt. Underflow (1e-400) is finite and reads as 0.
// - Booleans: true/yes/on and false/no/off in any case (libMOOS).
// - Trimming removes blanks, tabs, CR and LF from both ends.
// - Number formatting is FIX and FMT below; the C locale is assumed throughout.
// - Angles are normalised with fmod, never with loops (N3); inputs must be finite.

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace base {

/// Blanks as the MOOS mission reader sees them inside a line: space, tab and CR
/// (docs/protocol.md 6.2).
inline constexpr std::string_view kBlanks = " \t\r";

// ---- case, trimming, splitting ---------------------------------------------------------------

/// Blanks, tabs, CR and LF removed from both ends.
std::string_view trim(std::string_view text);
/// Every space, tab and CR removed (libMOOS global values, docs/protocol.md 6.2).
std::string remove_blanks(std::string_view text);
/// ASCII case-insensitive equality.
bool iequals(std::string_view a, std::string_view b);
std::string to_lower(std::string_view text);
std::string to_upper(std::string_view text);
bool starts_with(std::string_view text, std::string_view prefix);
bool ends_with(std::string_view text, std::string_view suffix);

/// Splits on every `separator`; pieces are not trimmed and empty pieces are kept.
std::vector<std::string_view> split(std::string_view text, char separator);
/// Splits on every `separator`, trimming each piece; keeps empty pieces.
std::vector<std::string_view> split_trimmed(std::string_view text, char separator);

/// One `key=value` piece of a comma list. `has_equals` is false for a piece without '='
/// (then `key` holds the whole trimmed piece and `value` is empty).
struct KeyValue {
  std::string_view key;
  std::string_view value;
  bool has_equals = true;
};

/// Splits "a=1, b=2" on `separator` (no quoting), each piece at its first '=', both sides trimmed.
/// With `respect_braces`, separators inside {...} do not split (NODE_REPORT, pts={...}).
/// Empty pieces (",,") are skipped. The same pieces one at a time: KeyValueReader
/// (key_value_reader.hpp).
std::vector<KeyValue> split_key_values(std::string_view text, char separator = ',',
                                       bool respect_braces = false);

// ---- numbers and booleans ---------------------------------------------------------------------

/// A finite decimal number (grammar above) that uses all of `text` after trimming.
std::optional<double> parse_number(std::string_view text);
/// The plain decimal [+-]digits[.digits] (a digit at least) at the start of `text`, read as
/// parse_number reads it: its length, with its value in `out`, when its digits make an integer
/// up to 2^53 and it has at most 22 decimals; 0 otherwise (parse_number covers the rest). For
/// scanners that read a number where it stands (NODE_REPORT).
std::size_t read_plain_decimal(std::string_view text, double& out);
/// A whole number in [0, 2^64 - 1], decimal digits only (an optional leading '+').
std::optional<std::uint64_t> parse_unsigned(std::string_view text);
/// A whole decimal number in [min, max] that uses all of `text` after trimming.
std::optional<long long> parse_integer(std::string_view text, long long min, long long max);
/// true/yes/on and false/no/off, any case; nullopt otherwise. "toggle" is not a value.
std::optional<bool> parse_bool(std::string_view text);

// ---- formatting -------------------------------------------------------------------------------

/// The pieces one after another, in one allocation (a text built for every detection: the
/// chain a + b + c allocates at each step).
std::string joined(std::initializer_list<std::string_view> pieces);

/// FIX(v, d): C printf("%.*f", d, v). `decimals` is clamped to [0, 30].
std::string fix(double value, int decimals);
/// FIX(v, d) appended to `out` (no temporary string: the swath polygon and the log writer).
void append_fix(std::string& out, double value, int decimals);
/// FMT(v, d) appended to `out`.
void append_fmt(std::string& out, double value, int decimals = 5);
/// The room write_fmt_fast() may fill (its longest text: 16 digits, a point and a sign).
inline constexpr std::size_t kFastFmtMaxChars = 24;
/// FMT(v, d) written at `dest`, which has room for kFastFmtMaxChars bytes, when the common case
/// covers it (|v| * 10^d below 2^53, at most 9 decimals): the end of the text (the room past it
/// may hold scratch digits), else nullptr and nothing written (append_fmt covers every value).
/// For writers that fill a buffer; write_fmt_fixed (fmt_fixed.hpp) when d is a constant.
char* write_fmt_fast(char* dest, double value, int decimals);
/// The same, and in `read_back` the number the text reads as (read_plain_decimal takes all of
/// it, and parse_number gives the same): for a writer that knows what its reader will find.
char* write_fmt_fast(char* dest, double value, int decimals, double& read_back);
/// FMT(v, d): FIX(v, d), then (only if the text has a '.') trailing '0's and then a trailing '.'
/// removed, and finally "-0" mapped to "0". FMT(0.6561, 3) == "0.656".
std::string fmt(double value, int decimals = 5);
/// printf-style "%g" with `significant` digits (C++ stream default is 6).
std::string format_g(double value, int significant = 6);
/// The shortest decimal text that reads back as exactly `value`.
std::string format_shortest(double value);

/// For warnings: the text, cut to `max_chars` with " ... (N bytes)" appended when longer, so a
/// 1 MB value never floods a report.
std::string excerpt(std::string_view text, std::size_t max_chars = 160);

/// Text from outside made safe for a log line ("Log and record injection"): every
/// control byte (below 0x20, and 0x7F) and every backslash is written as `\xHH`, so a client
/// can neither end a line nor forge one. Printable ASCII and bytes >= 0x80 (UTF-8) are kept.
std::string escape_for_log(std::string_view text);

/// Outside text as a warning or log line quotes it: excerpt(), then escape_for_log().
std::string log_excerpt(std::string_view text);

// ---- angles -----------------------------------------------------------------------------------

namespace detail {
/// norm360 for any input: one fmod (no loop, N3). The inline cases below give the same bits.
double norm360_general(double angle_deg);
}  // namespace detail

/// Angle in [0, 360) (never -0.0), exact for every finite input. Headings and the differences
/// of two headings (within one turn) are the common inputs, several per vehicle step: those are
/// normalised inline, without a call (NaN and everything else go to norm360_general).
inline double norm360(double angle_deg) {
  if (angle_deg >= 0.0 && angle_deg < 360.0) return angle_deg + 0.0;  // -0.0 becomes +0.0
  if (angle_deg < 0.0 && angle_deg > -360.0) {
    const double r = angle_deg + 360.0;
    return r < 360.0 ? r : 0.0;  // -1e-17 + 360 rounds to 360
  }
  return detail::norm360_general(angle_deg);
}
/// Angle in (-180, 180].
inline double norm180(double angle_deg) {
  const double r = norm360(angle_deg);
  return r > 180.0 ? r - 360.0 : r;
}

// ---- inline definitions: trim and iequals run on every key and value of every message -------

namespace detail {
/// ASCII case folding, as std::tolower does in the "C" locale our programs never change,
/// without a library call per byte.
inline char lower_ascii(char c) {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c + ('a' - 'A')) : c;
}
/// One compare for the usual byte (anything above ' ' is kept), four for the rest.
inline bool is_trimmed(char c) {
  return static_cast<unsigned char>(c) <= ' ' && (c == ' ' || c == '\t' || c == '\r' || c == '\n');
}
}  // namespace detail

inline std::string_view trim(std::string_view text) {
  while (!text.empty() && detail::is_trimmed(text.front())) text.remove_prefix(1);
  while (!text.empty() && detail::is_trimmed(text.back())) text.remove_suffix(1);
  return text;
}

inline bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (detail::lower_ascii(a[i]) != detail::lower_ascii(b[i])) return false;
  }
  return true;
}

}  // namespace base
