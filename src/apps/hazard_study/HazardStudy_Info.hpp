#pragma once
// hazard_study's --help text (the man page is made from it, cmake/programs.cmake).
#include <string>

namespace hazard_study {

std::string usage_line();
std::string help_text();

}  // namespace hazard_study
