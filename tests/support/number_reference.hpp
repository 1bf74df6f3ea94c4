#pragma once
// The reference reading of a number (the grammar of differences.md "Numbers", checked by a regular
// expression, then strtod; finite only), against which base::parse_number (std::from_chars) is
// compared bit for bit: by tests/base/number_differential_test.cpp and by fuzz/number.cpp.

#include <cmath>
#include <cstdlib>
#include <optional>
#include <regex>
#include <string>

namespace test_support {

inline std::optional<double> reference_number(const std::string& text) {
  static const std::regex grammar(
      R"([ \t\r\n]*([+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?)[ \t\r\n]*)");
  std::smatch m;
  if (!std::regex_match(text, m, grammar)) return std::nullopt;
  const std::string number = m[1].str();
  char* end = nullptr;
  const double v = std::strtod(number.c_str(), &end);
  if (end != number.c_str() + number.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace test_support
