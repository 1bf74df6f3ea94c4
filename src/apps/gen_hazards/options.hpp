#pragma once
// gen_hazards' command line (docs/differences.md D30, D31, and the decisions in
// docs/gen_hazards.md): one table of options (name, value, default, range, meaning) that the
// parser, --help and the docs test all read.
//
// Contract
// - Arguments are processed left to right; a repeated scalar option takes the last value
//   (the original's habit). `--polygon` and `--objects` are repeatable and keep their order.
// - Every rejected argument adds one error that quotes the argument as given; nothing is
//   clamped or repaired silently (the original clipped --exp and truncated counts with atoi).
// - `--help`/`--version` anywhere win over errors (main prints the text and exits 0).
// - `recorded_args` is what the header comment repeats: every argument in order except
//   `--seed` (appended by the header with the effective seed) and `--output` (where the file
//   goes does not change what is in it, so the same command gives byte-identical files).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hazard/hazard_object.hpp"
#include "mission/polygon.hpp"

namespace gen_hazards {

/// Exit codes: success (also --help and --version), the output file could not be written,
/// and bad input (a bad argument or a field that cannot be generated; nothing is written).
inline constexpr int kExitOk = 0;
inline constexpr int kExitCannotWrite = 1;
inline constexpr int kExitBadInput = 2;

/// --exp range (manual 6.3, differences.md D31); values outside are errors.
inline constexpr double kMinResemblanceExp = 0.01;
inline constexpr double kMaxResemblanceExp = 10.0;
/// --aspect_range: the spread of optimal aspects, at most a full turn.
inline constexpr double kMaxAspectRangeDeg = 360.0;
/// --aspect_{min,max}_{base,range}: each in [0, 90].
inline constexpr double kMaxAspectWindowDeg = 90.0;
/// Most objects one run may generate (all sets together): the largest field the design plans
/// for (design.md "Scale"). Larger requests are an error rather than a long wait for memory.
inline constexpr std::uint64_t kMaxTotalObjects = 1'000'000;

/// Aspect defaults of the original: aspect uniform over the full circle, window
/// half-width 15 deg, no spread.
inline constexpr double kDefaultAspectBaseDeg = 0.0;
inline constexpr double kDefaultAspectRangeDeg = 360.0;
inline constexpr double kDefaultAspectMinBaseDeg = 15.0;
inline constexpr double kDefaultAspectMinRangeDeg = 0.0;
inline constexpr double kDefaultAspectMaxRangeDeg = 0.0;

/// One `--polygon`: the region and the argument exactly as given (for messages).
struct Region {
  mission::ConvexPolygon polygon;
  std::string argument;
};

/// One `--objects=N,TYPE`.
struct ObjectSet {
  std::uint64_t count = 0;
  hazard::ObjectType type = hazard::ObjectType::kBenign;
  std::string argument;
};

/// Aspect generation (manual 7), all in degrees. Present when any aspect
/// option is given.
struct AspectOptions {
  double base_deg = kDefaultAspectBaseDeg;          ///< any finite value, used modulo 360
  double range_deg = kDefaultAspectRangeDeg;        ///< [0, 360]
  double min_base_deg = kDefaultAspectMinBaseDeg;   ///< [0, 90]
  double min_range_deg = kDefaultAspectMinRangeDeg; ///< [0, 90]
  /// [0, 90]; not set: aspect_max starts at the object's drawn aspect_min (the original).
  std::optional<double> max_base_deg;
  double max_range_deg = kDefaultAspectMaxRangeDeg;  ///< [0, 90]
};

/// Everything the generator needs; the seed is filled in by the caller (main picks one from
/// the operating system when --seed is absent).
struct GeneratorConfig {
  std::vector<Region> regions;
  std::vector<ObjectSet> sets;
  std::optional<double> resemblance_exp;  ///< --exp, in [0.01, 10]; not set: no hr
  std::optional<AspectOptions> aspect;    ///< not set: no aspect fields
  std::uint64_t seed = 0;
};

/// The objects of all sets together.
std::uint64_t total_objects(const GeneratorConfig& config);

struct CommandLine {
  bool help = false;
  bool version = false;
  GeneratorConfig config;                  ///< config.seed is 0 here; see `seed`
  std::optional<std::uint64_t> seed;       ///< --seed, when given
  std::optional<std::string> output_path;  ///< --output, when given (non-empty)
  std::vector<std::string> recorded_args;  ///< for the header comment (see file comment)
  std::vector<std::string> errors;         ///< one per bad argument, each quoting it
};

/// Parses the arguments after the program name.
CommandLine parse_command_line(const std::vector<std::string>& args);

/// One row of the option table, for --help and docs/gen_hazards.md.
struct OptionDoc {
  std::string name;          ///< e.g. "--exp=E"
  std::string meaning;       ///< one or more sentences
  std::string default_text;  ///< e.g. "off"
  std::string range_text;    ///< e.g. "[0.01, 10]"
};

/// Every option, in the order --help lists them (help and version last).
const std::vector<OptionDoc>& option_docs();

/// `// gen_hazards <recorded args...> --seed=N`: the program name is always `gen_hazards`
/// (not argv[0]'s path), arguments that a POSIX shell would split or expand are single-quoted,
/// so the line can be pasted back into a shell to regenerate the file.
std::string header_line(const std::vector<std::string>& recorded_args, std::uint64_t seed);

}  // namespace gen_hazards
