// hazard_replay's command line. Contract in args.hpp.

#include "args.hpp"

namespace hazard_replay {

const moos::SwitchTable& switch_table() {
  using moos::SwitchKind;
  static const moos::SwitchTable table = [] {
    moos::SwitchTable t;
    t.rules = {moos::switch_rule("--alias", SwitchKind::kText, "a name"),
               moos::switch_rule("--seed", SwitchKind::kUnsigned, "a whole number in [0, 2^64)"),
               moos::switch_rule("--until", SwitchKind::kNumber, "a finite number of seconds"),
               moos::switch_rule("--output", SwitchKind::kText, "a file name"),
               moos::help_switch_rule()};
    t.bad_value = [](const std::string& arg, const moos::SwitchRule& r) {
      return r.name + " needs " + r.problem + ": '" + arg + "'";
    };
    t.unknown = [](const std::string& arg) { return "unknown option '" + arg + "'"; };
    return t;
  }();
  return table;
}

ParsedArgs parse_args(const std::vector<std::string>& args) {
  const moos::SwitchValues v = moos::parse_switches(args, switch_table());
  auto fail = [](std::string why) { return ParsedArgs{std::nullopt, std::move(why)}; };
  Options o;
  if (v.has("--help")) {
    o.help = true;
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
  o.until_s = v.number("--until");
  o.output_path = v.text("--output");
  return ParsedArgs{o, {}};
}

}  // namespace hazard_replay
