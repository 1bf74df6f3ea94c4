// hazard_study's command line. Contract in study_args.hpp.

#include "study_args.hpp"

#include <utility>

#include "base/text.hpp"
#include "moos/command_line.hpp"

namespace hazard_study {

namespace {

const moos::SwitchTable& switch_table() {
  using moos::SwitchKind;
  static const moos::SwitchTable table = [] {
    moos::SwitchTable t;
    t.rules = {
        moos::switch_rule("--seed", SwitchKind::kUnsigned, "a whole number in [0, 2^64)"),
        moos::switch_rule("--seeds", SwitchKind::kText, "a range A..B of whole numbers"),
        moos::switch_rule("--field", SwitchKind::kText, "gen_hazards options"),
        moos::switch_rule("--field-seed", SwitchKind::kUnsigned, "a whole number in [0, 2^64)"),
        moos::switch_rule("--field-seeds", SwitchKind::kText, "a range A..B of whole numbers"),
        moos::switch_rule("--max-time", SwitchKind::kNumber, "a number of seconds in (0, 3.2e7]",
                          moos::Range{0.0, kMaxMaxTime_s, true, false}),
        moos::switch_rule("--deploy-at", SwitchKind::kNumber, "a number of seconds in [0, 3600]",
                          moos::Range{0.0, 3600.0}),
        moos::switch_rule("--final", SwitchKind::kText, "vehicle names separated by commas"),
        moos::switch_rule("--alog", SwitchKind::kText, "a file name"),
        moos::switch_rule("--summary", SwitchKind::kFlag, "no value"),
        moos::help_switch_rule(), moos::version_switch_rule()};
    t.bad_value = [](const std::string& arg, const moos::SwitchRule& r) {
      return r.name + " needs " + r.problem + ": '" + base::excerpt(arg) + "'";
    };
    t.unknown = [](const std::string& arg) { return "unknown option '" + base::excerpt(arg) + "'"; };
    return t;
  }();
  return table;
}

std::optional<std::pair<std::uint64_t, std::uint64_t>> parse_seed_range(std::string_view text) {
  const auto dots = text.find("..");
  if (dots == std::string_view::npos) return std::nullopt;
  const auto first = base::parse_unsigned(text.substr(0, dots));
  const auto last = base::parse_unsigned(text.substr(dots + 2));
  if (!first || !last || *last < *first || *last - *first >= kMaxSeedsPerRun) return std::nullopt;
  return std::make_pair(*first, *last);
}

/// The label of a setting given without --setting: its assignments.
std::string label_of(const std::vector<Assignment>& assignments) {
  std::string label;
  for (const Assignment& a : assignments) label += (label.empty() ? "" : " ") + a.as_typed;
  return label;
}

/// Takes --set and --setting (in order) out of `args` into `settings`; "" or the error.
std::string take_settings(std::vector<std::string>& args, std::vector<Setting>& settings) {
  std::vector<std::string> rest;
  std::optional<Setting> open;       // a --setting being filled
  std::vector<Assignment> loose;     // --set before any --setting
  std::size_t count = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    std::optional<std::string> value;
    bool is_set = false;
    if (arg == "--set" || arg == "--setting") {
      if (i + 1 >= args.size()) return arg + " needs a value";
      value = args[++i];
      is_set = arg == "--set";
    } else if (base::starts_with(arg, "--set=")) {
      value = arg.substr(6);
      is_set = true;
    } else if (base::starts_with(arg, "--setting=")) {
      value = arg.substr(10);
    }
    if (!value) {
      rest.push_back(arg);
      continue;
    }
    if (!is_set) {
      if (value->empty() || value->size() > 200 || value->find('\n') != std::string::npos)
        return "--setting needs a label of 1 to 200 characters on one line: '" +
               base::excerpt(*value) + "'";
      if (open) settings.push_back(std::move(*open));
      if (settings.size() + 1 > kMaxSettings)
        return "more than " + std::to_string(kMaxSettings) + " settings";
      open = Setting{*value, {}};
      continue;
    }
    auto assignment = parse_assignment(*value);
    if (!assignment)
      return "--set needs BLOCK.NAME=VALUE (a block, a parameter name and a value on one line): '" +
             base::excerpt(*value) + "'";
    if (++count > kMaxAssignments)
      return "more than " + std::to_string(kMaxAssignments) + " --set";
    (open ? open->assignments : loose).push_back(std::move(*assignment));
  }
  if (!loose.empty() && (open || !settings.empty()))
    return "--set '" + base::excerpt(loose.front().as_typed) +
           "' comes before the first --setting: put it after one";
  if (open) settings.push_back(std::move(*open));
  if (!loose.empty()) settings.push_back(Setting{label_of(loose), std::move(loose)});
  if (settings.empty()) settings.push_back(Setting{"mission", {}});
  args = std::move(rest);
  return {};
}

/// --field, --field-seed and --field-seeds into `o`; "" or the error.
std::string take_field(const moos::SwitchValues& v, Options& o) {
  const bool seeds_given = v.has("--field-seed") || v.has("--field-seeds");
  if (!v.has("--field"))
    return seeds_given ? "--field-seed and --field-seeds need --field (the field to generate)"
                       : std::string();
  ParsedField field = parse_field(*v.text("--field"));
  if (!field.spec) return field.error;
  o.field = std::move(field.spec);
  if (const auto seed = v.whole("--field-seed")) o.first_field_seed = o.last_field_seed = *seed;
  if (const auto range = v.text("--field-seeds")) {
    if (v.has("--field-seed")) return "--field-seed and --field-seeds exclude each other";
    const auto seeds = parse_seed_range(*range);
    if (!seeds)
      return "--field-seeds needs A..B, whole numbers with A <= B and at most " +
             std::to_string(kMaxSeedsPerRun) + " seeds: '--field-seeds=" + base::excerpt(*range) +
             "'";
    o.first_field_seed = seeds->first;
    o.last_field_seed = seeds->second;
  }
  const std::uint64_t fields = o.last_field_seed - o.first_field_seed + 1;
  const std::uint64_t seeds = o.last_seed - o.first_seed + 1;
  if (fields > kMaxSeedsPerRun / seeds)
    return "--field-seeds and --seeds: " + std::to_string(fields) + " x " + std::to_string(seeds) +
           " missions per setting, more than " + std::to_string(kMaxSeedsPerRun);
  for (const Setting& s : o.settings)
    for (const Assignment& a : s.assignments)
      if (base::iequals(a.name, "hazard_file"))
        return "--set '" + base::excerpt(a.as_typed) +
               "': --field gives every block its hazard_file; give one or the other";
  return {};
}

/// --final=a,b: names, each a vehicle name.
std::optional<std::vector<std::string>> parse_names(const std::string& text) {
  std::vector<std::string> names;
  for (const auto part : base::split_trimmed(text, ',')) {
    if (part.empty() || part.size() > 100) return std::nullopt;
    for (const char c : part)
      if (c == ' ' || c == '\t' || c == '=' || c == '#') return std::nullopt;
    names.emplace_back(part);
  }
  if (names.empty() || names.size() > 100) return std::nullopt;
  return names;
}

}  // namespace

std::optional<Assignment> parse_assignment(const std::string& text) {
  if (text.size() > 4096 || text.find('\n') != std::string::npos ||
      text.find('\r') != std::string::npos)
    return std::nullopt;
  const auto eq = text.find('=');
  if (eq == std::string::npos) return std::nullopt;
  const std::string target(base::trim(std::string_view(text).substr(0, eq)));
  const auto dot = target.rfind('.');
  if (dot == std::string::npos) return std::nullopt;
  Assignment a;
  a.block = std::string(base::trim(std::string_view(target).substr(0, dot)));
  a.name = std::string(base::trim(std::string_view(target).substr(dot + 1)));
  a.value = std::string(base::trim(std::string_view(text).substr(eq + 1)));
  if (a.block.empty() || a.name.empty()) return std::nullopt;
  a.as_typed = a.block + "." + a.name + "=" + a.value;
  return a;
}

ParsedArgs parse_args(const std::vector<std::string>& all_args) {
  auto fail = [](std::string why) { return ParsedArgs{std::nullopt, std::move(why)}; };
  Options o;
  std::vector<std::string> args;
  for (const std::string& arg : all_args) {
    if (!moos::is_macro_argument(arg)) {
      args.push_back(arg);
      continue;
    }
    const auto eq = arg.find('=');
    o.substitutions[arg.substr(2, eq - 2)] = arg.substr(eq + 1);
  }
  if (const std::string error = take_settings(args, o.settings); !error.empty()) {
    const moos::SwitchValues info = moos::parse_switches(args, switch_table());
    if (!info.has("--help") && !info.has("--version")) return fail(error);
  }
  const moos::SwitchValues v = moos::parse_switches(args, switch_table());
  if (v.has("--help") || v.has("--version")) {
    o.help = v.has("--help");
    o.version = !o.help;
    return ParsedArgs{o, {}};
  }
  if (!v.errors.empty()) return fail(v.errors.front());
  if (v.free.empty()) return fail("missing MISSION.moos");
  if (v.free.size() > 1) return fail("unexpected argument '" + base::excerpt(v.free[1]) + "'");
  o.mission_path = v.free[0];
  if (const auto seed = v.whole("--seed")) o.first_seed = o.last_seed = *seed;
  if (const auto range = v.text("--seeds")) {
    if (v.has("--seed")) return fail("--seed and --seeds exclude each other");
    const auto seeds = parse_seed_range(*range);
    if (!seeds)
      return fail("--seeds needs A..B, whole numbers with A <= B and at most " +
                  std::to_string(kMaxSeedsPerRun) + " seeds: '--seeds=" + base::excerpt(*range) +
                  "'");
    o.first_seed = seeds->first;
    o.last_seed = seeds->second;
  }
  if (std::string error = take_field(v, o); !error.empty()) return fail(std::move(error));
  if (const auto t = v.number("--max-time")) o.max_time_s = *t;
  if (const auto t = v.number("--deploy-at")) o.deploy_s = *t;
  if (const auto final = v.text("--final")) {
    auto names = parse_names(*final);
    if (!names) return fail("--final needs vehicle names separated by commas: '" +
                            base::excerpt(*final) + "'");
    o.final_vehicles = std::move(*names);
  }
  o.alog_path = v.text("--alog");
  if (o.alog_path && o.last_seed != o.first_seed)
    return fail("--alog writes one mission: give --seed=N (not --seeds)");
  if (o.alog_path && o.settings.size() > 1)
    return fail("--alog writes one mission: give one setting");
  if (o.alog_path && o.last_field_seed != o.first_field_seed)
    return fail("--alog writes one mission: give --field-seed=N (not --field-seeds)");
  o.summary = v.has("--summary");
  return ParsedArgs{o, {}};
}

}  // namespace hazard_study
