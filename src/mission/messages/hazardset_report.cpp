#include "mission/messages/hazardset_report.hpp"

#include "base/text.hpp"

namespace mission {

namespace {

bool begins_with(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

// The value after the first '=' (trimmed), or "" when there is none.
std::string value_of(std::string_view part) {
  const auto eq = part.find('=');
  if (eq == std::string_view::npos) return std::string();
  return std::string(base::trim(part.substr(eq + 1)));
}

ReportedObject parse_object(std::string_view part) {
  ReportedObject object;
  for (const base::KeyValue& kv : base::split_key_values(part)) {
    const std::string key = base::to_lower(kv.key);
    if (key == "label" && !kv.value.empty()) object.label = std::string(kv.value);
    if (key == "x") object.x_m = base::parse_number(kv.value);
    if (key == "y") object.y_m = base::parse_number(kv.value);
    if (key == "aspect") object.aspect_deg = base::parse_number(kv.value);
    if (key == "aspect_min") object.aspect_min_deg = base::parse_number(kv.value);
    if (key == "aspect_max") object.aspect_max_deg = base::parse_number(kv.value);
  }
  return object;
}

}  // namespace

ReportedObject reported_object(std::string label, double x_m, double y_m) {
  ReportedObject o;
  o.label = std::move(label);
  o.x_m = x_m;
  o.y_m = y_m;
  return o;
}

bool HazardsetReport::has_label(std::string_view label) const {
  for (const ReportedObject& o : objects)
    if (o.label && *o.label == label) return true;
  return false;
}

HazardsetReport parse_hazardset_report(std::string_view text) {
  HazardsetReport report;
  for (std::string_view part : base::split_trimmed(base::trim(text), '#')) {
    if (part.empty()) continue;
    if (begins_with(part, "source")) {
      report.source = value_of(part);
    } else if (begins_with(part, "name")) {
      report.name = value_of(part);
    } else if (begins_with(part, "search_region")) {
      report.search_region = value_of(part);
    } else if (begins_with(part, "transit_path_width")) {
      // metadata the original accepts and ignores
    } else {
      report.objects.push_back(parse_object(part));
    }
  }
  return report;
}

std::string format_hazardset_report(const HazardsetReport& report) {
  std::string out = "source=" + report.source;
  if (!report.name.empty()) out += "#name=" + report.name;
  if (report.xpath_m) out += "#xpath=" + base::fmt(*report.xpath_m, 1);
  if (report.search_region) out += "#search_region=" + *report.search_region;
  for (const ReportedObject& o : report.objects) {
    std::string part;
    auto add = [&part](const std::string& field) { part += (part.empty() ? "" : ",") + field; };
    if (o.x_m) add("x=" + base::fmt(*o.x_m, 2));
    if (o.y_m) add("y=" + base::fmt(*o.y_m, 2));
    if (o.label) add("label=" + *o.label);
    if (o.aspect_deg) add("aspect=" + base::fmt(*o.aspect_deg));
    if (o.aspect_min_deg) add("aspect_min=" + base::fmt(*o.aspect_min_deg));
    if (o.aspect_max_deg) add("aspect_max=" + base::fmt(*o.aspect_max_deg));
    out += "#" + part;
  }
  return out;
}

}  // namespace mission
