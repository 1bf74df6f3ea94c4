#pragma once
// hazard_study's command line (help: HazardStudy_Info.cpp).
//
// Contract:
// - `--set=BLOCK.NAME=VALUE` (or `--set BLOCK.NAME=VALUE`) gives parameter NAME of the
//   ProcessConfig block BLOCK the value VALUE: every line of NAME in the block is replaced by the
//   `--set` lines of that name (several `--set` of one name give several lines, e.g. several
//   sensor_config). BLOCK is everything before the last '.' of the part before the first '='.
// - `--setting=LABEL` starts a new setting: the `--set` that follow belong to it. `--set` before
//   any `--setting` form one setting labelled by its assignments. Without any, one setting:
//   the mission as written, labelled "mission". At most kMaxSettings settings.
// - `--field=OPTIONS` generates the field with gen_hazards' own options (blank-separated words,
//   field.hpp); `--field-seed=N` or `--field-seeds=A..B` (only with --field; default 1) are its
//   seeds. Field seeds times sensor seeds is at most kMaxSeedsPerRun.
// - `--NAME=value` (NAME starting with a capital letter) is a `$(NAME)` of the mission file.
// - Every refused value is an error naming the argument as typed.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "field.hpp"

namespace hazard_study {

inline constexpr std::uint64_t kMaxSeedsPerRun = 10000000;
inline constexpr std::size_t kMaxSettings = 1000;
inline constexpr std::size_t kMaxAssignments = 10000;
/// Simulated seconds a mission may take by default (missions/jake/launch.sh's ML_MAX_SIM_S).
inline constexpr double kDefaultMaxTime_s = 12000.0;
/// Longest --max-time: a mission longer than a simulated year is a mistake.
inline constexpr double kMaxMaxTime_s = 3.2e7;

/// One parameter of one block.
struct Assignment {
  std::string block;
  std::string name;
  std::string value;
  std::string as_typed;  ///< "BLOCK.NAME=VALUE", for labels and errors
};

struct Setting {
  std::string label;
  std::vector<Assignment> assignments;
};

struct Options {
  bool help = false;
  bool version = false;
  std::string mission_path;
  std::uint64_t first_seed = 1;
  std::uint64_t last_seed = 1;
  std::vector<Setting> settings;
  std::optional<FieldSpec> field;  ///< --field: a generated field instead of the hazard files
  std::uint64_t first_field_seed = 1;
  std::uint64_t last_field_seed = 1;
  double max_time_s = kDefaultMaxTime_s;
  double deploy_s = 1.0;  ///< when DEPLOY_ALL and HAZARD_SEARCH_START are posted
  std::vector<std::string> final_vehicles;  ///< empty: from the mission (mission_plan.hpp)
  std::optional<std::string> alog_path;
  bool summary = false;
  std::map<std::string, std::string> substitutions;
};

struct ParsedArgs {
  std::optional<Options> options;
  std::string error;  ///< when options is empty
};

ParsedArgs parse_args(const std::vector<std::string>& args);

/// "BLOCK.NAME=VALUE" split as the contract says; nullopt when a part is missing.
std::optional<Assignment> parse_assignment(const std::string& text);

}  // namespace hazard_study
