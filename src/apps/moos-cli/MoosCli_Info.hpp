#pragma once
// The help text of moos-cli. Its options are a stable interface: tests and users depend on them.

#include <string>

namespace moos_cli {

std::string help_text();

}  // namespace moos_cli
