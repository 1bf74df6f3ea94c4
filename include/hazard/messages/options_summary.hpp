#pragma once
// UHZ_OPTIONS_SUMMARY (manual 4.5, differences.md D21): the configured sensor options.
//
// Example: width=25,exp=4,pclass=0.80:width=50,exp=2,pclass=0.60:width=10,exp=6,pclass=0.93,max=1
//
// Options in configuration order, separated by ':'; each `width=..,exp=..,pclass=..` with the
// values as written in the configuration, `,max=N` appended when N > 0. The parser also accepts
// the original's `class=` key (D20) and rejects an option whose width, exp or pclass is missing
// or not a number. An empty string is a summary with no options.

#include <string>
#include <string_view>
#include <vector>

#include "hazard/messages/parsed.hpp"

namespace hazard {

struct OptionsSummaryEntry {
  std::string width;   ///< value text as written, e.g. "25"
  std::string exp;     ///< e.g. "4"
  std::string pclass;  ///< e.g. "0.80"
  int max_vehicles = 0;  ///< 0 = unlimited (not written)
};

struct OptionsSummary {
  std::vector<OptionsSummaryEntry> options;
};

Parsed<OptionsSummary> parse_options_summary(std::string_view text);
std::string format_options_summary(const OptionsSummary& summary);

}  // namespace hazard
