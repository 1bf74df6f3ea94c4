#pragma once
// What hazard_study runs of a mission file: the processes of its `ProcessConfig = ANTLER` block
// (as pAntler and missions/common/launch_lib.sh read the Run lines), the settings of each for
// one study setting and seed, and the vehicles whose graded report ends a mission.
//
// Contract:
// - The mission is read once, with the command line's `$(NAME)` values and never the
//   environment (a study must not depend on the shell it runs in). PORT, VIEW_PORT and WARP,
//   the launcher's network and pacing macros, default to 9000, 0 and 1; SEED to the first seed.
//   Any error of the mission file is fatal (the runner's output must be the mission's).
// - Run lines of MOOSDB, pLogLite and pWebViewer are skipped: the runner is the database, and it
//   logs with --alog. A Run line of any other program than uFldHazardSensor, uFldHazardMetric,
//   pHazardMgr and uSimSurveyVehicle is an error naming it.
// - An assignment (`--set`) must name the block of a process that runs; its lines replace the
//   block's lines of that name (case-insensitive), at the place of the first one, else at the
//   end. AppTick and IdleAppTick may be set; other framework parameters may not.
// - The seed replaces every `random_seed` of each uFldHazardSensor block.
// - With a generated field (`field_file`), one `hazard_file = <field_file>` replaces the
//   hazard_file lines of every uFldHazardSensor and uFldHazardMetric block (the field's reader,
//   field_cache.hpp, serves it from memory).
// - Final vehicles: those given, else the vname of every pHazardMgr block without handover_to.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "moos/app.hpp"
#include "moos/mission.hpp"
#include "study_args.hpp"

namespace hazard_study {

/// One Run line of the ANTLER block.
struct Process {
  std::string program;  ///< e.g. "pHazardMgr"
  std::string name;     ///< the run alias, e.g. "pHazardMgr_archie" (its block)
};

struct MissionPlan {
  std::shared_ptr<const moos::MissionFile> mission;
  std::vector<Process> processes;  ///< in Run-line order
  std::vector<std::string> final_vehicles;
  std::string community;
  /// A generated field's name (field.hpp, set per field seed); nullopt: the mission's files.
  std::optional<std::string> field_file;
};

/// The plan, or nullopt with `error` naming the file, line or argument.
std::optional<MissionPlan> load_plan(const Options& options, std::string& error);

/// "" when every assignment of `settings` names a running process and a parameter it may set;
/// else the error naming the `--set` (unknown block; framework parameter).
std::string check_assignments(const MissionPlan& plan, const std::vector<Setting>& settings);

/// The file name that --set lines carry: an app's warning about one starts "--set:K: ", K the
/// assignment's 1-based index in its setting.
inline constexpr const char* kSetFile = "--set";

/// The settings of `process` for `setting` and `seed` (see the contract), at warp 1.
moos::AppSettings process_settings(const MissionPlan& plan, const Process& process,
                                   const moos::AppTraits& traits, const Setting& setting,
                                   std::uint64_t seed);

}  // namespace hazard_study
