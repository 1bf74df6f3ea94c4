#pragma once
// Private helpers shared by the message modules: reading a key=value list with typed lookups
// whose errors name the field and the value, and writing one.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "base/text.hpp"
#include "base/text_appender.hpp"

namespace hazard::detail {

/// A parsed key=value list. Keys compare case-insensitively; a repeated key: the last one wins.
class Fields {
 public:
  explicit Fields(std::string_view text, bool respect_braces = false)
      : pieces_(base::split_key_values(text, ',', respect_braces)) {}

  std::optional<std::string_view> get(std::string_view key) const;
  /// A finite number, nullopt if absent; sets `error` (if empty) when present but not a number.
  std::optional<double> number(std::string_view key, std::string& error) const;
  /// Keys present that are not in `known` (for strict messages).
  std::vector<std::string_view> unknown_keys(const std::vector<std::string_view>& known) const;
  const std::vector<base::KeyValue>& pieces() const { return pieces_; }

 private:
  std::vector<base::KeyValue> pieces_;
};

/// Fields::number's rule for a value found some other way (a one-pass parser: node_report.cpp).
std::optional<double> number_field(std::string_view key, std::optional<std::string_view> text,
                                   std::string& error);
/// The error of a field whose value is no finite number: "field 'X' value 'abc' is not a
/// finite number".
std::string not_a_number(std::string_view key, std::string_view value);

/// Whether `text` holds a control byte (below 0x20, or 0x7F): names and labels must not, since
/// they reach variable names, postings and log lines.
bool has_control_byte(std::string_view text);
/// "field 'pd' value 'abc'" (the value cut and escaped: it is outside text).
std::string field_value(std::string_view key, std::string_view value);
/// The vehicle name in field `key`: present, non-empty, at most kMaxVehicleNameBytes and free
/// of control bytes (ranges.hpp); nullopt with `error` set otherwise.
std::optional<std::string> vehicle_name(const Fields& f, std::string_view key, std::string& error);
/// The rule itself, without a copy of the name (node_report.cpp): false with `error` set when
/// the name is absent, empty, too long or holds a control byte.
bool valid_vehicle_name(std::string_view key, std::optional<std::string_view> name,
                        std::string& error);
/// "missing field 'vname'".
std::string missing_field(std::string_view key);

/// Appends ",key=value" (no comma when `out` is empty).
void append_field(std::string& out, std::string_view key, std::string_view value);

/// "{x1,y1:x2,y2}" with FMT(., decimals) coordinates.
std::string format_points(const std::vector<glm::dvec2>& points, int decimals);
/// The same appended to `out`.
void append_points(std::string& out, const std::vector<glm::dvec2>& points, int decimals);
/// The same put through `out` (a caller that writes more around it).
void append_points(base::TextAppender& out, const std::vector<glm::dvec2>& points, int decimals);
/// Parses "{x1,y1:x2,y2:...}" (braces optional); nullopt if any coordinate is bad.
std::optional<std::vector<glm::dvec2>> parse_points(std::string_view text);

}  // namespace hazard::detail
