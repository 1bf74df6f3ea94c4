#include "hazard/messages/classify_request.hpp"

#include "fields.hpp"

namespace hazard {

using Result = Parsed<ClassifyRequest>;

Result parse_classify_request(std::string_view text) {
  const detail::Fields f(text);
  ClassifyRequest r;
  std::string error;
  auto vname = detail::vehicle_name(f, "vname", error);
  if (!vname) return Result::fail(error);
  r.vname = std::move(*vname);
  if (const auto action = f.get("action"); action && !action->empty()) {
    if (base::iequals(*action, "top")) {
      r.action = ClassifyAction::kTop;
    } else if (base::iequals(*action, "clear")) {
      r.action = ClassifyAction::kClear;
    } else {
      return Result::fail(detail::field_value("action", *action) + " is neither 'top' nor 'clear'");
    }
  }
  r.priority = f.number("priority", error);
  if (!error.empty()) return Result::fail(error);
  if (const auto label = f.get("label")) r.label = std::string(*label);
  if (r.label.empty() && r.action != ClassifyAction::kClear) {
    return Result::fail(detail::missing_field("label"));
  }
  return Result::ok(std::move(r));
}

std::string format_classify_request(const ClassifyRequest& r) {
  std::string out;
  detail::append_field(out, "vname", r.vname);
  if (!r.label.empty()) detail::append_field(out, "label", r.label);
  if (r.priority) detail::append_field(out, "priority", base::fmt(*r.priority));
  if (r.action == ClassifyAction::kTop) detail::append_field(out, "action", "top");
  if (r.action == ClassifyAction::kClear) detail::append_field(out, "action", "clear");
  return out;
}

}  // namespace hazard
