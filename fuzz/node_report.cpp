// Fuzz target: the NODE_REPORT parser, with and without a geodetic placement for LAT/LON-only
// reports; an accepted report is formatted and read back.

#include "fuzz_input.hpp"
#include "geo_placement.hpp"
#include "hazard/messages/node_report.hpp"

namespace {

void parse_and_reread(std::string_view text, const hazard::GeoPlacement* where) {
  const auto parsed = hazard::parse_node_report(text, where);
  if (parsed.value) (void)hazard::parse_node_report(hazard::format_node_report(*parsed.value));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::as_text(data, size);
  parse_and_reread(text, nullptr);
  parse_and_reread(text, &fuzz::jake_placement(hazard::GeodesyMode::kUtm));
  return 0;
}
