#include "mission/messages/hazard_search.hpp"

#include "base/text.hpp"

namespace mission {

hazard::Parsed<HazardSearchStart> parse_hazard_search_start(std::string_view /*text*/) {
  return hazard::Parsed<HazardSearchStart>::ok(HazardSearchStart{});
}

std::string format_hazard_search_start(const HazardSearchStart& /*start*/) { return "true"; }

hazard::Parsed<double> parse_hazard_search_score(std::string_view text) {
  const auto v = base::parse_number(text);
  if (!v || *v < 0.0 || *v > 100.0) {
    return hazard::Parsed<double>::fail("HAZARD_SEARCH_SCORE value '" + std::string(text) +
                                        "' is not a number in [0, 100]");
  }
  return hazard::Parsed<double>::ok(*v);
}

}  // namespace mission
