// hazard_replay's command line. Contract in args.hpp.

#include "args.hpp"

#include <map>
#include <utility>

#include "base/text.hpp"

namespace hazard_replay {

const moos::SwitchTable& switch_table() {
  using moos::SwitchKind;
  static const moos::SwitchTable table = [] {
    moos::SwitchTable t;
    t.rules = {moos::switch_rule("--alias", SwitchKind::kText, "a name"),
               moos::switch_rule("--seed", SwitchKind::kUnsigned, "a whole number in [0, 2^64)"),
               moos::switch_rule("--seeds", SwitchKind::kText, "a range A..B of whole numbers"),
               moos::switch_rule("--score", SwitchKind::kFlag, "no value"),
               moos::switch_rule("--until", SwitchKind::kNumber, "a finite number of seconds"),
               moos::switch_rule("--output", SwitchKind::kText, "a file name"),
               moos::help_switch_rule(), moos::version_switch_rule()};
    t.bad_value = [](const std::string& arg, const moos::SwitchRule& r) {
      return r.name + " needs " + r.problem + ": '" + arg + "'";
    };
    t.unknown = [](const std::string& arg) { return "unknown option '" + arg + "'"; };
    return t;
  }();
  return table;
}

std::optional<SeedRange> parse_seed_range(std::string_view text) {
  const auto dots = text.find("..");
  if (dots == std::string_view::npos) return std::nullopt;
  const auto first = base::parse_unsigned(text.substr(0, dots));
  const auto last = base::parse_unsigned(text.substr(dots + 2));
  if (!first || !last || *last < *first || *last - *first >= kMaxSeedsPerRun) return std::nullopt;
  return SeedRange{*first, *last};
}

ParsedArgs parse_args(const std::vector<std::string>& all_args) {
  std::vector<std::string> args;
  std::map<std::string, std::string> substitutions;
  for (const std::string& arg : all_args) {
    if (!moos::is_macro_argument(arg)) {
      args.push_back(arg);
      continue;
    }
    const auto eq = arg.find('=');
    substitutions[arg.substr(2, eq - 2)] = arg.substr(eq + 1);
  }
  const moos::SwitchValues v = moos::parse_switches(args, switch_table());
  auto fail = [](std::string why) { return ParsedArgs{std::nullopt, std::move(why)}; };
  Options o;
  if (v.has("--help") || v.has("--version")) {
    o.help = v.has("--help");
    o.version = !o.help;
    return ParsedArgs{o, {}};
  }
  if (!v.errors.empty()) return fail(v.errors.front());
  const std::vector<std::string>& files = v.free;
  if (files.size() < 2)
    return fail(files.empty() ? "missing CONFIG.moos and INPUT.alog" : "missing INPUT.alog");
  if (files.size() > 2) return fail("unexpected argument '" + files[2] + "'");
  o.config_path = files[0];
  o.input_path = files[1];
  o.app_name = v.text("--alias").value_or(o.app_name);
  o.seed = v.whole("--seed");
  if (const auto range = v.text("--seeds")) {
    if (o.seed) return fail("--seed and --seeds exclude each other");
    o.seeds = parse_seed_range(*range);
    if (!o.seeds) {
      return fail("--seeds needs A..B, whole numbers with A <= B and at most " +
                  std::to_string(kMaxSeedsPerRun) + " seeds: '--seeds=" + *range + "'");
    }
  }
  o.score = v.has("--score");
  if (o.score && !o.seeds) return fail("--score needs --seeds=A..B");
  o.until_s = v.number("--until");
  o.output_path = v.text("--output");
  o.substitutions = std::move(substitutions);
  return ParsedArgs{o, {}};
}

}  // namespace hazard_replay
