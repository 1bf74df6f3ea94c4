#include "hazard/messages/node_report.hpp"

#include <cmath>

#include "fields.hpp"
#include "hazard/ranges.hpp"

namespace hazard {

using detail::Fields;
using detail::missing_field;

namespace {

// A coordinate given as LAT/LON keeps its precision (about 1 mm at 8 decimals).
constexpr int kLatLonDecimals = 8;

std::optional<std::string_view> either(const Fields& f, std::string_view a, std::string_view b) {
  auto v = f.get(a);
  return v ? v : f.get(b);
}

std::optional<double> optional_number(const Fields& f, std::string_view key) {
  const auto text = f.get(key);
  return text ? base::parse_number(*text) : std::nullopt;
}

// A LAT/LON-only position through the placement, or the reason it cannot be placed.
std::optional<glm::dvec2> place_lat_lon(const Fields& f, const GeoPlacement* placement,
                                        std::string& error) {
  const GeoPlacement none;
  if (!placement) placement = &none;
  if (!placement->projection) {
    error = "LAT/LON without X/Y cannot be placed (" + placement->unavailable + ")";
    return std::nullopt;
  }
  const auto lat = f.number("LAT", error);
  const auto lon = f.number("LON", error);
  if (!error.empty()) return std::nullopt;
  if (!valid_latitude(*lat)) {
    error = detail::field_value("LAT", *f.get("LAT")) + " is outside [-90, 90]";
    return std::nullopt;
  }
  if (!valid_longitude(*lon)) {
    error = detail::field_value("LON", *f.get("LON")) + " is outside [-180, 360]";
    return std::nullopt;
  }
  return placement->projection->to_local(*lat, *lon);
}

// Physically meaningful ranges (ranges.hpp): a position beyond kMaxNodeCoordinate_m, or a
// speed that is negative or beyond kMaxNodeSpeed_mps, is refused; empty when in range.
std::string out_of_range(const Fields& f, glm::dvec2 position, double spd,
                         std::string_view spd_text) {
  const std::string bound = base::fmt(kMaxNodeCoordinate_m, 0);
  if (std::fabs(position.x) > kMaxNodeCoordinate_m ||
      std::fabs(position.y) > kMaxNodeCoordinate_m) {
    const auto x = f.get("X");
    const auto y = f.get("Y");
    const std::string given = x && y ? detail::field_value("X", *x) + ", " +
                                           detail::field_value("Y", *y)
                                     : "the position placed from LAT/LON";
    return given + ": beyond " + bound + " m from the origin (kMaxNodeCoordinate_m)";
  }
  if (!(spd >= 0.0 && spd <= kMaxNodeSpeed_mps)) {
    return detail::field_value("SPD", spd_text) + " is outside [0, " +
           base::fmt(kMaxNodeSpeed_mps, 0) + "] m/s";
  }
  return {};
}

}  // namespace

Parsed<NodeReport> parse_node_report(std::string_view text) {
  return parse_node_report(text, nullptr);
}

Parsed<NodeReport> parse_node_report(std::string_view text, const GeoPlacement* placement) {
  const Fields f(text, /*respect_braces=*/true);
  NodeReport r;
  std::string error;
  auto name = detail::vehicle_name(f, "NAME", error);
  if (!name) return Parsed<NodeReport>::fail(error);
  r.name = std::move(*name);

  const auto x = f.number("X", error);
  const auto y = f.number("Y", error);
  const auto spd_text = either(f, "SPD", "SPEED");
  const auto hdg_text = either(f, "HDG", "HEADING");
  const auto spd = spd_text ? base::parse_number(*spd_text) : std::nullopt;
  const auto hdg = hdg_text ? base::parse_number(*hdg_text) : std::nullopt;
  if (!error.empty()) return Parsed<NodeReport>::fail(error);
  if (spd_text && !spd) {
    return Parsed<NodeReport>::fail(detail::field_value("SPD", *spd_text) +
                                    " is not a finite number");
  }
  if (hdg_text && !hdg) {
    return Parsed<NodeReport>::fail(detail::field_value("HDG", *hdg_text) +
                                    " is not a finite number");
  }
  std::optional<glm::dvec2> position;
  if (x && y) {
    position = glm::dvec2{*x, *y};
  } else if (f.get("LAT") && f.get("LON")) {
    position = place_lat_lon(f, placement, error);
    if (!position) return Parsed<NodeReport>::fail(error);
    r.placed_from_lat_lon = true;
  } else {
    return Parsed<NodeReport>::fail(missing_field(!x ? "X" : "Y"));
  }
  if (!spd) return Parsed<NodeReport>::fail(missing_field("SPD"));
  if (!hdg) return Parsed<NodeReport>::fail(missing_field("HDG"));
  r.x_m = position->x;
  r.y_m = position->y;
  r.speed_mps = *spd;
  r.heading_deg = base::norm360(*hdg);
  const std::string why = out_of_range(f, {r.x_m, r.y_m}, r.speed_mps, spd_text.value_or(""));
  if (!why.empty()) return Parsed<NodeReport>::fail(why);
  r.lat_deg = optional_number(f, "LAT");
  r.lon_deg = optional_number(f, "LON");
  r.time_s = optional_number(f, "TIME");
  if (const auto type = f.get("TYPE"); type && !type->empty()) r.type = std::string(*type);
  return Parsed<NodeReport>::ok(std::move(r));
}

std::string format_node_report(const NodeReport& r) {
  std::string out;
  detail::append_field(out, "NAME", r.name);
  detail::append_field(out, "X", base::fmt(r.x_m, 2));
  detail::append_field(out, "Y", base::fmt(r.y_m, 2));
  detail::append_field(out, "SPD", base::fmt(r.speed_mps, 2));
  detail::append_field(out, "HDG", base::fmt(r.heading_deg, 2));
  if (r.lat_deg) detail::append_field(out, "LAT", base::fmt(*r.lat_deg, kLatLonDecimals));
  if (r.lon_deg) detail::append_field(out, "LON", base::fmt(*r.lon_deg, kLatLonDecimals));
  if (r.time_s) detail::append_field(out, "TIME", base::fmt(*r.time_s, 3));
  if (r.type) detail::append_field(out, "TYPE", *r.type);
  return out;
}

}  // namespace hazard
