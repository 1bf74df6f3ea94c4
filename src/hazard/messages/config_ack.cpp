#include "hazard/messages/config_ack.hpp"

#include "fields.hpp"

namespace hazard {

using Result = Parsed<ConfigAck>;

Result parse_config_ack(std::string_view text) {
  const detail::Fields f(text);
  const auto unknown = f.unknown_keys({"vname", "width", "pd", "pfa", "pclass"});
  if (!unknown.empty()) return Result::fail("unexpected key '" + std::string(unknown[0]) + "'");
  const auto vname = f.get("vname");
  if (!vname || vname->empty()) return Result::fail(detail::missing_field("vname"));
  std::string error;
  const auto width = f.number("width", error);
  const auto pd = f.number("pd", error);
  const auto pfa = f.number("pfa", error);
  const auto pclass = f.number("pclass", error);
  if (!error.empty()) return Result::fail(error);
  for (auto [key, value] : {std::pair{"width", width.has_value()}, std::pair{"pd", pd.has_value()},
                            std::pair{"pfa", pfa.has_value()},
                            std::pair{"pclass", pclass.has_value()}}) {
    if (!value) return Result::fail(detail::missing_field(key));
  }
  return Result::ok(ConfigAck{std::string(*vname), *width, *pd, *pfa, *pclass});
}

std::string format_config_ack(const ConfigAck& a) {
  return "vname=" + a.vname + ",width=" + base::fmt(a.width_m, 1) + ",pd=" + base::fmt(a.pd, 3) +
         ",pfa=" + base::fmt(a.pfa, 3) + ",pclass=" + base::fmt(a.pclass, 3);
}

}  // namespace hazard
