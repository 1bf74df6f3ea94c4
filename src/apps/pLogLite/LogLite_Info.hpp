#pragma once
// The texts of pLogLite's information switches (--help, --example, --interface, --version).

#include <string>

namespace plog_lite {

std::string help_text();
std::string example_text();
std::string interface_text();
std::string version_text();

}  // namespace plog_lite
