#include "hazard/messages/node_report.hpp"

#include "fields.hpp"

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

}  // namespace

Parsed<NodeReport> parse_node_report(std::string_view text) {
  return parse_node_report(text, nullptr);
}

Parsed<NodeReport> parse_node_report(std::string_view text, const GeoPlacement* placement) {
  const Fields f(text, /*respect_braces=*/true);
  NodeReport r;
  const auto name = f.get("NAME");
  if (!name || name->empty()) return Parsed<NodeReport>::fail(missing_field("NAME"));
  r.name = std::string(*name);

  std::string error;
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
