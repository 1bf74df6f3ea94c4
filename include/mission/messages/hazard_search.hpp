#pragma once
// HAZARD_SEARCH_START and HAZARD_SEARCH_SCORE (docs/mission-logic.md).
//
// Examples: HAZARD_SEARCH_START = true      (any value: the grader's search clock starts at the
//                                            time the mail is handled)
//           HAZARD_SEARCH_SCORE = 86.666667 (a double: the normalised score of the latest report)
//
// HAZARD_SEARCH_START carries no data, so its parser accepts anything and its formatter writes
// "true". HAZARD_SEARCH_SCORE is posted as a MOOS double; in an .alog it appears as text, which
// the parser reads back (a finite number in [0, 100], else an error naming the value).

#include <string>
#include <string_view>

#include "hazard/messages/parsed.hpp"

namespace mission {

inline constexpr const char* kHazardSearchStartVar = "HAZARD_SEARCH_START";
inline constexpr const char* kHazardSearchScoreVar = "HAZARD_SEARCH_SCORE";

struct HazardSearchStart {};

hazard::Parsed<HazardSearchStart> parse_hazard_search_start(std::string_view text);
std::string format_hazard_search_start(const HazardSearchStart& start);

/// HAZARD_SEARCH_SCORE is posted as a double (HazardsetEval::norm_score), so it has no text
/// formatter; this reads the text form found in logs.
hazard::Parsed<double> parse_hazard_search_score(std::string_view text);

}  // namespace mission
