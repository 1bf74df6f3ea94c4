#include "app_support.hpp"

#include "base/file.hpp"

#include <chrono>
#include <exception>
#include <filesystem>
#include <random>
#include <utility>

namespace app_support {

std::uint64_t operating_system_seed() {
  try {
    std::random_device device;
    return (static_cast<std::uint64_t>(device()) << 32) ^ static_cast<std::uint64_t>(device());
  } catch (const std::exception&) {
    return static_cast<std::uint64_t>(
        std::chrono::system_clock::now().time_since_epoch().count());
  }
}

hazard::HazardFileReader mission_relative_reader(std::string mission_directory) {
  return [dir = std::filesystem::path(std::move(mission_directory))](const std::string& path) {
    const std::filesystem::path p(path);
    return base::read_file_text((p.is_relative() ? dir / p : p).string());
  };
}

std::vector<hazard::ConfigEntry> to_config_entries(const std::vector<moos::ConfigLine>& lines) {
  std::vector<hazard::ConfigEntry> out;
  out.reserve(lines.size());
  for (const moos::ConfigLine& l : lines) out.push_back({l.key, l.value, l.file, l.line});
  return out;
}

hazard::Engine make_sensor_engine(const std::vector<moos::ConfigLine>& block_lines,
                                  const std::string& mission_directory,
                                  const hazard::MissionOrigin& origin,
                                  std::optional<std::uint64_t> command_line_seed,
                                  const std::function<std::uint64_t()>& os_seed) {
  return make_sensor_engine(block_lines, mission_relative_reader(mission_directory), origin,
                            command_line_seed, os_seed);
}

hazard::Engine make_sensor_engine(const std::vector<moos::ConfigLine>& block_lines,
                                  const hazard::HazardFileReader& read,
                                  const hazard::MissionOrigin& origin,
                                  std::optional<std::uint64_t> command_line_seed,
                                  const std::function<std::uint64_t()>& os_seed) {
  hazard::EngineSetup setup =
      hazard::load_configuration(to_config_entries(block_lines), read, origin);
  const hazard::SeedChoice seed = hazard::resolve_seed(command_line_seed, setup.config, os_seed);
  return hazard::Engine(std::move(setup), seed);
}

std::string information_switches_help(const std::string& app_name) {
  return "  --alias=<ProcessName>\n"
         "      Launch " + app_name + " with the given process\n"
         "      name rather than " + app_name + ".\n"
         "  --example, -e\n"
         "      Display example MOOS configuration block.\n"
         "  --help, -h\n"
         "      Display this help message.\n"
         "  --interface, -i\n"
         "      Display MOOS publications and subscriptions.\n"
         "  --version,-v\n"
         "      Display release version of " + app_name + ".\n";
}

std::string generic_switches_help() {
  return "  --NAME=value\n"
         "      Replaces $(NAME) in the mission file.\n"
         "  --moos_host=HOST, --moos_port=PORT, --moos_time_warp=W,\n"
         "  --moos_app_tick=HZ, --moos_name=NAME\n"
         "      Generic MOOS switches; they override the mission file.\n"
         "\n"
         "Note: If argv[2] does not otherwise match a known option,\n"
         "      then it will be interpreted as a run alias. This is\n"
         "      to support pAntler launching conventions.\n"
         "\n";
}

}  // namespace app_support
