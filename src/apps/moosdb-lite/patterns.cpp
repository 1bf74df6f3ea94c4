// Strict checks of wildcard registration strings (spec 5.5). See patterns.hpp.

#include "patterns.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace moosdb_lite {

std::optional<double> parse_finite_number(std::string_view text) {
  if (text.empty()) return std::nullopt;
  const std::string copy(text);
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(copy.c_str(), &end);
  if (end != copy.c_str() + copy.size() || errno == ERANGE || !std::isfinite(value))
    return std::nullopt;
  return value;
}

std::optional<std::string> wildcard_spec_problem(std::string_view text) {
  // Commas and blanks both separate items: read blank-separated words after turning commas
  // into blanks.
  std::string items(text);
  std::replace(items.begin(), items.end(), ',', ' ');
  std::istringstream words(items);
  for (std::string item; words >> item;) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) return "item '" + item + "' has no '='";
    const std::string key = item.substr(0, eq);
    const std::string value = item.substr(eq + 1);
    if (key == "Interval") {
      const auto interval = parse_finite_number(value);
      if (!interval || *interval < 0.0) return "Interval '" + value + "' is not a number >= 0";
    } else if (key != "AppPattern" && key != "VarPattern") {
      return "unknown item '" + key + "' (expected AppPattern, VarPattern, Interval)";
    }
  }
  return std::nullopt;
}

}  // namespace moosdb_lite
