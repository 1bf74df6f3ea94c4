#include "scenario/config_text.hpp"

#include "base/text.hpp"

namespace hazard {

std::vector<ConfigEntry> config_entries(std::string_view block, const std::string& file) {
  std::vector<ConfigEntry> out;
  int line = 0;
  for (std::string_view raw : base::split_trimmed(block, '\n')) {
    ++line;
    const std::string_view text = base::trim(raw.substr(0, raw.find("//")));
    const auto eq = text.find('=');
    if (text.empty() || eq == std::string_view::npos) continue;
    out.push_back({std::string(base::trim(text.substr(0, eq))),
                   std::string(base::trim(text.substr(eq + 1))), file, line});
  }
  return out;
}

}  // namespace hazard
