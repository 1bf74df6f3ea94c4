#include "fields.hpp"

#include <algorithm>

#include "hazard/ranges.hpp"

namespace hazard::detail {

std::optional<std::string_view> Fields::get(std::string_view key) const {
  for (auto it = pieces_.rbegin(); it != pieces_.rend(); ++it) {
    if (it->has_equals && base::iequals(it->key, key)) return it->value;
  }
  return std::nullopt;
}

std::optional<double> Fields::number(std::string_view key, std::string& error) const {
  return number_field(key, get(key), error);
}

std::optional<double> number_field(std::string_view key, std::optional<std::string_view> text,
                                   std::string& error) {
  if (!text) return std::nullopt;
  const auto v = base::parse_number(*text);
  if (!v && error.empty()) error = not_a_number(key, *text);
  return v;
}

std::string not_a_number(std::string_view key, std::string_view value) {
  return field_value(key, value) + " is not a finite number";
}

std::vector<std::string_view> Fields::unknown_keys(
    const std::vector<std::string_view>& known) const {
  std::vector<std::string_view> out;
  for (const base::KeyValue& kv : pieces_) {
    const bool is_known = std::any_of(known.begin(), known.end(),
                                      [&](std::string_view k) { return base::iequals(k, kv.key); });
    if (!is_known) out.push_back(kv.key);
  }
  return out;
}

bool has_control_byte(std::string_view text) {
  return std::any_of(text.begin(), text.end(), [](char c) {
    const auto b = static_cast<unsigned char>(c);
    return b < 0x20 || b == 0x7F;
  });
}

std::string field_value(std::string_view key, std::string_view value) {
  return "field '" + std::string(key) + "' value '" + base::log_excerpt(value) +
         "'";
}

std::optional<std::string> vehicle_name(const Fields& f, std::string_view key,
                                        std::string& error) {
  const auto name = f.get(key);
  if (!valid_vehicle_name(key, name, error)) return std::nullopt;
  return std::string(*name);
}

bool valid_vehicle_name(std::string_view key, std::optional<std::string_view> name,
                        std::string& error) {
  if (!name || name->empty()) {
    error = missing_field(key);
    return false;
  }
  if (name->size() > kMaxVehicleNameBytes) {
    error = field_value(key, *name) + " is longer than " + std::to_string(kMaxVehicleNameBytes) +
            " bytes";
    return false;
  }
  if (has_control_byte(*name)) {
    error = field_value(key, *name) + " contains a control byte";
    return false;
  }
  return true;
}

std::string missing_field(std::string_view key) {
  return "missing field '" + std::string(key) + "'";
}

void append_field(std::string& out, std::string_view key, std::string_view value) {
  if (!out.empty()) out.push_back(',');
  out.append(key);
  out.push_back('=');
  out.append(value);
}

void append_points(base::TextAppender& out, const std::vector<glm::dvec2>& points, int decimals) {
  out.put('{');
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) out.put(':');
    out.put_fmt(points[i].x, decimals);
    out.put(',');
    out.put_fmt(points[i].y, decimals);
  }
  out.put('}');
}

void append_points(std::string& out, const std::vector<glm::dvec2>& points, int decimals) {
  base::TextAppender appender(out);
  append_points(appender, points, decimals);
}

std::string format_points(const std::vector<glm::dvec2>& points, int decimals) {
  std::string out;
  append_points(out, points, decimals);
  return out;
}

std::optional<std::vector<glm::dvec2>> parse_points(std::string_view text) {
  text = base::trim(text);
  if (!text.empty() && text.front() == '{') text.remove_prefix(1);
  if (!text.empty() && text.back() == '}') text.remove_suffix(1);
  std::vector<glm::dvec2> points;
  if (base::trim(text).empty()) return points;
  for (std::string_view pair : base::split_trimmed(text, ':')) {
    const auto xy = base::split_trimmed(pair, ',');
    if (xy.size() != 2) return std::nullopt;
    const auto x = base::parse_number(xy[0]);
    const auto y = base::parse_number(xy[1]);
    if (!x || !y) return std::nullopt;
    points.emplace_back(*x, *y);
  }
  return points;
}

}  // namespace hazard::detail
