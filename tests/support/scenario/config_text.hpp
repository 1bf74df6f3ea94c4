#pragma once
// Configuration blocks written as text, for tests and benchmarks: "key = value" lines as the
// engine's configuration entries (what a program extracts from a mission file with libmoos).

#include <string>
#include <string_view>
#include <vector>

#include "hazard/config.hpp"

namespace hazard {

/// One entry per "key = value" line of `block`, numbered from 1 and attributed to `file`;
/// blank lines, lines without '=' and `//` comments are skipped.
std::vector<ConfigEntry> config_entries(std::string_view block, const std::string& file);

}  // namespace hazard
