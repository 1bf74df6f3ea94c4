#pragma once
// Release identity shared by every binary's --version banner.
#include <string_view>

namespace hazard {
/// Project release, e.g. "1.0.0".
std::string_view release_version();
}  // namespace hazard
