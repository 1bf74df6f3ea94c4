// hazard_study: the processes of a mission and their settings. Contract in mission_plan.hpp.

#include "mission_plan.hpp"

#include <algorithm>

#include "base/text.hpp"

namespace hazard_study {

namespace {

const char* const kSkipped[] = {"MOOSDB", "pLogLite", "pWebViewer"};
const char* const kRunnable[] = {"uFldHazardSensor", "uFldHazardMetric", "pHazardMgr",
                                 "uSimSurveyVehicle"};

bool one_of(const std::string& name, const char* const* first, const char* const* last) {
  return std::any_of(first, last, [&](const char* n) { return base::iequals(name, n); });
}

/// "Run = program @ NewConsole = false ~ alias": the program and its alias.
Process parse_run_line(const std::string& value) {
  const std::string_view v(value);
  const auto at = v.find('@');
  const auto tilde = v.find('~', at == std::string_view::npos ? 0 : at);
  Process p;
  p.program = std::string(base::trim(v.substr(0, std::min(at, tilde))));
  p.name = tilde == std::string_view::npos ? p.program : std::string(base::trim(v.substr(tilde + 1)));
  return p;
}

std::string place(const moos::ConfigLine& line) {
  return line.file + ":" + std::to_string(line.line) + ": ";
}

std::optional<std::vector<Process>> read_processes(const moos::MissionFile& mission,
                                                   std::string& error) {
  const moos::ProcessBlock* antler = mission.block("ANTLER");
  if (!antler) {
    error = mission.path() + ": no `ProcessConfig = ANTLER` block: which processes run?";
    return std::nullopt;
  }
  std::vector<Process> processes;
  for (const moos::ConfigLine& line : antler->lines) {
    if (!base::iequals(line.key, "Run")) continue;
    Process p = parse_run_line(line.value);
    if (one_of(p.program, std::begin(kSkipped), std::end(kSkipped))) continue;
    if (!one_of(p.program, std::begin(kRunnable), std::end(kRunnable))) {
      error = place(line) + "hazard_study cannot run '" + base::excerpt(p.program) +
              "' (it runs uFldHazardSensor, uFldHazardMetric, pHazardMgr and uSimSurveyVehicle)";
      return std::nullopt;
    }
    if (!mission.block(p.name)) {
      error = place(line) + "no `ProcessConfig = " + base::excerpt(p.name) + "` block";
      return std::nullopt;
    }
    for (const Process& other : processes)
      if (base::iequals(other.name, p.name)) {
        error = place(line) + "'" + base::excerpt(p.name) + "' runs twice";
        return std::nullopt;
      }
    processes.push_back(std::move(p));
  }
  if (processes.empty()) {
    error = antler->file + ":" + std::to_string(antler->line) +
            ": the ANTLER block runs no process hazard_study can run";
    return std::nullopt;
  }
  return processes;
}

std::optional<std::string> block_value(const moos::ProcessBlock& block, const char* key) {
  for (const moos::ConfigLine& line : block.lines)
    if (base::iequals(line.key, key)) return line.value;
  return std::nullopt;
}

std::vector<std::string> default_final_vehicles(const moos::MissionFile& mission,
                                                const std::vector<Process>& processes,
                                                const std::string& community) {
  std::vector<std::string> finals;
  for (const Process& p : processes) {
    if (!base::iequals(p.program, "pHazardMgr")) continue;
    const moos::ProcessBlock& block = *mission.block(p.name);
    if (block_value(block, "handover_to")) continue;
    finals.push_back(block_value(block, "vname").value_or(community));
  }
  return finals;
}

/// The block's lines with `name` replaced by `replacement` (at the first one's place).
void replace_lines(std::vector<moos::ConfigLine>& lines, const std::string& name,
                   const std::vector<moos::ConfigLine>& replacement) {
  auto first = std::find_if(lines.begin(), lines.end(),
                            [&](const moos::ConfigLine& l) { return base::iequals(l.key, name); });
  const auto at = first - lines.begin();
  lines.erase(std::remove_if(lines.begin(), lines.end(),
                             [&](const moos::ConfigLine& l) { return base::iequals(l.key, name); }),
              lines.end());
  lines.insert(lines.begin() + std::min<std::ptrdiff_t>(at, static_cast<std::ptrdiff_t>(lines.size())),
               replacement.begin(), replacement.end());
}

bool may_set_framework(const std::string& name) {
  return base::iequals(name, "AppTick") || base::iequals(name, "IdleAppTick");
}

}  // namespace

std::optional<MissionPlan> load_plan(const Options& options, std::string& error) {
  moos::MissionOptions mission_options;
  mission_options.use_environment = false;
  mission_options.substitutions = {{"PORT", "9000"}, {"VIEW_PORT", "0"}, {"WARP", "1"},
                                   {"SEED", std::to_string(options.first_seed)}};
  for (const auto& [name, value] : options.substitutions) mission_options.substitutions[name] = value;
  std::vector<moos::MissionError> errors;
  auto mission = moos::MissionFile::load(options.mission_path, mission_options, &errors);
  if (!mission) {
    error = options.mission_path + ": cannot read the mission file";
    return std::nullopt;
  }
  if (!errors.empty()) {
    error = errors.front().to_string();
    if (errors.size() > 1) error += " (and " + std::to_string(errors.size() - 1) + " more)";
    return std::nullopt;
  }
  MissionPlan plan;
  plan.community = mission->global("Community").value_or("");
  auto processes = read_processes(*mission, error);
  if (!processes) return std::nullopt;
  plan.processes = std::move(*processes);
  plan.final_vehicles = options.final_vehicles.empty()
                            ? default_final_vehicles(*mission, plan.processes, plan.community)
                            : options.final_vehicles;
  if (plan.final_vehicles.empty()) {
    error = options.mission_path +
            ": no pHazardMgr without handover_to, so no vehicle's report ends the mission: "
            "name the vehicles with --final";
    return std::nullopt;
  }
  plan.mission = std::make_shared<const moos::MissionFile>(std::move(*mission));
  return plan;
}

std::string check_assignments(const MissionPlan& plan, const std::vector<Setting>& settings) {
  for (const Setting& s : settings) {
    for (const Assignment& a : s.assignments) {
      const auto p = std::find_if(plan.processes.begin(), plan.processes.end(),
                                  [&](const Process& q) { return base::iequals(q.name, a.block); });
      if (p == plan.processes.end()) {
        std::string names;
        for (const Process& q : plan.processes) names += (names.empty() ? "" : ", ") + q.name;
        return "--set '" + base::excerpt(a.as_typed) + "': no process '" +
               base::excerpt(a.block) + "' runs in the mission (blocks: " + names + ")";
      }
      if (moos::is_framework_parameter(a.name) && !may_set_framework(a.name))
        return "--set '" + base::excerpt(a.as_typed) + "': " + a.name +
               " is a framework parameter hazard_study does not vary (AppTick and IdleAppTick "
               "only)";
    }
  }
  return {};
}

moos::AppSettings process_settings(const MissionPlan& plan, const Process& process,
                                   const moos::AppTraits& traits, const Setting& setting,
                                   std::uint64_t seed) {
  const std::vector<std::string> args = {process.program, plan.mission->path(), process.name};
  moos::AppSettings s = moos::resolve_app_settings(traits, moos::parse_command_line(args),
                                                   plan.mission.get());
  s.time_warp = 1.0;
  std::vector<std::pair<std::string, std::vector<moos::ConfigLine>>> replaced;
  for (std::size_t i = 0; i < setting.assignments.size(); ++i) {
    const Assignment& a = setting.assignments[i];
    if (!base::iequals(a.block, process.name)) continue;
    const moos::ConfigLine line{a.name, a.value, kSetFile, static_cast<int>(i + 1)};
    if (base::iequals(a.name, "AppTick")) {
      const auto hz = base::parse_number(a.value);
      if (hz && *hz > 0 && *hz <= 1000) s.app_tick_hz = *hz;
      else s.config_warnings.push_back(place(line) + "AppTick needs a number in (0, 1000]");
      continue;
    }
    if (base::iequals(a.name, "IdleAppTick")) {
      const auto hz = base::parse_number(a.value);
      if (hz && *hz > 0 && *hz <= 1000) s.idle_app_tick_hz = *hz;
      else s.config_warnings.push_back(place(line) + "IdleAppTick needs a number in (0, 1000]");
      continue;
    }
    auto same = std::find_if(replaced.begin(), replaced.end(),
                             [&](const auto& r) { return base::iequals(r.first, a.name); });
    if (same == replaced.end()) replaced.push_back({a.name, {line}});
    else same->second.push_back(line);
  }
  if (plan.field_file && (base::iequals(process.program, "uFldHazardSensor") ||
                          base::iequals(process.program, "uFldHazardMetric")))
    replaced.push_back({"hazard_file", {moos::ConfigLine{"hazard_file", *plan.field_file,
                                                         "--field", 1}}});
  if (base::iequals(process.program, "uFldHazardSensor"))
    replaced.push_back({"random_seed", {moos::ConfigLine{"random_seed", std::to_string(seed),
                                                         "--seeds", 1}}});
  for (const auto& [name, lines] : replaced) replace_lines(s.config_lines, name, lines);
  return s;
}

}  // namespace hazard_study
