#include "base/version.hpp"

namespace base {
std::string_view release_version() { return "1.0.0"; }
}  // namespace base
