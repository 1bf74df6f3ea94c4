#include "hazard/messages/config_request.hpp"

#include "fields.hpp"
#include "hazard/ranges.hpp"

namespace hazard {

using Result = Parsed<ConfigRequest>;

Result parse_config_request(std::string_view text) {
  const detail::Fields f(text);
  std::string error;
  auto vname = detail::vehicle_name(f, "vname", error);
  if (!vname) return Result::fail(error);
  ConfigRequest r;
  r.vname = std::move(*vname);
  // An empty width ("width=,pd=0.8") is a pd-only update, as in the original
  // (docs/messages.md, UHZ_CONFIG_REQUEST).
  const auto width_text = f.get("width");
  if (width_text && !width_text->empty()) r.width_m = f.number("width", error);
  r.pd = f.number("pd", error);
  if (!error.empty()) return Result::fail(error);
  if (r.width_m && !(*r.width_m > 0.0)) {
    return Result::fail(detail::field_value("width", *f.get("width")) + " is not > 0");
  }
  if (r.width_m && *r.width_m > kMaxSwathWidth_m) {
    return Result::fail(detail::field_value("width", *f.get("width")) + " is above " +
                        base::fmt(kMaxSwathWidth_m) + " m (kMaxSwathWidth_m)");
  }
  if (r.pd && !(*r.pd >= 0.0 && *r.pd <= 1.0)) {
    return Result::fail(detail::field_value("pd", *f.get("pd")) + " is outside [0, 1]");
  }
  if (!r.width_m && !r.pd) return Result::fail("neither 'width' nor 'pd' given");
  return Result::ok(std::move(r));
}

std::string format_config_request(const ConfigRequest& r) {
  std::string out;
  detail::append_field(out, "vname", r.vname);
  if (r.width_m) detail::append_field(out, "width", base::fmt(*r.width_m));
  if (r.pd) detail::append_field(out, "pd", base::fmt(*r.pd));
  return out;
}

}  // namespace hazard
