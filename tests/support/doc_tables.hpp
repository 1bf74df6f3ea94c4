#pragma once
// Tables in the docs that mirror code (switch tables), read back so that a test can compare them
// with the table in code: a doc that drifts from the code fails the suite.

#include <set>
#include <string>
#include <vector>

#include "moos/command_line.hpp"

namespace test_support {

/// The rows of the first markdown table after the first heading line (one starting with '#')
/// that contains `heading`, in file `path`: each row's cells, trimmed, without the header row
/// and the `|---|` line. Empty when the file, the heading or the table is missing.
std::vector<std::vector<std::string>> doc_table(const std::string& path, const std::string& heading);

/// The switches a table cell names: every `code` span that starts with '-', cut at '=' or a blank
/// (`--moos_port=PORT` names --moos_port).
std::set<std::string> switches_named(const std::string& cell);

/// Every switch named in the first column of `rows`.
std::set<std::string> switches_in_first_column(const std::vector<std::vector<std::string>>& rows);

/// The names and aliases of a switch table's rules (kIgnored rules only with `with_ignored`).
std::set<std::string> switches_of(const moos::SwitchTable& table, bool with_ignored);

}  // namespace test_support
