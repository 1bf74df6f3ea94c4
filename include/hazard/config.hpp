#pragma once
// Configuration: the one parameter table (every reader uses it) and the loader that turns a list of
// configuration entries (key, value, where written) into typed values. Where the entries come
// from (a MOOS mission file's ProcessConfig block, read by libmoos) is the program's business.
//
// Contract: every parameter is described once in parameter_table() (name, aliases, kind, unit,
// default, allowed range, help); the defaults of EngineConfig, the parser, the docs table
// (parameter_table_markdown) and the app's --example all read it. The loader applies the rules of
// differences.md: names case-insensitive, lines in file order, a repeated scalar takes the last
// value with a warning (D36, whole block); each rejected value keeps the previous value (the
// default) and produces a config warning naming file, line, parameter and value ("Validation",
// D38);
// hazard files are read through the caller's reader (libhazard does no I/O). Framework keys
// (AppTick, CommsTick, ...) are accepted silently; AppTick's value is kept for hazard_replay.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "base/result.hpp"
#include "hazard/geodesy.hpp"
#include "hazard/hazard_field.hpp"
#include "hazard/sensor_options.hpp"

namespace hazard {

/// One `key = value` line of the configuration block, where it was written.
struct ConfigEntry {
  std::string key;
  std::string value;
  std::string file;
  int line = 0;
};

/// show_detections / show_reports (docs/messages.md, D38).
struct DetectionCircles {
  bool enabled = true;               ///< false: no circles at all (value 0)
  std::optional<double> duration_s;  ///< nullopt: no limit ("nolimit")
};

struct EngineConfig {
  /// Every field at its table default.
  EngineConfig();

  double swath_length_m;            ///< total along-track length (D1)
  double min_reset_interval_s;      ///< D11
  double min_classify_interval_s;   ///< D9
  double options_summary_interval_s;
  std::optional<double> max_turn_rate_dps;     ///< nullopt: gate off
  std::optional<double> max_vehicle_speed_mps; ///< nullopt: gate off
  bool ignore_resemblances;
  bool ignore_aspect;   ///< extension: the aspect effect off (effects.hpp)
  bool swath_sweep;     ///< extension: the swept swath between node reports (sensing_track.hpp)
  int swath_substeps;   ///< extension: 0 = sample at iterations; N = N poses per report interval
  GeodesyMode geodesy;  ///< how LAT/LON-only input is placed (geodesy.hpp)
  /// The mission's LatOrigin/LongOrigin (file globals, not the block): set by
  /// load_configuration when both are given, numbers and in range; nullopt otherwise.
  std::optional<GeodeticOrigin> origin;
  bool seed_random;
  std::optional<std::uint64_t> random_seed;
  bool show_hazards;
  bool show_swath;
  bool show_pd;
  bool show_pfa;
  DetectionCircles show_detections;
  double swath_transparency;
  std::string hazard_color;
  std::string hazard_shape;
  double hazard_marker_width_m;
  std::string benign_color;
  std::string benign_shape;
  double benign_marker_width_m;
  double app_tick_hz;  ///< the framework's AppTick (hazard_replay's iteration rate)
  SensorOptions options;
};

enum class ParamKind {
  kNumber,          ///< finite number within `range`
  kGate,            ///< number within `range`, or `off`
  kBool,            ///< true/yes/on, false/no/off, toggle
  kColor,           ///< a colour word (style.hpp)
  kShape,           ///< a marker shape word
  kShowDetections,  ///< number >= 0 or nolimit/unlimited
  kSeed,            ///< whole number in [0, 2^64)
  kCount,           ///< whole number within `range`
  kGeodesy,         ///< a geodesy mode word (geodesy.hpp)
  kHazardFile,      ///< path, repeatable
  kHazardLine,      ///< object spec, repeatable
  kSensorConfig,    ///< sensor option, repeatable
  kFramework,       ///< read by the MOOS application framework
  kNoEffect,        ///< the original's dead features: accepted with a warning
};

struct ValueRange {
  std::optional<double> min;
  bool min_inclusive = true;
  std::optional<double> max;
  bool max_inclusive = true;
  /// Values at or above `min` but below this are raised to it with a warning (swath_length).
  std::optional<double> raise_below;
};

using ParamTarget =
    std::variant<std::monostate, double EngineConfig::*, bool EngineConfig::*,
                 std::optional<double> EngineConfig::*, std::string EngineConfig::*,
                 DetectionCircles EngineConfig::*, std::optional<std::uint64_t> EngineConfig::*,
                 int EngineConfig::*, GeodesyMode EngineConfig::*>;

struct ParameterSpec {
  std::string_view name;
  std::string_view aliases;  ///< comma-separated, may be empty
  ParamKind kind;
  std::string_view unit;          ///< "m", "s", "deg/s", "" ...
  std::string_view default_text;  ///< as the docs and --example show it; "" = none
  ValueRange range;
  std::string_view help;          ///< one line
  std::string_view reference;     ///< manual section or differences.md entry
  ParamTarget target;
};

const std::vector<ParameterSpec>& parameter_table();
/// The spec whose name or alias equals `key` case-insensitively; keys starting with `moos_`
/// resolve to the framework entry for them.
const ParameterSpec* find_parameter(std::string_view key);
/// "(0, inf)", "[0, 1]", "> 0 or off", "true/false", ...
std::string allowed_values_text(const ParameterSpec& spec);
/// The docs' parameter table (docs/configuration.md holds it verbatim; a test checks).
std::string parameter_table_markdown();

/// One hazard file named by `hazard_file`.
struct HazardFileStatus {
  std::string path;    ///< as written in the configuration
  bool read_ok = false;
  HazardFileCounts counts;
};

/// Everything the loader produced. Engine takes it whole.
struct EngineSetup {
  EngineConfig config;
  HazardField field;
  std::vector<std::string> config_warnings;
  std::vector<HazardFileStatus> hazard_files;
  /// How LAT/LON-only positions are placed (the projection, or why there is none).
  GeoPlacement placement;
};

/// The mission's LatOrigin and LongOrigin globals, as the program read them (the number, and the
/// text to name a value that is not a number; app_support::mission_origin reads them from a
/// mission file). All empty: the mission gives no origin.
struct MissionOrigin {
  std::optional<double> lat_deg;
  std::optional<double> lon_deg;
  std::optional<std::string> lat_text;  ///< present when the global is written at all
  std::optional<std::string> lon_text;
};

/// Reads a hazard file by the path written in the configuration: its text, or why it cannot be
/// read (the reason goes into the configuration warning after the file's name).
using HazardFileReader = std::function<base::Result<std::string>(const std::string& path)>;

EngineSetup load_configuration(const std::vector<ConfigEntry>& entries,
                               const HazardFileReader& read);
/// The same with the mission's origin: a usable origin (both given, numbers, latitude in
/// [-90, 90], longitude in [-180, 360]) and `geodesy` not `off` place LAT/LON-only positions;
/// an origin given but unusable is a configuration warning naming the global and its value.
EngineSetup load_configuration(const std::vector<ConfigEntry>& entries,
                               const HazardFileReader& read, const MissionOrigin& origin);

/// Where the seed in use came from (differences.md "Seeds").
enum class SeedSource { kCommandLine, kRandomSeed, kOperatingSystem, kFixed };
struct SeedChoice {
  std::uint64_t seed = 1;
  SeedSource source = SeedSource::kFixed;
};
/// The seed seed_random = false uses (the original's unseeded glibc state is seed 1).
inline constexpr std::uint64_t kUnseededSeed = 1;
/// --seed beats random_seed = N, which beats seed_random (true: `os_seed()`; false: seed 1).
SeedChoice resolve_seed(std::optional<std::uint64_t> command_line_seed, const EngineConfig& config,
                        const std::function<std::uint64_t()>& os_seed);
/// "command line", "random_seed", "operating system", "seed_random = false".
const char* seed_source_name(SeedSource source);

}  // namespace hazard
