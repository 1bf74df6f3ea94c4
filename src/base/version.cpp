#include "base/version.hpp"

namespace base {

// HAZARD_RELEASE_VERSION comes from project(... VERSION ...) in the top CMakeLists.txt.
std::string_view release_version() { return HAZARD_RELEASE_VERSION; }

std::string version_line(std::string_view program) {
  std::string line(program);
  line += ' ';
  line += release_version();
  line += " (HazardSensor)\n";
  return line;
}

}  // namespace base
