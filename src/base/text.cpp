#include "base/text.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace base {

namespace {

constexpr std::string_view kTrimmed = " \t\r\n";
constexpr int kMaxDecimals = 30;

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// ASCII case folding, as std::tolower/toupper do in the "C" locale our programs never change,
// without a library call per byte (iequals runs on every key of every message).
char lower_ascii(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c + ('a' - 'A')) : c; }
char upper_ascii(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - ('a' - 'A')) : c; }

// Accepts exactly the grammar of parse_number's contract.
bool is_decimal_number(std::string_view s) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t mantissa_digits = 0;
  while (i < s.size() && is_digit(s[i])) ++i, ++mantissa_digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && is_digit(s[i])) ++i, ++mantissa_digits;
  }
  if (mantissa_digits == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t exponent_digits = 0;
    while (i < s.size() && is_digit(s[i])) ++i, ++exponent_digits;
    if (exponent_digits == 0) return false;
  }
  return i == s.size();
}

}  // namespace

void append_fix(std::string& out, double value, int decimals) {
  decimals = std::clamp(decimals, 0, kMaxDecimals);
  // std::to_chars with a precision is specified "as if by printf" in the C locale, and is much
  // faster than glibc's printf; the large buffer only matters for values near 1e308.
  char small[64];
  auto r = std::to_chars(small, small + sizeof small, value, std::chars_format::fixed, decimals);
  if (r.ec == std::errc()) {
    out.append(small, r.ptr);
    return;
  }
  const std::size_t at = out.size();
  out.resize(at + 400);
  r = std::to_chars(out.data() + at, out.data() + out.size(), value, std::chars_format::fixed,
                    decimals);
  out.resize(static_cast<std::size_t>(r.ptr - out.data()));
}

void append_fmt(std::string& out, double value, int decimals) {
  const std::size_t at = out.size();
  append_fix(out, value, decimals);
  if (out.find('.', at) != std::string::npos) {
    while (out.size() > at && out.back() == '0') out.pop_back();
    if (out.size() > at && out.back() == '.') out.pop_back();
  }
  if (out.size() == at + 2 && out.compare(at, 2, "-0") == 0) out.erase(at, 1);
}

std::string fix(double value, int decimals) {
  std::string s;
  append_fix(s, value, decimals);
  return s;
}

std::string fmt(double value, int decimals) {
  std::string s;
  append_fmt(s, value, decimals);
  return s;
}

std::string format_g(double value, int significant) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", significant, value);
  return buf;
}

std::string format_shortest(double value) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, value);
  if (ec != std::errc()) return format_g(value, 17);
  return std::string(buf, ptr);
}

std::string_view trim(std::string_view text) {
  // A loop over the (usually zero) blanks at each end, not a search through kTrimmed per byte.
  const auto trimmed = [](char c) { return kTrimmed.find(c) != std::string_view::npos; };
  while (!text.empty() && trimmed(text.front())) text.remove_prefix(1);
  while (!text.empty() && trimmed(text.back())) text.remove_suffix(1);
  return text;
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (lower_ascii(a[i]) != lower_ascii(b[i])) return false;
  }
  return true;
}

std::string to_lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = lower_ascii(c);
  return out;
}

std::string to_upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = upper_ascii(c);
  return out;
}

std::string remove_blanks(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text)
    if (kBlanks.find(c) == std::string_view::npos) out.push_back(c);
  return out;
}

bool starts_with(std::string_view text, std::string_view prefix) {
  return text.size() >= prefix.size() && text.compare(0, prefix.size(), prefix) == 0;
}

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const auto at = text.find(separator, start);
    if (at == std::string_view::npos) {
      out.push_back(text.substr(start));
      return out;
    }
    out.push_back(text.substr(start, at - start));
    start = at + 1;
  }
}

namespace {

// The reference conversion of a text that passed is_decimal_number. strtod needs a terminated
// string; the grammar check makes it locale-safe in the "C" locale that our programs never
// change. Underflow (1e-400) yields a finite 0 and is kept.
std::optional<double> convert_with_strtod(std::string_view text) {
  const std::string copy(text);
  char* end = nullptr;
  const double v = std::strtod(copy.c_str(), &end);
  if (end != copy.c_str() + copy.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

// std::from_chars is correctly rounded, as glibc's strtod is, so both give the same double for
// every text of the grammar; it needs no copy. It takes no '+' and reports overflow and
// underflow as errors: those texts (and anything else it does not take whole) go to strtod,
// which decides them as it always did (tests/base/number_differential_test.cpp).
std::optional<double> parse_number(std::string_view text) {
  text = trim(text);
  if (!is_decimal_number(text)) return std::nullopt;
  const std::string_view unsigned_or_minus =
      text.front() == '+' ? text.substr(1) : text;
  const char* const end = unsigned_or_minus.data() + unsigned_or_minus.size();
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(unsigned_or_minus.data(), end, v);
  if (ec == std::errc() && ptr == end && std::isfinite(v)) return v;
  return convert_with_strtod(text);
}

std::optional<std::uint64_t> parse_unsigned(std::string_view text) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty() || !std::all_of(text.begin(), text.end(), is_digit)) return std::nullopt;
  std::uint64_t v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  return v;
}

std::optional<long long> parse_integer(std::string_view text, long long min, long long max) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  if (v < min || v > max) return std::nullopt;
  return v;
}

std::optional<bool> parse_bool(std::string_view text) {
  text = trim(text);
  if (iequals(text, "true") || iequals(text, "yes") || iequals(text, "on")) return true;
  if (iequals(text, "false") || iequals(text, "no") || iequals(text, "off")) return false;
  return std::nullopt;
}

KeyValueReader::KeyValueReader(std::string_view text, char separator, bool respect_braces)
    : text_(text), separator_(separator), respect_braces_(respect_braces) {}

bool KeyValueReader::next(KeyValue& kv) {
  while (start_ <= text_.size()) {
    // The piece ends at the next separator outside {...} (braces count only when asked).
    std::size_t i = start_;
    int depth = 0;
    for (; i < text_.size(); ++i) {
      const char c = text_[i];
      if (respect_braces_ && c == '{') ++depth;
      if (respect_braces_ && c == '}' && depth > 0) --depth;
      if (c == separator_ && depth == 0) break;
    }
    const std::string_view piece = trim(text_.substr(start_, i - start_));
    start_ = i + 1;
    if (piece.empty()) continue;
    const auto eq = piece.find('=');
    if (eq == std::string_view::npos) {
      kv = KeyValue{piece, {}, false};
    } else {
      kv = KeyValue{trim(piece.substr(0, eq)), trim(piece.substr(eq + 1)), true};
    }
    return true;
  }
  return false;
}

std::vector<KeyValue> split_key_values(std::string_view text, char separator, bool respect_braces) {
  std::vector<KeyValue> out;
  KeyValueReader reader(text, separator, respect_braces);
  for (KeyValue kv; reader.next(kv);) out.push_back(kv);
  return out;
}

std::vector<std::string_view> split_trimmed(std::string_view text, char separator) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const auto pos = text.find(separator, start);
    if (pos == std::string_view::npos) {
      out.push_back(trim(text.substr(start)));
      return out;
    }
    out.push_back(trim(text.substr(start, pos - start)));
    start = pos + 1;
  }
}

std::string escape_for_log(std::string_view text) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7F || c == '\\') {
      out += "\\x";
      out.push_back(kHex[byte >> 4]);
      out.push_back(kHex[byte & 0xF]);
    } else {
      out.push_back(c);
    }
  }
  return out;
}

// fmod is exact (the remainder of two doubles is representable), so any finite heading, however
// large (1e15, 1e300), normalises in one step without a loop (N3).
double norm360(double angle_deg) {
  double r = std::fmod(angle_deg, 360.0);
  if (r < 0) r += 360.0;
  if (r >= 360.0) r = 0.0;  // -1e-17 + 360 rounds to 360
  return r + 0.0;           // -720 gives fmod = -0.0; adding +0.0 makes it +0.0
}

double norm180(double angle_deg) {
  const double r = norm360(angle_deg);
  return r > 180.0 ? r - 360.0 : r;
}

std::string excerpt(std::string_view text, std::size_t max_chars) {
  if (text.size() <= max_chars) return std::string(text);
  std::string out(text.substr(0, max_chars));
  out += " ... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

}  // namespace base
