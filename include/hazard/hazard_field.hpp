#pragma once
// The ground-truth field: objects in load order, a label index, and the spatial index.
//
// Object ids are small integers (load order, 0-based); names (labels) appear only at the message
// edge. Loading reads text handed in by the caller (libhazard does no I/O): hazard files
// (differences.md "Hazard lines": `hazard =` lines; `region =`, `source =`, comments and blank
// lines skipped; anything else warned) and inline `hazard =` configuration lines. Every problem
// names file, line, field and value; a rejected line never stops the others from loading.
// A duplicate label keeps the first object and reports the later line.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "hazard/geodesy.hpp"
#include "hazard/hazard_object.hpp"
#include "hazard/spatial_grid.hpp"

namespace hazard {

using ObjectId = std::uint32_t;

/// The field stored compactly: flat arrays of what sensing reads, indexed by id.
/// Per object: position (16 bytes), type (1), resemblance (8, NaN when absent), an index into
/// the aspect table and one into the style table (4 + 4, kNone when the object has none: most
/// objects have no rendering hints, many no aspect), its label in one shared character table
/// (4 bytes of offset + the characters), and 8 bytes of label lookup (an open-addressing table
/// of ids at most half full). Nothing per object is a heap allocation of its own; marker text is
/// built when posted. Measured in bench/engine (scale_bench: bytes per object).
/// Rejected alternative: a vector of HazardObject plus a std::unordered_map<std::string, id>
/// (about 370 bytes per object, most of it optional strings and map nodes).
class HazardField {
 public:
  /// An object's aspect fields (manual 7), present when any of the three is.
  struct Aspect {
    std::optional<double> aspect_deg, aspect_min_deg, aspect_max_deg;
    /// All three present: the object is aspect-sensitive.
    bool triple() const { return aspect_deg && aspect_min_deg && aspect_max_deg; }
  };

  /// Adds an object; false (and nothing changes) if its label is already present or the label
  /// table would pass 4 GiB.
  bool add(const HazardObject& object);
  /// Room for `objects` in all (a loader that can count its lines calls it first, so the label
  /// table is not rebuilt as it grows).
  void reserve(std::size_t objects);
  /// Builds the spatial index and releases spare capacity; call after the last add() (Engine does).
  void build_index();

  std::size_t size() const { return types_.size(); }
  /// The object as loaded, rebuilt from the tables (for output and tests; sensing and
  /// classification use the accessors below, which copy nothing and touch only the tables they
  /// read: in a field of a million objects each table read is a cache miss).
  HazardObject object(ObjectId id) const;
  glm::dvec2 position(ObjectId id) const { return positions_[id]; }
  ObjectType type(ObjectId id) const { return static_cast<ObjectType>(types_[id]); }
  bool is_hazard(ObjectId id) const { return type(id) == ObjectType::kHazard; }
  std::optional<double> resemblance(ObjectId id) const;
  bool has_aspect_triple(ObjectId id) const;
  /// The aspect fields; nullptr when the object has none.
  const Aspect* aspect(ObjectId id) const {
    return aspect_index_[id] == kNone ? nullptr : &aspects_[aspect_index_[id]];
  }
  std::string_view label(ObjectId id) const;
  /// Stable 64-bit hash of the label (dice key; see dice.hpp).
  std::uint64_t label_hash(ObjectId id) const;
  /// The id of a label, if present.
  std::optional<ObjectId> find(std::string_view label) const;
  const SpatialGrid& grid() const { return grid_; }

  int hazard_count() const { return hazards_; }
  int benign_count() const { return static_cast<int>(size()) - hazards_; }
  /// Bytes the field's tables hold (capacity, index included), for the scale benchmark.
  std::size_t memory_bytes() const;

 private:
  static constexpr std::uint32_t kNone = UINT32_MAX;
  struct Style {
    std::optional<std::string> color, shape, source;
    std::optional<double> marker_width_m;
  };
  /// Slot of `label` in label_slots_: where it is, or the empty slot where it belongs.
  std::size_t slot_of(std::string_view label, std::uint64_t hash) const;
  /// The label table rebuilt with at least 2 * `objects` slots.
  void grow_label_slots(std::size_t objects);

  std::vector<glm::dvec2> positions_;
  std::vector<std::uint8_t> types_;
  std::vector<double> resemblances_;         ///< NaN: none
  std::vector<std::uint32_t> aspect_index_;  ///< into aspects_, or kNone
  std::vector<std::uint32_t> style_index_;   ///< into styles_, or kNone
  std::vector<Aspect> aspects_;
  std::vector<Style> styles_;
  std::string label_chars_;                  ///< every label, back to back
  std::vector<std::uint32_t> label_ends_;    ///< end of label id in label_chars_
  std::vector<std::uint32_t> label_slots_;   ///< ids by label hash (linear probing), or kNone
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
