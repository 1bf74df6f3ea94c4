#include "hazard/messages/options_summary.hpp"

#include <limits>

#include "fields.hpp"

namespace hazard {

using Result = Parsed<OptionsSummary>;

Result parse_options_summary(std::string_view text) {
  OptionsSummary summary;
  if (base::trim(text).empty()) return Result::ok(summary);
  for (std::string_view option : base::split_trimmed(text, ':')) {
    const detail::Fields f(option);
    OptionsSummaryEntry e;
    const auto width = f.get("width");
    const auto exp = f.get("exp");
    auto pclass = f.get("pclass");
    if (!pclass) pclass = f.get("class");
    if (!width) return Result::fail(detail::missing_field("width"));
    if (!exp) return Result::fail(detail::missing_field("exp"));
    if (!pclass) return Result::fail(detail::missing_field("pclass"));
    for (auto [key, value] : {std::pair{"width", *width}, std::pair{"exp", *exp},
                              std::pair{"pclass", *pclass}}) {
      if (!base::parse_number(value)) {
        return Result::fail(detail::not_a_number(key, value));
      }
    }
    if (const auto max = f.get("max")) {
      const auto n = base::parse_unsigned(*max);
      if (!n || *n > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
        return Result::fail(detail::field_value("max", *max) + " is not a whole number >= 0");
      }
      e.max_vehicles = static_cast<int>(*n);
    }
    e.width = std::string(*width);
    e.exp = std::string(*exp);
    e.pclass = std::string(*pclass);
    summary.options.push_back(std::move(e));
  }
  return Result::ok(std::move(summary));
}

std::string format_options_summary(const OptionsSummary& summary) {
  std::string out;
  for (const OptionsSummaryEntry& e : summary.options) {
    if (!out.empty()) out.push_back(':');
    out += "width=" + e.width + ",exp=" + e.exp + ",pclass=" + e.pclass;
    if (e.max_vehicles > 0) out += ",max=" + std::to_string(e.max_vehicles);
  }
  return out;
}

}  // namespace hazard
