#pragma once
// One row of an application's parameter table: the .moos name, its default
// as text and a help line. The applications build --example and --help from these tables.

#include <vector>

namespace mission {

struct ParamInfo {
  const char* name;
  const char* default_text;
  const char* help;
};

/// The ParamInfo of each row of a table whose rows have an `info` member, in table order.
template <class Rows>
std::vector<ParamInfo> param_infos(const Rows& rows) {
  std::vector<ParamInfo> out;
  for (const auto& row : rows) out.push_back(row.info);
  return out;
}

}  // namespace mission
