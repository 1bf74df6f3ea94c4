#include "base/text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>

#include "base/fmt_fixed.hpp"
#include "base/key_value_reader.hpp"

namespace base {

namespace {

constexpr int kMaxDecimals = 30;

bool is_digit(char c) { return c >= '0' && c <= '9'; }

using detail::lower_ascii;

// ASCII case folding, as std::toupper does in the "C" locale our programs never change.
char upper_ascii(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - ('a' - 'A')) : c; }

// FIX for the common case, with integer arithmetic: |value| * 10^decimals below 2^53 and at
// most kMaxFastDecimals decimals. The product is off by at most half an ulp, which matters only
// when it lies that close to a rounding tie (x.5); the exact error settles those, and an exact
// tie goes to the even neighbour, as printf does. Same text as printf
// (tests/base/number_differential_test.cpp).
// With `fmt` the text is FMT's (trailing zeros and then a trailing '.' removed, "-0" as "0").
// Every other case has no FixedText: the caller uses std::to_chars, which rounds the exact
// binary value as printf does.
// Kept hand-written because std::to_chars with a precision (libstdc++'s Ryu printf) alone costs
// 3.6 times the instructions here: 2,319 instead of 647 per node report for the swath
// polygon's numbers, the replay loop 7,586 instead of 5,534 (+37 %), and about 4 times the time
// per FMT (120 ns instead of 30); that would take hazard_replay below the 2,000,000 node reports
// per CPU second docs/performance.md quotes ("hazard_replay's digest rate", measured there).
constexpr int kMaxFastDecimals = 9;

// The pieces of the text: [-]whole[.decimals], the decimals `shown` digits of `fraction`
// (leading zeros included). Measured first, then written in place: no buffer and no copy.
struct FixedText {
  bool negative = false;
  std::uint64_t whole = 0;
  std::uint64_t fraction = 0;
  int shown = 0;
  std::size_t length = 0;
};

// Powers of ten a double holds exactly (10^22 is the largest).
constexpr double kExactPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                        1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                        1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// A plain decimal's value from its digits as one integer and its count of decimals, both exact
// (at most 2^53 and 22): one correctly rounded division. The one definition read_plain_decimal
// and the writer's read-back share.
double plain_decimal_value(std::uint64_t mantissa, std::size_t decimals, bool negative) {
  // (through int64: one instruction; the mantissa is below 2^63)
  const double v = static_cast<double>(static_cast<std::int64_t>(mantissa)) /
                   kExactPowersOfTen[decimals];
  return negative ? -v : v;
}

// 10^0 .. 10^16: every power a value below 2^53 (16 digits) is compared with or scaled by.
constexpr std::uint64_t kPow10Int[17] = {1,
                                         10,
                                         100,
                                         1000,
                                         10000,
                                         100000,
                                         1000000,
                                         10000000,
                                         100000000,
                                         1000000000,
                                         10000000000,
                                         100000000000,
                                         1000000000000,
                                         10000000000000,
                                         100000000000000,
                                         1000000000000000,
                                         10000000000000000};

// Decimal digits of v (at least 1): from its bit width (1233 / 4096 is just below log10(2)),
// corrected by one comparison.
int decimal_digits(std::uint64_t v) {
  const int bits = 64 - __builtin_clzll(v | 1);
  const int guess = (bits * 1233) >> 12;
  return guess + ((v | 1) >= kPow10Int[guess] ? 1 : 0);  // 0 has one digit too
}

// Filled in `t`, false outside the fast path. Inlined into each writer (every number of every
// posting): a returned std::optional<FixedText> went through memory, a call each way.
[[gnu::always_inline]] inline bool fixed_fast_text(double value, int decimals, bool fmt,
                                                   FixedText& t) {
  static constexpr double kPow10[kMaxFastDecimals + 1] = {1e0, 1e1, 1e2, 1e3, 1e4,
                                                         1e5, 1e6, 1e7, 1e8, 1e9};
  if (decimals > kMaxFastDecimals) return false;
  const double magnitude = std::fabs(value);
  const double scaled = magnitude * kPow10[decimals];
  if (!(scaled < 0x1p53)) return false;  // also NaN and infinities
  // Truncation is floor here (0 <= scaled < 2^53), without a library call; through int64,
  // which converts in one instruction each way (uint64 needs a branch for 2^63 and above).
  const auto whole_units_signed = static_cast<std::int64_t>(scaled);
  const auto whole_units = static_cast<std::uint64_t>(whole_units_signed);
  const auto whole = static_cast<double>(whole_units_signed);
  const double fraction = scaled - whole;  // exact below 2^53
  bool round_up = fraction > 0.5;
  if (std::fabs(fraction - 0.5) <= scaled * 0x1p-50)  // near a tie: the product's error decides
    round_up = detail::rounds_up_near_tie(magnitude, kPow10[decimals], scaled, fraction,
                                          (whole_units & 1U) != 0);
  const std::uint64_t units = whole_units + (round_up ? 1 : 0);
  // The whole part without a division: floor(|value|) * 10^decimals <= units (both sides
  // round monotonically), and rounding up carries at most once into the whole part.
  const std::uint64_t scale = kPow10Int[decimals];
  t.whole = static_cast<std::uint64_t>(static_cast<std::int64_t>(magnitude));
  t.fraction = units - t.whole * scale;
  if (t.fraction >= scale) {
    ++t.whole;
    t.fraction -= scale;
  }
  t.shown = decimals;
  if (fmt) {  // FMT drops trailing zeros, then the point
    if (t.fraction == 0) t.shown = 0;
    for (; t.shown > 0 && t.fraction % 10 == 0; --t.shown) t.fraction /= 10;
  }
  t.negative = std::signbit(value) && !(fmt && t.whole == 0 && t.shown == 0);  // "-0" as "0"
  const int length = (t.negative ? 1 : 0) + decimal_digits(t.whole) +
                     (t.shown > 0 ? 1 + t.shown : 0);
  t.length = static_cast<std::size_t>(length);
  return true;
}

// Writes the text so that it ends at `end` (t.length bytes before it), from the right, two
// digits per division.
[[gnu::always_inline]] inline void write_fixed_text(const FixedText& t, char* end) {
  static constexpr char kPairs[] =
      "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
      "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
      "8081828384858687888990919293949596979899";
  char* p = end;
  std::uint64_t rest = t.fraction;
  int digits = t.shown;
  for (; digits >= 2; digits -= 2, rest /= 100) {
    p -= 2;
    std::memcpy(p, kPairs + 2 * (rest % 100), 2);
  }
  if (digits == 1) *--p = static_cast<char>('0' + rest);
  if (t.shown > 0) *--p = '.';
  for (rest = t.whole; rest >= 100; rest /= 100) {
    p -= 2;
    std::memcpy(p, kPairs + 2 * (rest % 100), 2);
  }
  if (rest >= 10) {
    p -= 2;
    std::memcpy(p, kPairs + 2 * rest, 2);
  } else {
    *--p = static_cast<char>('0' + rest);
  }
  if (t.negative) *--p = '-';
}

// The fast path's text appended to `out` in place; false outside the fast path.
bool append_fixed_fast(std::string& out, double value, int decimals, bool fmt) {
  FixedText t;
  if (!fixed_fast_text(value, decimals, fmt, t)) return false;
  const std::size_t at = out.size();
  out.resize(at + t.length);
  write_fixed_text(t, out.data() + at + t.length);
  return true;
}

}  // namespace

void append_fix(std::string& out, double value, int decimals) {
  decimals = std::clamp(decimals, 0, kMaxDecimals);
  if (append_fixed_fast(out, value, decimals, /*fmt=*/false)) return;
  // std::to_chars with a precision is specified "as if by printf" in the C locale, and is much
  // faster than glibc's printf; the large buffer only matters for values near 1e308.
  char small[64];
  auto r = std::to_chars(small, small + sizeof small, value, std::chars_format::fixed, decimals);
  if (r.ec == std::errc()) {
    out.append(small, static_cast<std::size_t>(r.ptr - small));
    return;
  }
  const std::size_t at = out.size();
  out.resize(at + 400);
  r = std::to_chars(out.data() + at, out.data() + out.size(), value, std::chars_format::fixed,
                    decimals);
  out.resize(static_cast<std::size_t>(r.ptr - out.data()));
}

void append_fmt(std::string& out, double value, int decimals) {
  if (append_fixed_fast(out, value, std::clamp(decimals, 0, kMaxDecimals), /*fmt=*/true)) return;
  const std::size_t at = out.size();
  append_fix(out, value, decimals);
  // FIX writes a '.' exactly when it has decimals (and the value is finite: "inf" and "nan"
  // end in neither '0' nor '.', so the trimming below leaves them alone).
  if (decimals > 0) {
    std::size_t end = out.size();  // one resize at the end: pop_back is a call per byte
    while (end > at && out[end - 1] == '0') --end;
    if (end > at && out[end - 1] == '.') --end;
    out.resize(end);
  }
  if (out.size() == at + 2 && out.compare(at, 2, "-0") == 0) out.erase(at, 1);
}

static_assert(kFastFmtMaxChars == kFmtFixedMaxChars, "one room for both writers");

namespace {

// FMT(v, d) through write_fmt_fixed<d>: one text for every writer of a buffer.
[[gnu::always_inline]] inline char* write_fmt_dispatched(char* dest, double value, int decimals,
                                                        double& read_back) {
  switch (std::max(decimals, 0)) {
    case 0: return write_fmt_fixed<0>(dest, value, read_back);
    case 1: return write_fmt_fixed<1>(dest, value, read_back);
    case 2: return write_fmt_fixed<2>(dest, value, read_back);
    case 3: return write_fmt_fixed<3>(dest, value, read_back);
    case 4: return write_fmt_fixed<4>(dest, value, read_back);
    case 5: return write_fmt_fixed<5>(dest, value, read_back);
    case 6: return write_fmt_fixed<6>(dest, value, read_back);
    case 7: return write_fmt_fixed<7>(dest, value, read_back);
    case 8: return write_fmt_fixed<8>(dest, value, read_back);
    case 9: return write_fmt_fixed<9>(dest, value, read_back);
    default: return nullptr;
  }
}

}  // namespace

namespace detail {

bool rounds_up_near_tie(double magnitude, double scale, double scaled, double fraction,
                        bool odd) {
  // The sign of (fraction - 0.5) + error, both exact doubles, is the side of the tie the value
  // is on; an exact tie (2.5 to 0 decimals, -10000.25 to 1) goes to the even neighbour, as
  // printf rounds in the default rounding mode.
  const double above_tie = (fraction - 0.5) + std::fma(magnitude, scale, -scaled);
  return above_tie > 0.0 || (above_tie == 0.0 && odd);
}

namespace {

// Exactly four digits of `v` (below 10^4), leading zeros kept.
void put_four(char* p, std::uint64_t v) {
  const std::uint64_t high = v / 100;
  put_pair(p, high);
  put_pair(p + 2, v - high * 100);
}

}  // namespace

// Eight digits at a time from the left, each group by constant divisions (a time stamp of
// 1.7e9 s has ten digits): no digit count first.
char* write_long_whole(char* p, std::uint64_t v) {
  if (v < 100000000) {  // five to eight digits
    const std::uint64_t high = v / 10000;
    p = write_whole(p, high);
    put_four(p, v - high * 10000);
    return p + 4;
  }
  const std::uint64_t high = v / 100000000;  // below 2^53 / 10^8: at most eight digits
  const std::uint64_t low = v - high * 100000000;
  p = write_whole(p, high);
  const std::uint64_t middle = low / 10000;
  put_four(p, middle);
  put_four(p + 4, low - middle * 10000);
  return p + 8;
}

}  // namespace detail

char* write_fmt_fast(char* dest, double value, int decimals) {
  double unused = 0.0;  // (its division is left out: the result is never read)
  return write_fmt_dispatched(dest, value, decimals, unused);
}

char* write_fmt_fast(char* dest, double value, int decimals, double& read_back) {
  return write_fmt_dispatched(dest, value, decimals, read_back);
}

std::string joined(std::initializer_list<std::string_view> pieces) {
  std::size_t size = 0;
  for (const std::string_view piece : pieces) size += piece.size();
  std::string out;
  out.reserve(size);
  for (const std::string_view piece : pieces) out.append(piece.data(), piece.size());
  return out;
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

// std::to_chars with a precision is specified "as if by printf" ("%.*g" here) in the C locale,
// without printf's format parsing and locale lookups (an app's _STATUS carries one each cycle).
std::string format_g(double value, int significant) {
  char buf[64];
  if (significant >= 0) {  // (a negative precision is printf's "none given": 6)
    const auto r =
        std::to_chars(buf, buf + sizeof buf, value, std::chars_format::general, significant);
    if (r.ec == std::errc()) return std::string(buf, r.ptr);
  }
  const int length = std::snprintf(nullptr, 0, "%.*g", significant, value);
  std::string out(static_cast<std::size_t>(std::max(length, 0)) + 1, '\0');
  std::snprintf(out.data(), out.size(), "%.*g", significant, value);
  out.pop_back();
  return out;
}

std::string format_shortest(double value) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, value);
  if (ec != std::errc()) return format_g(value, 17);
  return std::string(buf, ptr);
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

constexpr std::uint64_t kMaxExactInteger = std::uint64_t{1} << 53;
constexpr std::size_t kMaxPlainDigits = 19;  // below 2^64 whatever they are

// Reads the digits from `i` into `mantissa`; the end of the run.
std::size_t read_digits(std::string_view text, std::size_t i, std::uint64_t& mantissa) {
  for (; i < text.size() && is_digit(text[i]); ++i)
    mantissa = mantissa * 10 + static_cast<std::uint64_t>(text[i] - '0');
  return i;
}

}  // namespace

// The usual number of mail ("-470.50"), when its digits make an integer up to 2^53 and it has
// at most 22 decimals: that integer and the power of ten are exact, so one division rounds
// correctly and gives what from_chars gives (Clinger's fast path), at a fraction of its cost.
std::size_t read_plain_decimal(std::string_view text, double& out) {
  const bool negative = !text.empty() && text[0] == '-';
  const std::size_t first = !text.empty() && (negative || text[0] == '+') ? 1 : 0;
  std::uint64_t mantissa = 0;
  std::size_t end = read_digits(text, first, mantissa);
  std::size_t digits = end - first;
  std::size_t decimals = 0;
  if (end < text.size() && text[end] == '.') {
    const std::size_t fraction = end + 1;
    end = read_digits(text, fraction, mantissa);
    decimals = end - fraction;
    digits += decimals;
  }
  // (More than 19 digits may have wrapped the mantissa: refused before it is looked at.)
  if (digits == 0 || digits > kMaxPlainDigits || mantissa > kMaxExactInteger ||
      decimals >= std::size(kExactPowersOfTen))
    return 0;
  out = plain_decimal_value(mantissa, decimals, negative);
  return end;
}

namespace {

// A text that std::from_chars took whole but reported out of range: the grammar reads an
// overflow (1e999) as no number and an underflow (1e-400) as the 0 (or subnormal) strtod gives.
// strtod needs a terminated string; in the "C" locale our programs never change it reads the
// grammar's texts as from_chars does.
std::optional<double> convert_out_of_range(std::string_view text) {
  const std::string copy(text);
  const double v = std::strtod(copy.c_str(), nullptr);
  if (!std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

// The grammar is std::from_chars's (libstdc++'s is fast_float's, correctly rounded as strtod
// is) with three differences: a leading '+' is taken, "inf", "nan" and "infinity" are not
// numbers (the byte after the sign must be a digit or a point), and the whole trimmed text must
// be used (tests/base/number_differential_test.cpp holds it to a regular expression and strtod).
std::optional<double> parse_number(std::string_view text) {
  text = trim(text);
  double v = 0.0;
  const std::size_t plain = read_plain_decimal(text, v);
  if (plain != 0 && plain == text.size()) return v;
  const std::size_t sign = !text.empty() && (text[0] == '+' || text[0] == '-') ? 1 : 0;
  if (sign >= text.size() || !(is_digit(text[sign]) || text[sign] == '.')) return std::nullopt;
  const char* const first = text.data() + (text[0] == '+' ? 1 : 0);
  const char* const last = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (ptr != last) return std::nullopt;
  if (ec == std::errc()) return v;
  if (ec == std::errc::result_out_of_range) return convert_out_of_range(text);
  return std::nullopt;
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

std::vector<KeyValue> split_key_values(std::string_view text, char separator, bool respect_braces) {
  std::vector<KeyValue> out;
  // At most one piece more than separators: one allocation, not a growth series (every
  // classify and sensor request is read through here).
  out.reserve(static_cast<std::size_t>(std::count(text.begin(), text.end(), separator)) + 1);
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
namespace detail {
double norm360_general(double angle_deg) {
  // fmod(a, 360) is a itself when |a| < 360: that case skips the library call.
  double r = std::fabs(angle_deg) < 360.0 ? angle_deg : std::fmod(angle_deg, 360.0);
  if (r < 0) r += 360.0;
  if (r >= 360.0) r = 0.0;  // -1e-17 + 360 rounds to 360
  return r + 0.0;           // -720 gives fmod = -0.0; adding +0.0 makes it +0.0
}
}  // namespace detail

std::string excerpt(std::string_view text, std::size_t max_chars) {
  if (text.size() <= max_chars) return std::string(text);
  std::string out(text.substr(0, max_chars));
  out += " ... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

std::string log_excerpt(std::string_view text) { return escape_for_log(excerpt(text)); }

}  // namespace base
