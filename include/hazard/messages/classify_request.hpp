#pragma once
// UHZ_CLASSIFY_REQUEST (manual 3.2, differences.md D7, D8, D10): ask for the classification of a
// detected object, optionally with a priority (default 50) and an action.
//
// Examples: vname=archie,label=152
//           vname=archie,label=152,priority=95
//           vname=archie,label=152,priority=100,action=top
//           vname=archie,action=clear
//
// vname is required; label is required unless action=clear; priority, if given, is a finite
// number; action, if given, is `top` or `clear` (any case). Unknown keys are ignored.

#include <optional>
#include <string>
#include <string_view>

#include "hazard/messages/parsed.hpp"

namespace hazard {

/// Priority of a request that gives none (manual 3.2).
inline constexpr double kDefaultClassifyPriority = 50.0;

enum class ClassifyAction { kNormal, kTop, kClear };

struct ClassifyRequest {
  std::string vname;
  std::string label;                ///< empty only for kClear
  std::optional<double> priority;   ///< kDefaultClassifyPriority when absent
  ClassifyAction action = ClassifyAction::kNormal;
};

Parsed<ClassifyRequest> parse_classify_request(std::string_view text);
std::string format_classify_request(const ClassifyRequest& request);

}  // namespace hazard
