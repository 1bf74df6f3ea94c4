#pragma once
// The ground-truth field: objects in load order, a label index, and the spatial index.
//
// Object ids are small integers (load order, 0-based); names (labels) appear only at the message
// edge. Loading reads text handed in by the caller (libhazard does no I/O): hazard files
// (rulings "Hazard lines": `hazard =` lines; `region =`, `source =`, comments and blank lines
// skipped; anything else warned) and inline `hazard =` configuration lines. Every problem names
// file, line, field and value; a rejected line never stops the others from loading.
// A duplicate label keeps the first object and reports the later line.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <glm/vec2.hpp>

#include "hazard/geodesy.hpp"
#include "hazard/hazard_object.hpp"
#include "hazard/spatial_grid.hpp"

namespace hazard {

using ObjectId = std::uint32_t;

class HazardField {
 public:
  /// Adds an object; false (and nothing changes) if its label is already present.
  bool add(HazardObject object);
  /// Builds the spatial index; call after the last add() (Engine does).
  void build_index();

  std::size_t size() const { return objects_.size(); }
  const HazardObject& object(ObjectId id) const { return objects_[id]; }
  const std::vector<HazardObject>& objects() const { return objects_; }
  glm::dvec2 position(ObjectId id) const { return positions_[id]; }
  /// Stable 64-bit hash of the label (dice key; see dice.hpp).
  std::uint64_t label_hash(ObjectId id) const { return label_hashes_[id]; }
  /// The id of a label, if present.
  std::optional<ObjectId> find(std::string_view label) const;
  const SpatialGrid& grid() const { return grid_; }

  int hazard_count() const { return hazards_; }
  int benign_count() const { return static_cast<int>(objects_.size()) - hazards_; }

 private:
  std::vector<HazardObject> objects_;
  std::vector<glm::dvec2> positions_;
  std::vector<std::uint64_t> label_hashes_;
  std::unordered_map<std::string, ObjectId> by_label_;
  SpatialGrid grid_;
  int hazards_ = 0;
};

/// Loads one `hazard =` spec found at `file`:`line`. Appends "file:line: ..." warnings.
/// Returns true if an object was added. `placement` places lat/lon-only lines (nullptr: none).
bool load_hazard_spec(std::string_view spec, std::string_view file, int line, HazardField& field,
                      std::vector<std::string>& warnings,
                      const GeoPlacement* placement = nullptr);

/// Counts of one hazard file's accepted objects.
struct HazardFileCounts {
  int hazards = 0;
  int benign = 0;
  int rejected_lines = 0;
};

/// Loads every `hazard =` line of a hazard file's text (see the file comment).
HazardFileCounts load_hazard_file_text(std::string_view text, std::string_view file,
                                       HazardField& field, std::vector<std::string>& warnings,
                                       const GeoPlacement* placement = nullptr);

}  // namespace hazard
