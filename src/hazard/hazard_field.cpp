#include "hazard/hazard_field.hpp"

#include <optional>

#include "hazard/dice.hpp"
#include "hazard/messages/hazard_line.hpp"
#include "base/text.hpp"

namespace hazard {

namespace {

std::string place(std::string_view file, int line) {
  return std::string(file) + ":" + std::to_string(line) + ": ";
}

// Strips a `//` comment (rulings: the sensor and the grader must agree on ground truth, and the
// grader strips comments).
std::string_view without_comment(std::string_view line) {
  const auto pos = line.find("//");
  return pos == std::string_view::npos ? line : line.substr(0, pos);
}

}  // namespace

bool HazardField::add(HazardObject object) {
  if (by_label_.count(object.label) != 0) return false;
  const auto id = static_cast<ObjectId>(objects_.size());
  by_label_.emplace(object.label, id);
  positions_.emplace_back(object.x_m, object.y_m);
  label_hashes_.push_back(hash_name(object.label));
  if (object.is_hazard()) ++hazards_;
  objects_.push_back(std::move(object));
  return true;
}

void HazardField::build_index() { grid_ = SpatialGrid(positions_); }

std::optional<ObjectId> HazardField::find(std::string_view label) const {
  const auto it = by_label_.find(std::string(label));
  if (it == by_label_.end()) return std::nullopt;
  return it->second;
}

bool load_hazard_spec(std::string_view spec, std::string_view file, int line, HazardField& field,
                      std::vector<std::string>& warnings, const GeoPlacement* placement) {
  HazardLineParse parsed = parse_hazard_line(spec, placement);
  for (const std::string& w : parsed.warnings) warnings.push_back(place(file, line) + w);
  if (!parsed.object) {
    warnings.push_back(place(file, line) + parsed.error + "; line rejected");
    return false;
  }
  const std::string label = parsed.object->label;
  if (!field.add(std::move(*parsed.object))) {
    warnings.push_back(place(file, line) + "duplicate label '" + label +
                       "'; the first object with this label is kept, this line is rejected");
    return false;
  }
  return true;
}

HazardFileCounts load_hazard_file_text(std::string_view text, std::string_view file,
                                       HazardField& field, std::vector<std::string>& warnings,
                                       const GeoPlacement* placement) {
  HazardFileCounts counts;
  int line_number = 0;
  // A UTF-8 byte-order mark is accepted at the start, as in mission files (issue 12).
  std::size_t start = base::starts_with(text, "\xEF\xBB\xBF") ? 3 : 0;
  while (start <= text.size()) {
    const auto end = text.find('\n', start);
    const std::string_view raw =
        text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    start = end == std::string_view::npos ? text.size() + 1 : end + 1;
    ++line_number;
    const std::string_view line = base::trim(without_comment(raw));
    if (line.empty()) continue;
    const auto eq = line.find('=');
    const std::string_view key = base::trim(line.substr(0, eq));
    if (eq != std::string_view::npos && base::iequals(key, "hazard")) {
      const std::size_t before = field.size();
      if (load_hazard_spec(line.substr(eq + 1), file, line_number, field, warnings, placement)) {
        (field.object(static_cast<ObjectId>(before)).is_hazard() ? counts.hazards
                                                                 : counts.benign) += 1;
      } else {
        ++counts.rejected_lines;
      }
    } else if (eq != std::string_view::npos && (base::iequals(key, "region") || base::iequals(key, "source"))) {
      continue;  // gen_hazards' region and the grader's source: not the sensor's business
    } else {
      warnings.push_back(place(file, line_number) + "unrecognised line '" +
                         base::escape_for_log(base::excerpt(line)) +
                         "' ignored (expected 'hazard = ...', 'region = ...' or 'source = ...')");
    }
  }
  return counts;
}

}  // namespace hazard
