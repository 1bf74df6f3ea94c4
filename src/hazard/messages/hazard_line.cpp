#include "hazard/messages/hazard_line.hpp"

#include <cmath>
#include <set>

#include "fields.hpp"
#include "hazard/ranges.hpp"
#include "hazard/style.hpp"
#include "base/key_value_reader.hpp"
#include "base/text.hpp"
#include "base/warning_budget.hpp"

namespace hazard {

namespace {

using detail::field_value;
using detail::missing_field;

// Ranges from differences.md "Validation" (D27, D28).
constexpr double kMaxAspectDeg = 360.0;       // aspect in [0, 360)
constexpr double kMaxAspectWindowDeg = 90.0;  // aspect_min, aspect_max in [0, 90], sum <= 90

std::string quoted(std::string_view s) { return "'" + base::escape_for_log(s) + "'"; }

// Collects what parse_hazard_line finds, field by field.
// Keys remembered to warn of a repeat: every known key and more, but not a million unknown ones.
constexpr std::size_t kMaxKeysTracked = 64;

struct LineReader {
  HazardLineParse result;
  HazardObject object;
  std::optional<double> x, y;
  std::optional<std::string> label;
  std::optional<ObjectType> type;
  std::optional<ObjectType> type_from_hazard_key;
  std::optional<std::string> lat_text, lon_text;
  const GeoPlacement* placement = nullptr;
  base::WarningBudget budget{base::kMaxWarningsPerLine};

  // A line of a million unknown keys gives a few warnings and a count, not a million.
  void warn(std::string text) { budget.add(result.warnings, std::move(text)); }
  void finish_warnings() {
    if (budget.dropped() > 0) result.warnings.push_back(budget.summary("warnings on this line"));
  }

  void reject(std::string why) {
    if (result.error.empty()) result.error = std::move(why);
  }

  std::optional<double> number(std::string_view key, std::string_view value) {
    const auto v = base::parse_number(value);
    if (!v) reject(field_value(key, value) + " is not a number");
    return v;
  }

  std::optional<double> ranged(std::string_view key, std::string_view value, double lo, double hi,
                               bool hi_inclusive) {
    const auto v = number(key, value);
    if (!v) return std::nullopt;
    if (*v < lo || *v > hi || (!hi_inclusive && *v == hi)) {
      reject(field_value(key, value) + " is outside [" + base::fmt(lo) + ", " + base::fmt(hi) +
             (hi_inclusive ? "]" : ")"));
      return std::nullopt;
    }
    return v;
  }

  void read(std::string_view raw_key, std::string_view value) {
    const std::string key = base::to_lower(raw_key);
    if (key == "x") {
      x = number(key, value);
    } else if (key == "y") {
      y = number(key, value);
    } else if (key == "label") {
      // A label reaches postings, variable payloads and logs: no control bytes.
      if (detail::has_control_byte(value)) {
        reject(field_value(key, value) + " contains a control byte");
      }
      if (value.size() > kMaxLabelBytes) {
        reject(field_value(key, value) + " is longer than " + std::to_string(kMaxLabelBytes) +
               " bytes (kMaxLabelBytes)");
      }
      label = std::string(value);
    } else if (key == "type") {
      if (base::iequals(value, "hazard")) {
        type = ObjectType::kHazard;
      } else if (base::iequals(value, "benign")) {
        type = ObjectType::kBenign;
      } else {
        reject(field_value(key, value) + " is neither 'hazard' nor 'benign'");
      }
    } else if (key == "hazard") {
      const auto b = base::parse_bool(value);
      if (!b) reject(field_value(key, value) + " is not a boolean word");
      if (b) type_from_hazard_key = *b ? ObjectType::kHazard : ObjectType::kBenign;
    } else if (key == "hr") {
      object.resemblance = ranged(key, value, 0.0, 1.0, true);
    } else if (key == "aspect") {
      object.aspect_deg = ranged(key, value, 0.0, kMaxAspectDeg, false);
    } else if (key == "aspect_min") {
      object.aspect_min_deg = ranged(key, value, 0.0, kMaxAspectWindowDeg, true);
    } else if (key == "aspect_max") {
      object.aspect_max_deg = ranged(key, value, 0.0, kMaxAspectWindowDeg, true);
    } else if (key == "color") {
      if (is_known_color(value)) {
        object.color = std::string(value);
      } else {
        warn(field_value(key, value) + " is not a known colour; hint ignored");
      }
    } else if (key == "shape") {
      const std::string shape = base::to_lower(value);
      if (is_known_shape(shape)) {
        object.shape = shape;
      } else {
        warn(field_value(key, value) + " is not a known shape; hint ignored");
      }
    } else if (key == "width") {
      const auto w = base::parse_number(value);
      if (w && *w >= 0.0) {
        object.marker_width_m = *w;
      } else {
        warn(field_value(key, value) +
                                  " is not a number >= 0; hint ignored");
      }
    } else if (key == "source") {
      object.source = std::string(value);
    } else if (key == "lat") {
      lat_text = std::string(value);  // read in finish(): used only without x and y
    } else if (key == "lon") {
      lon_text = std::string(value);
    } else {
      warn("unknown key " + quoted(raw_key) + " (value " +
                                quoted(base::excerpt(value)) + ") ignored");
    }
  }

  void check_aspect_window() {
    const auto& lo = object.aspect_min_deg;
    const auto& hi = object.aspect_max_deg;
    if (lo && hi && *lo > *hi) {
      reject("aspect_min " + base::fmt(*lo) + " is greater than aspect_max " + base::fmt(*hi));
    } else if (lo && hi && *lo + *hi > kMaxAspectWindowDeg) {
      reject("aspect_min + aspect_max = " + base::fmt(*lo + *hi) + " exceeds 90");
    }
    const int present = static_cast<int>(object.aspect_deg.has_value()) +
                        static_cast<int>(lo.has_value()) + static_cast<int>(hi.has_value());
    if (present > 0 && present < 3) {
      warn(
          "partial aspect data (aspect, aspect_min and aspect_max are needed together); the "
          "object loads without aspect sensitivity");
    }
  }

  // A lat/lon-only position through the placement (geodesy.hpp), or a rejection saying why not.
  void place_lat_lon() {
    const GeoPlacement none;
    const GeoPlacement& p = placement ? *placement : none;
    if (!p.projection) {
      return reject("position given only as lat/lon cannot be placed (" + p.unavailable + ")");
    }
    const auto lat = number("lat", *lat_text);
    const auto lon = number("lon", *lon_text);
    if (!lat || !lon) return;
    if (!valid_latitude(*lat)) return reject(field_value("lat", *lat_text) + " is outside [-90, 90]");
    if (!valid_longitude(*lon)) {
      return reject(field_value("lon", *lon_text) + " is outside [-180, 360]");
    }
    const glm::dvec2 at = p.projection->to_local(*lat, *lon);
    x = at.x;
    y = at.y;
  }

  void finish() {
    if (!result.error.empty()) return;
    if ((!x || !y) && lat_text && lon_text) place_lat_lon();
    if (!result.error.empty()) return;
    if (!x || !y) return reject(missing_field(!x ? "x" : "y"));
    if (std::fabs(*x) > kMaxObjectCoordinate_m || std::fabs(*y) > kMaxObjectCoordinate_m) {
      return reject("position (" + base::format_g(*x) + ", " + base::format_g(*y) +
                    ") is beyond " + base::fmt(kMaxObjectCoordinate_m, 0) +
                    " m from the origin (kMaxObjectCoordinate_m)");
    }
    if (!type) type = type_from_hazard_key;
    if (!type) return reject(missing_field("type"));
    if (!label || label->empty()) return reject(missing_field("label"));
    check_aspect_window();
    if (!result.error.empty()) return;
    object.x_m = *x;
    object.y_m = *y;
    object.label = *label;
    object.type = *type;
    result.object = std::move(object);
  }
};

}  // namespace

const char* type_name(ObjectType type) {
  return type == ObjectType::kHazard ? "hazard" : "benign";
}

HazardLineParse parse_hazard_line(std::string_view spec) { return parse_hazard_line(spec, nullptr); }

HazardLineParse parse_hazard_line(std::string_view spec, const GeoPlacement* placement) {
  LineReader reader;
  reader.placement = placement;
  std::set<std::string> seen;  // keys already read: the known ones and a few more (bounded)
  base::KeyValueReader pieces(spec);  // one at a time: a line of a million keys, no vector of them
  for (base::KeyValue kv; pieces.next(kv);) {
    if (!kv.has_equals) {
      reader.warn("piece " + quoted(base::excerpt(kv.key)) +
                                       " has no '='; ignored");
      continue;
    }
    if (seen.size() < kMaxKeysTracked && !seen.insert(base::to_lower(kv.key)).second) {
      reader.warn("key " + quoted(kv.key) +
                                       " repeated; the later value is used");
    }
    reader.read(kv.key, kv.value);
  }
  reader.finish();
  reader.finish_warnings();
  if (!reader.result.error.empty()) reader.result.object.reset();
  return std::move(reader.result);
}

std::string format_hazard_line(const HazardObject& o) {
  std::string out = "x=" + base::fmt(o.x_m, 2) + ",y=" + base::fmt(o.y_m, 2) + ",label=" + o.label +
                    ",type=" + type_name(o.type);
  if (o.color) out += ",color=" + *o.color;
  if (o.shape) out += ",shape=" + *o.shape;
  if (o.marker_width_m) out += ",width=" + base::fmt(*o.marker_width_m);
  if (o.resemblance && !o.is_hazard()) out += ",hr=" + base::fmt(*o.resemblance);
  if (o.aspect_deg) out += ",aspect=" + base::fmt(*o.aspect_deg);
  if (o.aspect_min_deg) out += ",aspect_min=" + base::fmt(*o.aspect_min_deg);
  if (o.aspect_max_deg) out += ",aspect_max=" + base::fmt(*o.aspect_max_deg);
  return out;
}

}  // namespace hazard
