#pragma once
// Small text helpers shared by libmoos's parsers (mission file, command line, AppCast requests)
// and by the programs built on libmoos, so that "what is a number" is decided in one place.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace moos::text {

/// Blanks as the MOOS mission reader sees them: space, tab and carriage return (spec 6.2).
inline constexpr std::string_view kBlanks = " \t\r";

std::string_view trim(std::string_view s);
/// Every space, tab and CR removed (libMOOS global values, spec 6.2).
std::string remove_blanks(std::string_view s);
std::string to_upper(std::string_view s);
std::string to_lower(std::string_view s);
/// ASCII case-insensitive equality.
bool iequals(std::string_view a, std::string_view b);
bool starts_with(std::string_view s, std::string_view prefix);
bool ends_with(std::string_view s, std::string_view suffix);

/// Splits on every occurrence of `sep` (empty fields kept).
std::vector<std::string_view> split(std::string_view s, char sep);

/// A finite decimal number (optional sign, fraction, exponent) that uses all of `s` after
/// trimming; nullopt for anything else, including "nan", "inf", hex and overflow. The accepted
/// characters are libMOOS's numeric test for mission values (`0-9 . e E - +`, spec 6.2).
std::optional<double> parse_number(std::string_view s);
/// A whole decimal number in [min, max] that uses all of `s` after trimming.
std::optional<long long> parse_integer(std::string_view s, long long min, long long max);
/// "true"/"false" in any case; nullopt otherwise.
std::optional<bool> parse_bool(std::string_view s);

/// printf-style "%g" with `significant` digits (C++ stream default is 6).
std::string format_g(double value, int significant = 6);
/// Fixed notation with `decimals` digits after the point.
std::string format_fixed(double value, int decimals);
/// The shortest decimal text that reads back as exactly `value`.
std::string format_shortest(double value);

}  // namespace moos::text
