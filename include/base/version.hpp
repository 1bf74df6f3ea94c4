#pragma once
// Release identity shared by every program's --version.
#include <string>
#include <string_view>

namespace base {
/// Project release, e.g. "1.0.0" (the top CMakeLists.txt's project version).
std::string_view release_version();
/// What every program's --version prints: "<program> <release> (HazardSensor)" and a newline.
std::string version_line(std::string_view program);
}  // namespace base
