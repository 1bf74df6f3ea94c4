#include "hazard/messages/node_report.hpp"

#include <cmath>

#include "base/key_value_reader.hpp"
#include "base/text_appender.hpp"
#include "fields.hpp"
#include "hazard/ranges.hpp"

namespace hazard {

using detail::missing_field;
using detail::number_field;

namespace {

// A coordinate given as LAT/LON keeps its precision (about 1 mm at 8 decimals).
constexpr int kLatLonDecimals = 8;

using Field = std::optional<std::string_view>;

// The keys a node report is read for, found in one pass over the text without a list of pieces
// (a node report arrives ten times a second per vehicle). As detail::Fields: keys compare
// case-insensitively, a piece without '=' is no value, a repeated key: the last one wins.
struct NodeFields {
  Field name, x, y, spd, speed, hdg, heading, lat, lon, time, type;

  explicit NodeFields(std::string_view text) {
    base::KeyValueReader reader(text, ',', /*respect_braces=*/true);
    for (base::KeyValue kv; reader.next(kv);) {
      if (!kv.has_equals) continue;
      if (Field* slot = slot_for(kv.key)) *slot = kv.value;
    }
  }

 private:
  // The slot of a key, or nullptr: a switch on the length and the first letter leaves at most
  // one candidate, compared case-insensitively (no lowered copy of the key is built).
  Field* slot_for(std::string_view key) {
    const auto is = [&](std::string_view spelled, Field& slot) {
      return base::iequals(spelled, key) ? &slot : nullptr;
    };
    const char first = base::detail::lower_ascii(key.empty() ? '\0' : key.front());
    switch (key.size()) {
      case 1:
        return first == 'x' ? &x : first == 'y' ? &y : nullptr;
      case 3:
        if (first == 's') return is("SPD", spd);
        if (first == 'h') return is("HDG", hdg);
        if (first == 'l') return is("LAT", lat) ? &lat : is("LON", lon);
        return nullptr;
      case 4:
        if (first == 'n') return is("NAME", name);
        if (first == 't') return is("TIME", time) ? &time : is("TYPE", type);
        return nullptr;
      case 5:
        return is("SPEED", speed);
      case 7:
        return is("HEADING", heading);
      default:
        return nullptr;
    }
  }
};

std::optional<double> optional_number(Field text) {
  return text ? base::parse_number(*text) : std::nullopt;
}

// A required number's text read into a plain double: ten reports a second per vehicle, and a
// std::optional<double> built in memory and then copied whole costs a stalled load each.
enum class NumberText { kAbsent, kNumber, kNotANumber };
NumberText read_number(Field text, double& out) {
  if (!text) return NumberText::kAbsent;
  const std::optional<double> v = base::parse_number(*text);
  if (!v) return NumberText::kNotANumber;
  out = *v;
  return NumberText::kNumber;
}

// A LAT/LON-only position through the placement, or the reason it cannot be placed.
std::optional<glm::dvec2> place_lat_lon(const NodeFields& f, const GeoPlacement* placement,
                                        std::string& error) {
  const GeoPlacement none;
  if (!placement) placement = &none;
  if (!placement->projection) {
    error = "LAT/LON without X/Y cannot be placed (" + placement->unavailable + ")";
    return std::nullopt;
  }
  const auto lat = number_field("LAT", f.lat, error);
  const auto lon = number_field("LON", f.lon, error);
  if (!error.empty()) return std::nullopt;
  if (!valid_latitude(*lat)) {
    error = detail::field_value("LAT", *f.lat) + " is outside [-90, 90]";
    return std::nullopt;
  }
  if (!valid_longitude(*lon)) {
    error = detail::field_value("LON", *f.lon) + " is outside [-180, 360]";
    return std::nullopt;
  }
  return placement->projection->to_local(*lat, *lon);
}

// Physically meaningful ranges (ranges.hpp): a position beyond kMaxNodeCoordinate_m, or a
// speed that is negative or beyond kMaxNodeSpeed_mps, is refused; empty when in range.
std::string out_of_range(const NodeFields& f, glm::dvec2 position, double spd,
                         std::string_view spd_text) {
  if (std::fabs(position.x) > kMaxNodeCoordinate_m ||
      std::fabs(position.y) > kMaxNodeCoordinate_m) {
    const std::string given = f.x && f.y ? detail::field_value("X", *f.x) + ", " +
                                               detail::field_value("Y", *f.y)
                                         : "the position placed from LAT/LON";
    return given + ": beyond " + base::fmt(kMaxNodeCoordinate_m, 0) +
           " m from the origin (kMaxNodeCoordinate_m)";
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

// The report is built in its place in the result (ten a second per vehicle: not moved out).
Parsed<NodeReport> parse_node_report(std::string_view text, const GeoPlacement* placement,
                                     NodeReportKeep keep) {
  const NodeFields f(text);
  Parsed<NodeReport> result;
  NodeReport& r = result.value.emplace();
  std::string error;
  const auto fail = [](std::string why) { return Parsed<NodeReport>::fail(std::move(why)); };
  if (!detail::valid_vehicle_name("NAME", f.name, error)) return fail(error);
  r.name.assign(f.name->data(), f.name->size());

  double x = 0.0, y = 0.0, spd = 0.0, hdg = 0.0;
  const NumberText x_read = read_number(f.x, x);
  const NumberText y_read = read_number(f.y, y);
  const Field spd_text = f.spd ? f.spd : f.speed;
  const Field hdg_text = f.hdg ? f.hdg : f.heading;
  const NumberText spd_read = read_number(spd_text, spd);
  const NumberText hdg_read = read_number(hdg_text, hdg);
  // The first field at fault names the error: X, Y, SPD, HDG, then what is missing.
  if (x_read == NumberText::kNotANumber) return fail(detail::not_a_number("X", *f.x));
  if (y_read == NumberText::kNotANumber) return fail(detail::not_a_number("Y", *f.y));
  if (spd_read == NumberText::kNotANumber) return fail(detail::not_a_number("SPD", *spd_text));
  if (hdg_read == NumberText::kNotANumber) return fail(detail::not_a_number("HDG", *hdg_text));
  if (x_read == NumberText::kNumber && y_read == NumberText::kNumber) {
    r.x_m = x;
    r.y_m = y;
  } else if (f.lat && f.lon) {
    const std::optional<glm::dvec2> placed = place_lat_lon(f, placement, error);
    if (!placed) return fail(error);
    r.x_m = placed->x;
    r.y_m = placed->y;
    r.placed_from_lat_lon = true;
  } else {
    return fail(missing_field(x_read == NumberText::kAbsent ? "X" : "Y"));
  }
  if (spd_read == NumberText::kAbsent) return fail(missing_field("SPD"));
  if (hdg_read == NumberText::kAbsent) return fail(missing_field("HDG"));
  r.speed_mps = spd;
  r.heading_deg = base::norm360(hdg);
  const std::string why = out_of_range(f, {r.x_m, r.y_m}, r.speed_mps, spd_text.value_or(""));
  if (!why.empty()) return fail(why);
  if (keep == NodeReportKeep::kPose) return result;  // nothing below can reject the report
  r.lat_deg = optional_number(f.lat);
  r.lon_deg = optional_number(f.lon);
  r.time_s = optional_number(f.time);
  if (f.type && !f.type->empty()) r.type.emplace(f.type->data(), f.type->size());
  return result;
}

NodeReportMemo& NodeReportMemo::this_thread() {
  thread_local NodeReportMemo memo;
  return memo;
}

const NodeReport* NodeReportMemo::find_or_keep(std::string_view text) {
  for (const Entry& e : entries_)
    if (e.text == text) return &e.report;
  Parsed<NodeReport> parsed = parse_node_report(text, nullptr, NodeReportKeep::kAll);
  // A failure may be a LAT/LON-only report that the caller's placement would place.
  if (!parsed || parsed.value->placed_from_lat_lon) return nullptr;
  if (entries_.size() < kKept) {
    entries_.push_back(Entry{std::string(text), std::move(*parsed.value)});
    return &entries_.back().report;
  }
  Entry& e = entries_[next_];
  next_ = (next_ + 1) % kKept;
  e.text.assign(text.data(), text.size());
  e.report = std::move(*parsed.value);
  return &e.report;
}

Parsed<NodeReport> NodeReportMemo::parse(std::string_view text, const GeoPlacement* placement,
                                         NodeReportKeep keep) {
  const NodeReport* kept = find_or_keep(text);
  if (!kept) return parse_node_report(text, placement, keep);
  Parsed<NodeReport> result;
  NodeReport& r = result.value.emplace(*kept);
  if (keep == NodeReportKeep::kPose) {  // as parse_node_report leaves them
    r.lat_deg.reset();
    r.lon_deg.reset();
    r.time_s.reset();
    r.type.reset();
  }
  return result;
}

// Built through a stack buffer, numbers written in place (a vehicle posts one every iteration);
// the text is the same as appending each field with detail::append_field.
std::string format_node_report(const NodeReport& r) {
  std::string out;
  {
    base::TextAppender a(out);
    a.put("NAME=");
    a.put(r.name);
    a.put_field(",X=", r.x_m, 2);
    a.put_field(",Y=", r.y_m, 2);
    a.put_field(",SPD=", r.speed_mps, 2);
    a.put_field(",HDG=", r.heading_deg, 2);
    if (r.lat_deg) a.put_field(",LAT=", *r.lat_deg, kLatLonDecimals);
    if (r.lon_deg) a.put_field(",LON=", *r.lon_deg, kLatLonDecimals);
    if (r.time_s) a.put_field(",TIME=", *r.time_s, 3);
    if (r.type) {
      a.put(",TYPE=");
      a.put(*r.type);
    }
  }
  return out;
}

}  // namespace hazard
