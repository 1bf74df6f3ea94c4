#include "doc_tables.hpp"

#include <fstream>

#include "base/text.hpp"

namespace test_support {

std::vector<std::vector<std::string>> doc_table(const std::string& path, const std::string& heading) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  bool after_heading = false;
  bool in_table = false;
  while (std::getline(in, line)) {
    if (!after_heading) {
      after_heading = base::starts_with(line, "#") && line.find(heading) != std::string::npos;
      continue;
    }
    const bool table_line = base::starts_with(line, "|");
    if (!table_line) {
      if (in_table) break;  // the first table ends
      continue;
    }
    if (!in_table) {  // the header row
      in_table = true;
      continue;
    }
    if (base::starts_with(line, "|---") || base::starts_with(line, "| ---")) continue;
    std::vector<std::string> cells;
    for (std::string_view cell : base::split_trimmed(line, '|')) cells.emplace_back(cell);
    // "| a | b |" splits into "", a, b, "".
    if (!cells.empty() && cells.front().empty()) cells.erase(cells.begin());
    if (!cells.empty() && cells.back().empty()) cells.pop_back();
    rows.push_back(std::move(cells));
  }
  return rows;
}

std::set<std::string> switches_named(const std::string& cell) {
  std::set<std::string> names;
  std::size_t open = cell.find('`');
  while (open != std::string::npos) {
    const std::size_t close = cell.find('`', open + 1);
    if (close == std::string::npos) break;
    const std::string span = cell.substr(open + 1, close - open - 1);
    if (base::starts_with(span, "-")) names.insert(span.substr(0, span.find_first_of("= ")));
    open = cell.find('`', close + 1);
  }
  return names;
}

std::set<std::string> switches_in_first_column(const std::vector<std::vector<std::string>>& rows) {
  std::set<std::string> names;
  for (const auto& row : rows)
    if (!row.empty()) names.merge(switches_named(row.front()));
  return names;
}

std::set<std::string> switches_of(const moos::SwitchTable& table, bool with_ignored) {
  std::set<std::string> names;
  for (const moos::SwitchRule& r : table.rules) {
    if (r.kind == moos::SwitchKind::kIgnored && !with_ignored) continue;
    names.insert(r.name);
    names.insert(r.aliases.begin(), r.aliases.end());
  }
  return names;
}

}  // namespace test_support
