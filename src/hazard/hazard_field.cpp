#include "hazard/hazard_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "hazard/dice.hpp"
#include "hazard/messages/hazard_line.hpp"
#include "base/text.hpp"
#include "base/warning_budget.hpp"

namespace hazard {

namespace {

std::string place(std::string_view file, int line) {
  return std::string(file) + ":" + std::to_string(line) + ": ";
}

// Strips a `//` comment: the sensor and the grader must agree on ground truth, and the grader
// strips comments.
std::string_view without_comment(std::string_view line) {
  const auto pos = line.find("//");
  return pos == std::string_view::npos ? line : line.substr(0, pos);
}

}  // namespace

bool HazardField::add(const HazardObject& object) {
  const std::uint64_t hash = hash_name(object.label);
  if (2 * (size() + 1) > label_slots_.size()) grow_label_slots(2 * (size() + 1));
  const std::size_t slot = slot_of(object.label, hash);
  if (label_slots_[slot] != kNone) return false;
  if (label_chars_.size() + object.label.size() > UINT32_MAX) return false;
  const auto id = static_cast<ObjectId>(size());
  label_slots_[slot] = id;
  label_chars_ += object.label;
  label_ends_.push_back(static_cast<std::uint32_t>(label_chars_.size()));
  positions_.emplace_back(object.x_m, object.y_m);
  types_.push_back(static_cast<std::uint8_t>(object.type));
  resemblances_.push_back(object.resemblance.value_or(std::numeric_limits<double>::quiet_NaN()));
  const bool has_aspect = object.aspect_deg || object.aspect_min_deg || object.aspect_max_deg;
  aspect_index_.push_back(has_aspect ? static_cast<std::uint32_t>(aspects_.size()) : kNone);
  if (has_aspect) {
    aspects_.push_back({object.aspect_deg, object.aspect_min_deg, object.aspect_max_deg});
  }
  const bool has_style = object.color || object.shape || object.source || object.marker_width_m;
  style_index_.push_back(has_style ? static_cast<std::uint32_t>(styles_.size()) : kNone);
  if (has_style) {
    styles_.push_back({object.color, object.shape, object.source, object.marker_width_m});
  }
  if (object.is_hazard()) ++hazards_;
  return true;
}

void HazardField::build_index() {
  grid_ = SpatialGrid(positions_);
  // Loading grew the tables by doubling; a static field needs no spare room.
  positions_.shrink_to_fit();
  types_.shrink_to_fit();
  resemblances_.shrink_to_fit();
  aspect_index_.shrink_to_fit();
  style_index_.shrink_to_fit();
  aspects_.shrink_to_fit();
  styles_.shrink_to_fit();
  label_chars_.shrink_to_fit();
  label_ends_.shrink_to_fit();
}

HazardObject HazardField::object(ObjectId id) const {
  HazardObject o;
  o.x_m = positions_[id].x;
  o.y_m = positions_[id].y;
  o.label = std::string(label(id));
  o.type = type(id);
  o.resemblance = resemblance(id);
  if (aspect_index_[id] != kNone) {
    const Aspect& a = aspects_[aspect_index_[id]];
    o.aspect_deg = a.aspect_deg;
    o.aspect_min_deg = a.aspect_min_deg;
    o.aspect_max_deg = a.aspect_max_deg;
  }
  if (style_index_[id] != kNone) {
    const Style& st = styles_[style_index_[id]];
    o.color = st.color;
    o.shape = st.shape;
    o.source = st.source;
    o.marker_width_m = st.marker_width_m;
  }
  return o;
}

std::optional<double> HazardField::resemblance(ObjectId id) const {
  const double hr = resemblances_[id];
  if (std::isnan(hr)) return std::nullopt;
  return hr;
}

bool HazardField::has_aspect_triple(ObjectId id) const {
  if (aspect_index_[id] == kNone) return false;
  const Aspect& a = aspects_[aspect_index_[id]];
  return a.aspect_deg && a.aspect_min_deg && a.aspect_max_deg;
}

std::string_view HazardField::label(ObjectId id) const {
  const std::uint32_t begin = id == 0 ? 0 : label_ends_[id - 1];
  return std::string_view(label_chars_).substr(begin, label_ends_[id] - begin);
}

std::uint64_t HazardField::label_hash(ObjectId id) const { return hash_name(label(id)); }

std::size_t HazardField::slot_of(std::string_view label, std::uint64_t hash) const {
  const std::size_t mask = label_slots_.size() - 1;  // a power of two
  // FNV's low bits follow the labels' low bits (numeric labels cluster): mixed first.
  for (std::size_t slot = mix64(hash) & mask;; slot = (slot + 1) & mask) {
    const std::uint32_t id = label_slots_[slot];
    if (id == kNone || this->label(id) == label) return slot;
  }
}

void HazardField::grow_label_slots(std::size_t objects) {
  std::size_t slots = 16;
  while (slots < 2 * objects) slots *= 2;
  if (slots <= label_slots_.size()) return;
  label_slots_.assign(slots, kNone);
  // Labels already in are unique: each goes to the first free slot of its probe sequence.
  const std::size_t mask = slots - 1;
  for (ObjectId id = 0; id < size(); ++id) {
    std::size_t slot = mix64(label_hash(id)) & mask;
    while (label_slots_[slot] != kNone) slot = (slot + 1) & mask;
    label_slots_[slot] = id;
  }
}

void HazardField::reserve(std::size_t objects) {
  grow_label_slots(objects);
  positions_.reserve(objects);
  types_.reserve(objects);
  resemblances_.reserve(objects);
  aspect_index_.reserve(objects);
  style_index_.reserve(objects);
  label_ends_.reserve(objects);
}

std::optional<ObjectId> HazardField::find(std::string_view label) const {
  if (label_slots_.empty()) return std::nullopt;
  const std::uint32_t id = label_slots_[slot_of(label, hash_name(label))];
  if (id == kNone) return std::nullopt;
  return id;
}

std::size_t HazardField::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  std::size_t heap = 0;
  for (const Style& st : styles_) {
    for (const auto* text : {&st.color, &st.shape, &st.source})
      if (*text && (*text)->capacity() > 15) heap += (*text)->capacity() + 1;
  }
  return bytes(positions_) + bytes(types_) + bytes(resemblances_) + bytes(aspect_index_) +
         bytes(style_index_) + bytes(aspects_) + bytes(styles_) + heap + label_chars_.capacity() +
         bytes(label_ends_) + bytes(label_slots_) + grid_.memory_bytes();
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
  const auto lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
  field.reserve(field.size() + lines);
  int line_number = 0;
  // A file of a million bad lines keeps kMaxWarningsPerKind warnings and counts the others:
  // each line's warnings are gathered, then pass the file's budget.
  base::WarningBudget budget{base::kMaxWarningsPerKind};
  std::vector<std::string> line_warnings;
  const auto keep_line_warnings = [&] {
    for (std::string& w : line_warnings) budget.add(warnings, std::move(w));
    line_warnings.clear();
  };
  // A UTF-8 byte-order mark is accepted at the start, as in mission files.
  std::size_t start = base::starts_with(text, "\xEF\xBB\xBF") ? 3 : 0;
  while (start <= text.size()) {
    const auto end = text.find('\n', start);
    const std::string_view raw =
        text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    start = end == std::string_view::npos ? text.size() + 1 : end + 1;
    ++line_number;
    keep_line_warnings();
    const std::string_view line = base::trim(without_comment(raw));
    if (line.empty()) continue;
    const auto eq = line.find('=');
    const std::string_view key = base::trim(line.substr(0, eq));
    if (eq != std::string_view::npos && base::iequals(key, "hazard")) {
      const std::size_t before = field.size();
      if (load_hazard_spec(line.substr(eq + 1), file, line_number, field, line_warnings,
                           placement)) {
        (field.is_hazard(static_cast<ObjectId>(before)) ? counts.hazards
                                                                 : counts.benign) += 1;
      } else {
        ++counts.rejected_lines;
      }
    } else if (eq != std::string_view::npos && (base::iequals(key, "region") || base::iequals(key, "source"))) {
      continue;  // gen_hazards' region and the grader's source: not the sensor's business
    } else {
      line_warnings.push_back(place(file, line_number) + "unrecognised line '" +
                              base::log_excerpt(line) +
                              "' ignored (expected 'hazard = ...', 'region = ...' or "
                              "'source = ...')");
    }
  }
  keep_line_warnings();
  if (budget.dropped() > 0) {
    warnings.push_back(std::string(file) + ": " + budget.summary("warnings"));
  }
  return counts;
}

}  // namespace hazard
