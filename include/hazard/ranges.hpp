#pragma once
// Physically meaningful ranges: the largest values the engine accepts from its
// configuration and its mail. Each is far beyond any real mission, so only nonsense is refused
// (with a warning naming the value), and no accepted value can overflow the arithmetic or be
// posted as a 309-digit number. The lower bounds (differences.md "Validation") stay where they
// are; these are the upper bounds, which the manual leaves open (docs/configuration.md).
// The ROC exponent has none: a huge exp only makes pfa 0 and is posted as written (N5).

#include <cstddef>

namespace hazard {

/// Sensor width to each side (sensor_config width, UHZ_CONFIG_REQUEST width), m: 1,000 km. The
/// geometry tests pin a million-metre width as a valid extreme (numerics_geometry_test.cpp); a
/// width of 1e308, once posted as a 309-digit number, is refused.
inline constexpr double kMaxSwathWidth_m = 1.0e6;
/// Total swath length (swath_length), m: 1,000 km, as the width.
inline constexpr double kMaxSwathLength_m = 1.0e6;
/// max_vehicle_speed gate, m/s: faster than any vehicle that carries a side-looking sonar.
inline constexpr double kMaxSpeedGate_mps = 100.0;
/// max_turn_rate gate, deg/s: ten turns a second.
inline constexpr double kMaxTurnRateGate_dps = 3600.0;
/// Intervals of the configuration (min_reset_interval, min_classify_interval,
/// options_summary_interval), s: one week.
inline constexpr double kMaxInterval_s = 7.0 * 24.0 * 3600.0;
/// Marker widths (default_hazard_width, default_benign_width), m: 10 km.
inline constexpr double kMaxMarkerWidth_m = 10000.0;
/// |X| and |Y| of a NODE_REPORT, m: 100,000 km, ten times the Earth's scale (UTM-scale and
/// ten-megametre scenes stay valid, tests/hazard/numerics_geometry_test.cpp).
inline constexpr double kMaxNodeCoordinate_m = 1.0e8;
/// |x| and |y| of a hazard object (hazard lines, files), m: as kMaxNodeCoordinate_m, so no
/// field extent can overflow (9e307 and -9e307 used to make it infinite).
inline constexpr double kMaxObjectCoordinate_m = kMaxNodeCoordinate_m;
/// SPD of a NODE_REPORT, m/s: [0, this]; a negative or faster speed is refused.
inline constexpr double kMaxNodeSpeed_mps = 1000.0;

/// A vehicle name (NODE_REPORT NAME, vname), bytes: it becomes part of variable names
/// (UHZ_CONFIG_ACK_<V>) and of log lines, so it must also be free of control bytes.
inline constexpr std::size_t kMaxVehicleNameBytes = 128;
/// An object's label (hazard lines, files), bytes: it is posted in every detection, hazard and
/// classification report about the object and in its marker, so a 1 MB label would make each of
/// those postings a megabyte. Labels that gen_hazards and missions use are a few bytes.
inline constexpr std::size_t kMaxLabelBytes = 256;

}  // namespace hazard
