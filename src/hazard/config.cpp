#include "hazard/config.hpp"

#include <cmath>
#include <limits>
#include <map>

#include "hazard/ranges.hpp"
#include "hazard/style.hpp"
#include "base/text.hpp"

namespace hazard {

namespace {

// Upper bound of swath_substeps: 100 poses per report interval is far beyond any accuracy gain
// (docs/accuracy.md: 4 already closes 10 m gaps) and bounds the work and the pieces held per
// evaluation (100 x kMaxTrackPoses at worst).
constexpr double kMaxSwathSubsteps = 100.0;

ValueRange at_least(double lo) { return ValueRange{lo, true, std::nullopt, true, std::nullopt}; }
ValueRange above(double lo) { return ValueRange{lo, false, std::nullopt, true, std::nullopt}; }
ValueRange above_to(double lo, double hi) { return ValueRange{lo, false, hi, true, std::nullopt}; }
ValueRange between(double lo, double hi) { return ValueRange{lo, true, hi, true, std::nullopt}; }

// The one table (loader, docs table and --example read it). Defaults are differences.md
// "Effective defaults".
const std::vector<ParameterSpec>& table() {
  using K = ParamKind;
  using C = EngineConfig;
  static const std::vector<ParameterSpec> t = {
      {"hazard_file", "", K::kHazardFile, "", "", {},
       "A file of `hazard = ...` lines; repeatable, every file loads; relative to the mission file",
       "manual 5", {}},
      {"hazard", "", K::kHazardLine, "", "", {},
       "One object written in the block (same format as a hazard file line); repeatable",
       "manual 5", {}},
      {"sensor_config", "", K::kSensorConfig, "", "", {},
       "One sensor option `width=W,exp=E,pclass=P[,max=N]` (`class` = `pclass`); repeatable",
       "manual 4, D20", {}},
      {"swath_length", "", K::kNumber, "m", "5",
       ValueRange{0.0, false, kMaxSwathLength_m, true, 1.0},
       "Total along-track length of the swath, half fore and half aft; below 1 it is raised to 1",
       "D1", &C::swath_length_m},
      {"min_reset_interval", "", K::kNumber, "s", "300", between(0.0, kMaxInterval_s),
       "Minimum time between width changes of one vehicle; pd may change at any time",
       "manual 4.4, D11", &C::min_reset_interval_s},
      {"min_classify_interval", "classify_period", K::kNumber, "s", "30",
       between(0.0, kMaxInterval_s),
       "At most one classification answer per vehicle per interval", "manual 3.2, D9",
       &C::min_classify_interval_s},
      {"options_summary_interval", "", K::kNumber, "s", "10", between(0.0, kMaxInterval_s),
       "Time between UHZ_OPTIONS_SUMMARY postings; 0 posts every iteration", "manual 4.5",
       &C::options_summary_interval_s},
      {"max_turn_rate", "", K::kGate, "deg/s", "1.5", above_to(0.0, kMaxTurnRateGate_dps),
       "Sensor off while the turn rate over the last 2 s exceeds this; `off` disables the gate",
       "manual 8, D13", &C::max_turn_rate_dps},
      {"max_vehicle_speed", "", K::kGate, "m/s", "2", above_to(0.0, kMaxSpeedGate_mps),
       "Sensor off while the reported speed exceeds this; `off` disables the gate", "manual 9, D14",
       &C::max_vehicle_speed_mps},
      {"ignore_resemblances", "", K::kBool, "", "false", {},
       "Ignore the objects' hazard resemblance factors (hr)", "manual 6.4",
       &C::ignore_resemblances},
      {"ignore_aspect", "", K::kBool, "", "false", {},
       "Ignore the objects' aspect fields: no aspect degradation (the aspect axis is still drawn)",
       "extension, manual 7", &C::ignore_aspect},
      {"swath_sweep", "", K::kBool, "", "false", {},
       "Count an object the swath passed over between two node reports, not only at sampled "
       "poses (docs/accuracy.md)",
       "extension", &C::swath_sweep},
      {"swath_substeps", "", K::kCount, "", "0", between(0.0, kMaxSwathSubsteps),
       "0: test the swath at the latest pose each iteration (the original); N: at every node "
       "report and N - 1 poses between two",
       "extension", &C::swath_substeps},
      {"geodesy", "", K::kGeodesy, "", "enu", {},
       "How LAT/LON-only node reports and lat/lon hazard lines are placed around the mission's "
       "LatOrigin/LongOrigin (docs/accuracy.md)",
       "extension", &C::geodesy},
      {"seed_random", "", K::kBool, "", "true", {},
       "true: dice seeded by the operating system; false: seed 1 (reproducible runs)", "D16",
       &C::seed_random},
      {"random_seed", "", K::kSeed, "", "", {},
       "Fixes the dice seed (beats seed_random; hazard_replay --seed beats it)",
       "differences.md \"Seeds\"", &C::random_seed},
      {"show_hazards", "", K::kBool, "", "true", {},
       "Post a VIEW_MARKER (and aspect VIEW_SEGLIST) per object at start-up and on PMV_CONNECT",
       "manual 7.6", &C::show_hazards},
      {"show_swath", "", K::kBool, "", "true", {},
       "Post each sensing vehicle's swath (VIEW_POLYGON)", "manual 7.5", &C::show_swath},
      {"show_pd", "", K::kBool, "", "true", {}, "Show pd in the swath label", "manual 7.8",
       &C::show_pd},
      {"show_pfa", "", K::kBool, "", "false", {}, "Show pfa in the swath label", "manual 7.8, D15",
       &C::show_pfa},
      {"show_detections", "show_reports", K::kShowDetections, "s", "nolimit", at_least(0.0),
       "Seconds a detection circle stays drawn; `nolimit` keeps it; 0 draws no circles at all",
       "manual 7.7, D38", &C::show_detections},
      {"swath_transparency", "", K::kNumber, "", "0.2", between(0.0, 1.0),
       "Transparency of the drawn swath", "manual 7.5, D38", &C::swath_transparency},
      {"default_hazard_color", "", K::kColor, "", "green", {}, "Marker colour of hazards",
       "manual 7.6, D17", &C::hazard_color},
      {"default_hazard_shape", "", K::kShape, "", "triangle", {},
       "Marker shape of hazards (circle, square, diamond, triangle, efield, gateway)",
       "manual 7.6", &C::hazard_shape},
      {"default_hazard_width", "", K::kNumber, "m", "8", between(0.0, kMaxMarkerWidth_m),
       "Marker width of hazards",
       "manual 7.6", &C::hazard_marker_width_m},
      {"default_benign_color", "", K::kColor, "", "light_blue", {},
       "Marker colour of benign objects", "manual 7.6, D18", &C::benign_color},
      {"default_benign_shape", "", K::kShape, "", "triangle", {},
       "Marker shape of benign objects", "manual 7.6", &C::benign_shape},
      {"default_benign_width", "", K::kNumber, "m", "8", between(0.0, kMaxMarkerWidth_m),
       "Marker width of benign objects", "manual 7.6", &C::benign_marker_width_m},
      {"rn_algorithm", "", K::kNoEffect, "", "", {},
       "The original's dead feature: accepted with a warning, no effect",
       "docs/differences.md", {}},
      {"rn_uniform_pct", "", K::kNoEffect, "", "", {},
       "The original's dead feature: accepted with a warning, no effect",
       "docs/differences.md", {}},
      {"AppTick", "", K::kFramework, "Hz", "4", above(0.0),
       "Iterations per second (MOOS time); hazard_replay iterates at this rate",
       "docs/protocol.md 6.3", &C::app_tick_hz},
      {"IdleAppTick", "", K::kFramework, "Hz", "", {},
       "Ours, opt-in: while nothing is to be done, iterate at this rate instead of every AppTick "
       "slot; mail wakes the app at once (docs/differences.md)",
       "include/moos/app.hpp", {}},
      {"CommsTick", "", K::kFramework, "Hz", "", {}, "Mail fetches per second",
       "docs/protocol.md 6.3", {}},
      {"MaxAppTick", "", K::kFramework, "Hz", "", {}, "Iteration rate limit in iterate mode 1",
       "docs/protocol.md 6.3", {}},
      {"IterateMode", "", K::kFramework, "", "", {}, "MOOS iterate mode 0, 1 or 2",
       "docs/protocol.md 6.3", {}},
      {"CatchCommandMessages", "", K::kFramework, "", "", {}, "MOOS framework switch",
       "docs/protocol.md 6.3", {}},
      {"SortMailByTime", "", K::kFramework, "", "", {}, "MOOS framework switch",
       "docs/protocol.md 6.3", {}},
      {"UseMOOSComms", "", K::kFramework, "", "", {}, "MOOS framework switch",
       "docs/protocol.md 6.3", {}},
      {"term_report_interval", "", K::kFramework, "s", "", {},
       "Minimum real time between terminal/AppCast reports", "docs/protocol.md 7.2", {}},
      {"max_appcast_events", "", K::kFramework, "", "", {}, "Events kept in the AppCast",
       "docs/protocol.md 7.2", {}},
      {"max_appcast_run_warnings", "", K::kFramework, "", "", {},
       "Distinct run warnings kept in the AppCast", "docs/protocol.md 7.2", {}},
      {"comms_policy", "", K::kFramework, "", "", {}, "AppCasting comms policy",
       "docs/protocol.md 7.2", {}},
      {"app_logging", "", K::kFramework, "", "", {}, "AppCasting log capture",
       "docs/protocol.md 7.2", {}},
      {"deprecated_ok", "", K::kFramework, "", "", {}, "AppCasting switch",
       "docs/protocol.md 7.2", {}},
      {"moos_*", "", K::kFramework, "", "", {},
       "Block versions of the MOOS command-line switches (moos_time_warp, ...)",
       "docs/protocol.md 6.3", {}},
  };
  return t;
}

std::string number_text(double v) { return std::isinf(v) ? (v > 0 ? "inf" : "-inf") : base::fmt(v); }

bool in_range(double v, const ValueRange& r) {
  if (r.min && (v < *r.min || (!r.min_inclusive && v == *r.min))) return false;
  if (r.max && (v > *r.max || (!r.max_inclusive && v == *r.max))) return false;
  return true;
}

std::string interval_text(const ValueRange& r) {
  std::string out = r.min ? (r.min_inclusive ? "[" : "(") + number_text(*r.min) : "(-inf";
  out += ", ";
  out += r.max ? number_text(*r.max) + (r.max_inclusive ? "]" : ")") : "inf)";
  return out;
}

// The outcome of applying one value: `error` set = rejected (nothing changed); `note` set =
// applied with a remark (raised value, no-effect parameter).
struct Applied {
  std::string error;
  std::string note;
};

Applied apply_number(double& field, const ParameterSpec& spec, std::string_view value) {
  const auto v = base::parse_number(value);
  if (!v) return {"not a finite number", {}};
  if (!in_range(*v, spec.range)) return {"outside " + interval_text(spec.range), {}};
  if (spec.range.raise_below && *v < *spec.range.raise_below) {
    field = *spec.range.raise_below;
    return {{}, "raised to " + base::fmt(*spec.range.raise_below)};
  }
  field = *v;
  return {};
}

Applied apply_value(EngineConfig& config, const ParameterSpec& spec, std::string_view value) {
  switch (spec.kind) {
    case ParamKind::kNumber:
      return apply_number(config.*std::get<double EngineConfig::*>(spec.target), spec, value);
    case ParamKind::kFramework:
      if (auto* target = std::get_if<double EngineConfig::*>(&spec.target)) {
        return apply_number(config.**target, spec, value);
      }
      return {};
    case ParamKind::kGate: {
      auto& field = config.*std::get<std::optional<double> EngineConfig::*>(spec.target);
      if (base::iequals(value, "off")) {
        field.reset();
        return {};
      }
      double v = 0.0;
      Applied a = apply_number(v, spec, value);
      if (!a.error.empty()) a.error += " (or 'off')";
      if (a.error.empty()) field = v;
      return a;
    }
    case ParamKind::kBool: {
      bool& field = config.*std::get<bool EngineConfig::*>(spec.target);
      if (base::iequals(value, "toggle")) {
        field = !field;
        return {};
      }
      const auto b = base::parse_bool(value);
      if (!b) return {"not a boolean word (true/false, yes/no, on/off, toggle)", {}};
      field = *b;
      return {};
    }
    case ParamKind::kColor:
      if (!is_known_color(value)) return {"not a known colour", {}};
      config.*std::get<std::string EngineConfig::*>(spec.target) = std::string(value);
      return {};
    case ParamKind::kShape: {
      const std::string shape = base::to_lower(value);
      if (!is_known_shape(shape)) return {"not a known shape", {}};
      config.*std::get<std::string EngineConfig::*>(spec.target) = shape;
      return {};
    }
    case ParamKind::kShowDetections: {
      auto& field = config.*std::get<DetectionCircles EngineConfig::*>(spec.target);
      if (base::iequals(value, "nolimit") || base::iequals(value, "unlimited")) {
        field = DetectionCircles{true, std::nullopt};
        return {};
      }
      double v = 0.0;
      Applied a = apply_number(v, spec, value);
      if (!a.error.empty()) {
        a.error += " (or 'nolimit')";
        return a;
      }
      field = v > 0.0 ? DetectionCircles{true, v} : DetectionCircles{false, std::nullopt};
      return a;
    }
    case ParamKind::kSeed: {
      const auto seed = base::parse_unsigned(value);
      if (!seed) return {"not a whole number in [0, 2^64)", {}};
      config.*std::get<std::optional<std::uint64_t> EngineConfig::*>(spec.target) = *seed;
      return {};
    }
    case ParamKind::kCount: {
      double v = 0.0;
      Applied a = apply_number(v, spec, value);
      if (a.error.empty() && v != std::floor(v)) a.error = "not a whole number";
      if (a.error.empty()) config.*std::get<int EngineConfig::*>(spec.target) = static_cast<int>(v);
      return a;
    }
    case ParamKind::kGeodesy: {
      const auto mode = parse_geodesy_mode(value);
      if (!mode) return {"not one of tangent, enu, azimuthal, utm, off", {}};
      config.*std::get<GeodesyMode EngineConfig::*>(spec.target) = *mode;
      return {};
    }
    case ParamKind::kNoEffect:
      return {{}, "has no effect (accepted for compatibility with the original)"};
    case ParamKind::kHazardFile:
    case ParamKind::kHazardLine:
    case ParamKind::kSensorConfig:
      break;  // handled by the loader
  }
  return {};
}

std::string place(const ConfigEntry& e) { return e.file + ":" + std::to_string(e.line) + ": "; }

/// Mission text in a warning goes through base::log_excerpt, since a mission line may hold any
/// byte but a newline (an ESC sequence in a value reached the terminal report).
std::string parameter_value(const ConfigEntry& e) {
  return "parameter '" + base::log_excerpt(e.key) + "' value '" + base::log_excerpt(e.value) + "'";
}

// The value the block gives `geodesy` (its last valid line, D36), read before the other lines
// so that hazard lines anywhere in the block are placed with it.
GeodesyMode geodesy_in_block(const std::vector<ConfigEntry>& entries) {
  GeodesyMode mode = EngineConfig().geodesy;
  for (const ConfigEntry& e : entries) {
    const ParameterSpec* spec = find_parameter(e.key);
    if (!spec || spec->kind != ParamKind::kGeodesy) continue;
    if (const auto m = parse_geodesy_mode(e.value)) mode = *m;
  }
  return mode;
}

// One origin global checked: a number in range, or the reason it is not usable.
std::optional<double> origin_value(const char* name, const std::optional<double>& value,
                                   const std::optional<std::string>& text,
                                   bool (*valid)(double), const char* range,
                                   std::string& problem) {
  if (!text && !value) return std::nullopt;
  const std::string written = text ? *text : base::fmt(*value);
  if (!value) {
    problem = std::string(name) + " value '" + base::log_excerpt(written) + "' is not a number";
  } else if (!valid(*value)) {
    problem = std::string(name) + " value '" + base::log_excerpt(written) + "' is outside " + range;
  } else {
    return value;
  }
  return std::nullopt;
}

class Loader {
 public:
  Loader(const HazardFileReader& read, const MissionOrigin& origin, GeodesyMode mode)
      : read_(read) {
    setup_.config.geodesy = mode;
    place_origin(origin);
  }

  void load(const ConfigEntry& e) {
    const ParameterSpec* spec = find_parameter(e.key);
    if (!spec) {
      warn(place(e) + "unknown parameter '" + base::log_excerpt(e.key) + "' (value '" +
           base::log_excerpt(e.value) + "') ignored");
      return;
    }
    if (base::trim(e.value).empty()) {
      warn(place(e) + "parameter '" + base::log_excerpt(e.key) + "' has no value; ignored");
      return;
    }
    switch (spec->kind) {
      case ParamKind::kHazardFile: return load_hazard_file(e);
      case ParamKind::kHazardLine:
        load_hazard_spec(e.value, e.file, e.line, setup_.field, setup_.config_warnings,
                         &setup_.placement);
        return;
      case ParamKind::kSensorConfig: return load_sensor_config(e);
      default: return load_scalar(*spec, e);
    }
  }

  EngineSetup finish() {
    if (setup_.field.size() == 0) {
      warn("no hazard field: no objects were loaded (hazard_file or hazard lines), so nothing "
           "can be detected");
    }
    if (setup_.config.options.empty()) {
      warn("no sensor_config: vehicles can never get a sensor setting, so nothing can be "
           "detected");
    }
    if (setup_.config.swath_sweep && setup_.config.swath_substeps > 0) {
      warn("swath_substeps = " + std::to_string(setup_.config.swath_substeps) +
           " is ignored: swath_sweep = true sweeps the swath exactly");
    }
    return std::move(setup_);
  }

 private:
  void warn(std::string text) { setup_.config_warnings.push_back(std::move(text)); }

  // The origin and the placement built from it (geodesy.hpp); an unusable origin is a warning.
  void place_origin(const MissionOrigin& o) {
    std::string problem;
    const auto lat = origin_value("LatOrigin", o.lat_deg, o.lat_text, valid_latitude,
                                  "[-90, 90]", problem);
    const auto lon = origin_value("LongOrigin", o.lon_deg, o.lon_text, valid_longitude,
                                  "[-180, 360]", problem);
    const bool lat_given = o.lat_text || o.lat_deg, lon_given = o.lon_text || o.lon_deg;
    if (problem.empty() && lat_given != lon_given) {
      problem = lat_given ? "LatOrigin is given without LongOrigin"
                          : "LongOrigin is given without LatOrigin";
    }
    if (!problem.empty()) {
      warn("mission file: " + problem +
           "; LAT/LON-only node reports and lat/lon hazard lines cannot be placed");
      setup_.placement.unavailable = "the mission's " + problem;
      return;
    }
    if (!lat || !lon) return;  // no origin: the placement's default reason
    setup_.config.origin = GeodeticOrigin{*lat, *lon};
    if (setup_.config.geodesy == GeodesyMode::kOff) {
      setup_.placement.unavailable = "geodesy = off";
      return;
    }
    setup_.placement.projection.emplace(*setup_.config.origin, setup_.config.geodesy);
  }

  void load_hazard_file(const ConfigEntry& e) {
    HazardFileStatus status;
    status.path = std::string(base::trim(e.value));
    const base::Result<std::string> text = read_(status.path);
    if (!text) {
      warn(place(e) + "cannot read hazard file '" + base::log_excerpt(status.path) +
           "': " + base::log_excerpt(text.error));
    } else {
      status.read_ok = true;
      status.counts = load_hazard_file_text(*text.value, base::escape_for_log(status.path),
                                            setup_.field, setup_.config_warnings,
                                            &setup_.placement);
    }
    setup_.hazard_files.push_back(std::move(status));
  }

  void load_sensor_config(const ConfigEntry& e) {
    SensorConfigParse parsed = parse_sensor_config(e.value);
    for (const std::string& w : parsed.warnings) warn(place(e) + "sensor_config: " + w);
    if (!parsed.option) {
      warn(place(e) + parameter_value(e) + ": " + parsed.error + "; option rejected");
      return;
    }
    const base::Result<std::size_t> added = setup_.config.options.add(std::move(*parsed.option));
    if (!added) {
      warn(place(e) + parameter_value(e) + ": " + added.error + "; option rejected");
    }
  }

  void load_scalar(const ParameterSpec& spec, const ConfigEntry& e) {
    const std::string canonical = base::to_lower(spec.name == "moos_*" ? e.key : spec.name);
    const auto [it, first] = seen_.emplace(canonical, place(e));
    if (!first) {
      warn(place(e) + "parameter '" + base::log_excerpt(e.key) + "' repeated (also at " +
           it->second.substr(0, it->second.size() - 2) + "); the last value is used");
      it->second = place(e);
    }
    const Applied a = apply_value(setup_.config, spec, base::trim(e.value));
    if (!a.error.empty()) {
      warn(place(e) + parameter_value(e) + ": " + a.error + "; ignored");
    } else if (!a.note.empty()) {
      warn(place(e) + parameter_value(e) + ": " + a.note);
    }
  }

  const HazardFileReader& read_;
  EngineSetup setup_;
  std::map<std::string, std::string> seen_;  // canonical name -> "file:line: " of the last one
};

std::string markdown_row(const ParameterSpec& p) {
  std::string aliases = p.aliases.empty() ? "" : " (alias `" + std::string(p.aliases) + "`)";
  std::string def = p.default_text.empty() ? "none" : "`" + std::string(p.default_text) + "`";
  return "| `" + std::string(p.name) + "`" + aliases + " | " + allowed_values_text(p) + " | " +
         (p.unit.empty() ? "" : std::string(p.unit)) + " | " + def + " | " + std::string(p.help) +
         " | " + std::string(p.reference) + " |\n";
}

}  // namespace

EngineConfig::EngineConfig() {
  for (const ParameterSpec& spec : table()) {
    if (!spec.default_text.empty() && !std::holds_alternative<std::monostate>(spec.target)) {
      apply_value(*this, spec, spec.default_text);
    }
  }
}

const std::vector<ParameterSpec>& parameter_table() { return table(); }

const ParameterSpec* find_parameter(std::string_view key) {
  key = base::trim(key);
  for (const ParameterSpec& spec : table()) {
    if (base::iequals(spec.name, key)) return &spec;
    for (std::string_view alias : base::split_trimmed(spec.aliases, ',')) {
      if (!alias.empty() && base::iequals(alias, key)) return &spec;
    }
  }
  if (key.size() > 5 && base::iequals(key.substr(0, 5), "moos_")) {
    for (const ParameterSpec& spec : table()) {
      if (spec.name == "moos_*") return &spec;
    }
  }
  return nullptr;
}

std::string allowed_values_text(const ParameterSpec& p) {
  switch (p.kind) {
    case ParamKind::kNumber: return "number in " + interval_text(p.range);
    case ParamKind::kGate: return "number in " + interval_text(p.range) + ", or `off`";
    case ParamKind::kBool: return "true/false (yes/no, on/off, toggle)";
    case ParamKind::kColor: return "colour";
    case ParamKind::kShape: return "shape";
    case ParamKind::kShowDetections:
      return "number in " + interval_text(p.range) + ", or `nolimit`";
    case ParamKind::kSeed: return "whole number in [0, 2^64)";
    case ParamKind::kCount: return "whole number in " + interval_text(p.range);
    case ParamKind::kGeodesy: return "`tangent`, `enu`, `azimuthal`, `utm` or `off`";
    case ParamKind::kHazardFile: return "path";
    case ParamKind::kHazardLine: return "object spec";
    case ParamKind::kSensorConfig: return "option spec";
    case ParamKind::kFramework:
      if (std::holds_alternative<std::monostate>(p.target)) return "framework";
      return "number in " + interval_text(p.range);
    case ParamKind::kNoEffect: return "anything";
  }
  return {};
}

std::string parameter_table_markdown() {
  std::string out =
      "| Parameter | Allowed values | Unit | Default | Meaning | Reference |\n"
      "|---|---|---|---|---|---|\n";
  for (const ParameterSpec& p : table()) {
    if (p.kind != ParamKind::kFramework) out += markdown_row(p);
  }
  out += "\nParameters of the MOOS application framework, accepted without warnings:\n\n"
         "| Parameter | Allowed values | Unit | Default | Meaning | Reference |\n"
         "|---|---|---|---|---|---|\n";
  for (const ParameterSpec& p : table()) {
    if (p.kind == ParamKind::kFramework) out += markdown_row(p);
  }
  return out;
}

EngineSetup load_configuration(const std::vector<ConfigEntry>& entries,
                               const HazardFileReader& read) {
  return load_configuration(entries, read, MissionOrigin{});
}

EngineSetup load_configuration(const std::vector<ConfigEntry>& entries,
                               const HazardFileReader& read, const MissionOrigin& origin) {
  Loader loader(read, origin, geodesy_in_block(entries));
  for (const ConfigEntry& e : entries) loader.load(e);
  return loader.finish();
}

SeedChoice resolve_seed(std::optional<std::uint64_t> command_line_seed, const EngineConfig& config,
                        const std::function<std::uint64_t()>& os_seed) {
  if (command_line_seed) return {*command_line_seed, SeedSource::kCommandLine};
  if (config.random_seed) return {*config.random_seed, SeedSource::kRandomSeed};
  if (config.seed_random) return {os_seed(), SeedSource::kOperatingSystem};
  return {kUnseededSeed, SeedSource::kFixed};
}

const char* seed_source_name(SeedSource source) {
  switch (source) {
    case SeedSource::kCommandLine: return "command line";
    case SeedSource::kRandomSeed: return "random_seed";
    case SeedSource::kOperatingSystem: return "operating system";
    case SeedSource::kFixed: return "seed_random = false";
  }
  return "";
}

}  // namespace hazard
