#pragma once
// Release identity shared by every binary's --version banner.
#include <string_view>

namespace base {
/// Project release, e.g. "1.0.0".
std::string_view release_version();
}  // namespace base
