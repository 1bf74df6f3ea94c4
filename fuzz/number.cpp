// Fuzz target: the fast paths of the text grammar against their references.
// parse_number (std::from_chars, strtod for what it reports out of range) must give bit for bit
// what the grammar of differences.md "Numbers", checked by a regular expression, and strtod
// give; fix and fmt (integer arithmetic, exact ties to even, std::to_chars) and write_fmt_fast
// must write what C printf writes for a double taken from the input's bytes. Any difference aborts.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <regex>
#include <string>

#include "base/text.hpp"
#include "number_reference.hpp"
#include "fuzz_input.hpp"

namespace {

// std::regex recurses per byte: longer texts are left to the unit test's generated ones.
constexpr std::size_t kMaxRegexBytes = 256;

using test_support::reference_number;

void check_number(std::string_view text) {
  if (text.size() > kMaxRegexBytes) return;
  const auto got = base::parse_number(text);
  const auto want = reference_number(std::string(text));
  if (got.has_value() != want.has_value()) std::abort();
  if (got && std::memcmp(&*got, &*want, sizeof(double)) != 0) std::abort();
}

std::string printf_fixed(double value, int decimals) {
  char text[512];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

void check_format(const std::uint8_t* data, std::size_t size) {
  if (size < sizeof(double) + 1) return;
  double v = 0.0;
  std::memcpy(&v, data, sizeof v);
  if (!std::isfinite(v)) return;
  const int decimals = data[sizeof v] % 31;  // fix clamps to [0, 30]
  const std::string want = printf_fixed(v, decimals);
  if (base::fix(v, decimals) != want) std::abort();
  std::string trimmed = want;
  if (trimmed.find('.') != std::string::npos) {
    while (trimmed.back() == '0') trimmed.pop_back();
    if (trimmed.back() == '.') trimmed.pop_back();
  }
  if (trimmed == "-0") trimmed = "0";
  if (base::fmt(v, decimals) != trimmed) std::abort();
  // The buffer-writing form: the same text within its stated room, or nothing.
  char room[base::kFastFmtMaxChars];
  if (const char* const end = base::write_fmt_fast(room, v, decimals))
    if (std::string(static_cast<const char*>(room), end) != trimmed) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  check_number(fuzz::as_text(data, size));
  check_format(data, size);
  return 0;
}
