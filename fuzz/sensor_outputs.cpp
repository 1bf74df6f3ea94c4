// Fuzz target: the parsers of the sensor's own postings, which the vehicle side (pHazardMgr) and
// the viewers read as outside input: UHZ_CONFIG_ACK, UHZ_DETECTION_REPORT, UHZ_HAZARD_REPORT,
// UHZ_OPTIONS_SUMMARY and the VIEW_* shapes. The first byte picks the parser; an accepted
// message is formatted and read back.

#include "fuzz_input.hpp"
#include "hazard/messages/config_ack.hpp"
#include "hazard/messages/detection_report.hpp"
#include "hazard/messages/hazard_report.hpp"
#include "hazard/messages/options_summary.hpp"
#include "hazard/messages/view_circle.hpp"
#include "hazard/messages/view_marker.hpp"
#include "hazard/messages/view_polygon.hpp"
#include "hazard/messages/view_seglist.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text = fuzz::as_text(data + 1, size - 1);
  using namespace hazard;
  using fuzz::parse_and_reread;
  switch (data[0] % 8) {
    case 0: parse_and_reread(text, parse_config_ack, format_config_ack); break;
    case 1: parse_and_reread(text, parse_detection_report, format_detection_report); break;
    case 2: parse_and_reread(text, parse_hazard_report, format_hazard_report); break;
    case 3: parse_and_reread(text, parse_options_summary, format_options_summary); break;
    case 4: parse_and_reread(text, parse_view_circle, format_view_circle); break;
    case 5: parse_and_reread(text, parse_view_marker, format_view_marker); break;
    case 6: parse_and_reread(text, parse_view_polygon, format_view_polygon); break;
    default: parse_and_reread(text, parse_view_seglist, format_view_seglist); break;
  }
  return 0;
}
