#pragma once
// Edge helpers shared by the programs (uFldHazardSensor, hazard_replay, gen_hazards, the
// mission apps): the I/O and operating-system pieces that the pure libraries leave to callers,
// and the one wiring of the sensor engine that uFldHazardSensor and hazard_replay share.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hazard/config.hpp"
#include "hazard/engine.hpp"
#include "moos/mission.hpp"

namespace app_support {

/// A seed from the operating system's entropy source (std::random_device); the wall clock
/// only if that source is unavailable. Used when `seed_random = true` (differences.md "Seeds").
std::uint64_t operating_system_seed();

/// A hazard-file reader for the engine's configuration loader: relative paths are resolved
/// against `mission_directory` (the folder of the .moos file), as the original does; a file that
/// cannot be read gives base::read_file_text's reason.
hazard::HazardFileReader mission_relative_reader(std::string mission_directory);

/// The engine's MissionOrigin from a mission's LatOrigin/LongOrigin globals: any `mission` with
/// global_double(key) and global(key) (moos::MissionFile, moos::AppSettings).
template <class Mission>
hazard::MissionOrigin mission_origin(const Mission& mission) {
  return hazard::MissionOrigin{mission.global_double("LatOrigin"),
                               mission.global_double("LongOrigin"), mission.global("LatOrigin"),
                               mission.global("LongOrigin")};
}

/// A ProcessConfig block's lines as engine configuration entries (key, value, file, line).
std::vector<hazard::ConfigEntry> to_config_entries(const std::vector<moos::ConfigLine>& lines);

/// The sensor engine of a uFldHazardSensor block, built the one way uFldHazardSensor and
/// hazard_replay both use: the block's lines go to hazard::load_configuration in file order
/// with their file and line, hazard files are read relative to `mission_directory`, `origin`
/// (the mission's LatOrigin/LongOrigin) places LAT/LON-only input, and the seed is resolved
/// (`command_line_seed`, else random_seed, else seed_random: `os_seed()`, else seed 1;
/// differences.md "Seeds"). Never fails: configuration problems become the engine's config warnings
/// (D26).
hazard::Engine make_sensor_engine(const std::vector<moos::ConfigLine>& block_lines,
                                  const std::string& mission_directory,
                                  const hazard::MissionOrigin& origin,
                                  std::optional<std::uint64_t> command_line_seed,
                                  const std::function<std::uint64_t()>& os_seed);

/// The same, hazard files read by `read` (a host that serves a field from memory).
hazard::Engine make_sensor_engine(const std::vector<moos::ConfigLine>& block_lines,
                                  const hazard::HazardFileReader& read,
                                  const hazard::MissionOrigin& origin,
                                  std::optional<std::uint64_t> command_line_seed,
                                  const std::function<std::uint64_t()>& os_seed);

/// --help lines of the switches every app takes (the MOOS-IvP wording): --alias and the four
/// information switches.
std::string information_switches_help(const std::string& app_name);
/// --help lines of the generic switches (--NAME=value, --moos_*) and the pAntler run-alias note,
/// ending in a blank line.
std::string generic_switches_help();

}  // namespace app_support
