#pragma once
// The texts of pWebViewer's information switches (--help, --example, --interface, --version).

#include <string>

namespace web_viewer {

std::string help_text();
std::string example_text();
std::string interface_text();
std::string version_text();

}  // namespace web_viewer
