#pragma once
// The hazard object line (manual 5, docs/hazard-file.md; docs/differences.md, "Hazard files").
//
// Example: x=37,y=-207,label=99,type=benign,hr=0.73,aspect=57,aspect_min=20,aspect_max=45
// (in a hazard file or a configuration block it follows `hazard = `).
//
// Keys are case-insensitive, values trimmed. x and y (or lat and lon), label and type are
// mandatory; `hazard=true|false` may stand in for a missing type (original). A bad simulation
// value (x, y, type, hr, aspect fields) rejects the line; a bad rendering hint (color, shape,
// width) is dropped with a warning and the object still loads; an unknown key is warned and
// ignored. A partial aspect triple loads without aspect sensitivity, with a warning.
// Position: x and y when given (then `lat`/`lon` are ignored). A line with `lat` and `lon` but no
// x/y is placed through a GeoPlacement (geodesy.hpp: the mission's LatOrigin/LongOrigin and the
// `geodesy` mode), lat in [-90, 90], lon in [-180, 360]; without a projection it is rejected with
// the placement's reason.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hazard/geodesy.hpp"
#include "hazard/hazard_object.hpp"

namespace hazard {

struct HazardLineParse {
  std::optional<HazardObject> object;  ///< set when the line is accepted
  std::string error;                   ///< why the line was rejected (names field and value)
  std::vector<std::string> warnings;   ///< non-fatal problems (each names field and value)
};

/// Parses the text after `hazard =` (a lat/lon-only line is rejected).
HazardLineParse parse_hazard_line(std::string_view spec);
/// The same, placing a lat/lon-only line with `placement` (nullptr: none).
HazardLineParse parse_hazard_line(std::string_view spec, const GeoPlacement* placement);

/// Renders in the order x, y, label, type, color, shape, width, hr, aspect, aspect_min,
/// aspect_max (docs/hazard-file.md; the original's shape bug fixed). x and y use FMT(.,2), the
/// rest FMT.
/// hr is written for benign objects only.
std::string format_hazard_line(const HazardObject& object);

}  // namespace hazard
