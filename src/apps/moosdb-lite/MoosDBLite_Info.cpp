#include "MoosDBLite_Info.hpp"

#include <algorithm>

#include "base/version.hpp"
#include "options.hpp"

namespace moosdb_lite {

namespace {

/// Option names longer than this get their meaning on the next line.
constexpr std::size_t kMaxInlineNameChars = 24;

std::string table(const std::vector<OptionDoc>& rows) {
  std::size_t width = 0;
  for (const auto& row : rows) {
    if (row.name.size() <= kMaxInlineNameChars) width = std::max(width, row.name.size());
  }
  std::string out;
  for (const auto& row : rows) {
    out += "  ";
    out += row.name;
    if (row.name.size() > width) {
      out += "\n  " + std::string(width + 2, ' ');
    } else {
      out += std::string(width + 2 - row.name.size(), ' ');
    }
    out += row.meaning;
    out += '\n';
  }
  return out;
}

}  // namespace

std::string help_text() {
  std::string out;
  out += "Usage: moosdb-lite [MISSION [ALIAS]] [OPTIONS]\n\n";
  out += "A MOOSDB-compatible server (MOOS v10 protocol) for machines without MOOS.\n";
  out += "libMOOS applications (synchronous or asynchronous) and pymoos2 connect to it as to\n";
  out += "the reference MOOSDB. Diagnostics go to standard error.\n\n";
  out += "Options:\n";
  out += table(option_docs());
  out += "\nMission-file globals read (command-line switches override them):\n";
  out += table(mission_global_docs());
  out += "\nSee docs/moos.md for what differs from the reference MOOSDB.\n";
  return out;
}

std::string version_text() {
  return base::version_line("moosdb-lite");
}

}  // namespace moosdb_lite
