#include "app_support.hpp"

#include <chrono>
#include <exception>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
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

std::optional<std::string> read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return text.str();
}

hazard::HazardFileReader mission_relative_reader(std::string mission_directory) {
  return [dir = std::filesystem::path(std::move(mission_directory))](const std::string& path) {
    const std::filesystem::path p(path);
    return read_text_file((p.is_relative() ? dir / p : p).string());
  };
}

std::vector<hazard::ConfigEntry> to_config_entries(const std::vector<moos::ConfigLine>& lines) {
  std::vector<hazard::ConfigEntry> out;
  out.reserve(lines.size());
  for (const moos::ConfigLine& l : lines) out.push_back({l.key, l.value, l.file, l.line});
  return out;
}

}  // namespace app_support
