// Fuzz target: the mission-side mail parsers (src/mission/messages): HAZARD_HANDOVER-style
// handovers, the search start and score, HAZARDSET_EVAL, HAZARDSET_REPORT and the mission
// parameters. The first byte picks the parser; an accepted message is formatted and read back.

#include "fuzz_input.hpp"
#include "mission/messages/hazard_handover.hpp"
#include "mission/messages/hazard_search.hpp"
#include "mission/messages/hazardset_eval.hpp"
#include "mission/messages/hazardset_report.hpp"
#include "mission/messages/mission_params.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text = fuzz::as_text(data + 1, size - 1);
  using namespace mission;
  using fuzz::parse_and_reread;
  switch (data[0] % 6) {
    case 0: parse_and_reread(text, parse_handover, format_handover); break;
    case 1:
      parse_and_reread(text, parse_hazard_search_start, format_hazard_search_start);
      break;
    case 2: (void)parse_hazard_search_score(text); break;
    case 3: parse_and_reread(text, parse_hazardset_eval, format_hazardset_eval); break;
    case 4: {
      const HazardsetReport report = parse_hazardset_report(text);
      (void)parse_hazardset_report(format_hazardset_report(report));
      break;
    }
    default: parse_and_reread(text, parse_mission_params, format_mission_params); break;
  }
  return 0;
}
