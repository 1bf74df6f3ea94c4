#include "hazard/version.hpp"

namespace hazard {
std::string_view release_version() { return "1.0.0"; }
}  // namespace hazard
