// Fuzz target: one hazard object line (the text after `hazard =`), with and without a geodetic
// placement for lat/lon-only lines, and the formatted line of every accepted object read back.

#include "fuzz_input.hpp"
#include "geo_placement.hpp"
#include "hazard/messages/hazard_line.hpp"

namespace {

void parse_and_reread(std::string_view spec, const hazard::GeoPlacement* where) {
  const hazard::HazardLineParse parsed = hazard::parse_hazard_line(spec, where);
  if (parsed.object) {
    // What we write must read back: the formatted line is parsed again (it must not crash).
    (void)hazard::parse_hazard_line(hazard::format_hazard_line(*parsed.object));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view spec = fuzz::as_text(data, size);
  parse_and_reread(spec, nullptr);
  parse_and_reread(spec, &fuzz::jake_placement(hazard::GeodesyMode::kTangent));
  return 0;
}
