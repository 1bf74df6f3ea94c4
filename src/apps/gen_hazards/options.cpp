#include "options.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string_view>

#include "base/text.hpp"
#include "hazard/ranges.hpp"
#include "moos/command_line.hpp"

namespace gen_hazards {

namespace {

using base::fmt;

/// Characters a POSIX shell takes literally in a word; anything else gets quoted in the header.
constexpr std::string_view kShellSafe =
    "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-=,.:/+@%";

std::string quoted(std::string_view text) { return "'" + std::string(text) + "'"; }

/// "[lo, hi]" with FMT numbers.
std::string interval(double lo, double hi) { return "[" + fmt(lo) + ", " + fmt(hi) + "]"; }

/// Collects what one argument sets; `fail` records an error quoting the argument.
struct ArgContext {
  std::string_view arg;
  std::string_view value;
  CommandLine& cli;
  void fail(const std::string& problem) const { cli.errors.push_back(quoted(arg) + ": " + problem); }
};

std::optional<double> number_in(const ArgContext& c, double lo, double hi) {
  const auto v = base::parse_number(c.value);
  if (!v) {
    c.fail(quoted(c.value) + " is not a number");
    return std::nullopt;
  }
  if (*v < lo || *v > hi) {
    c.fail(fmt(*v) + " is outside " + interval(lo, hi));
    return std::nullopt;
  }
  return v;
}

AspectOptions& aspect_of(CommandLine& cli) {
  if (!cli.config.aspect) cli.config.aspect.emplace();
  return *cli.config.aspect;
}

/// ConvexPolygon::parse names the text already ("polygon '<text>': ..."); the argument is
/// quoted in front of the message, so that prefix would only repeat it.
std::string without_polygon_prefix(const std::string& message, std::string_view text) {
  const std::string prefix = "polygon " + quoted(base::trim(text)) + ": ";
  if (message.rfind(prefix, 0) == 0) return message.substr(prefix.size());
  return message;
}

void apply_polygon(const ArgContext& c) {
  auto parsed = mission::ConvexPolygon::parse(c.value);
  if (!parsed) {
    c.fail("not a valid convex polygon: " + without_polygon_prefix(parsed.error, c.value));
    return;
  }
  auto& polygon = *parsed.value;
  // Every object must load in the sensor, which refuses positions beyond the bound; a polygon
  // beyond it (1e300 once gave "covers only -nan of its bounding box") is refused here.
  const mission::Bounds box = polygon.bounds();
  const double reach_m = std::max({std::abs(box.min_m.x), std::abs(box.min_m.y),
                                   std::abs(box.max_m.x), std::abs(box.max_m.y)});
  if (!(reach_m <= hazard::kMaxObjectCoordinate_m)) {
    c.fail("the polygon reaches " + base::format_g(reach_m) + " m from the origin, beyond the " +
           base::format_g(hazard::kMaxObjectCoordinate_m) +
           " m that the sensor accepts for an object (kMaxObjectCoordinate_m)");
    return;
  }
  c.cli.config.regions.push_back(Region{std::move(polygon), std::string(c.arg)});
}

void apply_objects(const ArgContext& c) {
  const auto comma = c.value.find(',');
  if (comma == std::string_view::npos) {
    c.fail("expected N,TYPE (for example --objects=5,hazard)");
    return;
  }
  const std::string_view count_text = base::trim(c.value.substr(0, comma));
  const std::string_view type_text = base::trim(c.value.substr(comma + 1));
  const auto count = base::parse_unsigned(count_text);
  if (!count) {
    c.fail("the count " + quoted(count_text) + " is not a whole number >= 0");
    return;
  }
  hazard::ObjectType type;
  if (base::iequals(type_text, "hazard")) {
    type = hazard::ObjectType::kHazard;
  } else if (base::iequals(type_text, "benign")) {
    type = hazard::ObjectType::kBenign;
  } else {
    c.fail("the type " + quoted(type_text) +
           " is neither 'hazard' nor 'benign' (the only types uFldHazardSensor accepts)");
    return;
  }
  if (*count > kMaxTotalObjects - total_objects(c.cli.config)) {
    c.fail("more than " + std::to_string(kMaxTotalObjects) + " objects in total");
    return;
  }
  c.cli.config.sets.push_back(ObjectSet{*count, type, std::string(c.arg)});
}

void apply_exp(const ArgContext& c) {
  if (auto v = number_in(c, kMinResemblanceExp, kMaxResemblanceExp)) c.cli.config.resemblance_exp = v;
}

void apply_aspect_base(const ArgContext& c) {
  const double any = std::numeric_limits<double>::max();
  if (auto v = number_in(c, -any, any)) aspect_of(c.cli).base_deg = *v;
}

void apply_aspect_range(const ArgContext& c) {
  if (auto v = number_in(c, 0.0, kMaxAspectRangeDeg)) aspect_of(c.cli).range_deg = *v;
}

/// The four window options share one range; `set` stores the value in its member.
std::function<void(const ArgContext&)> window_option(void (*set)(AspectOptions&, double)) {
  return [set](const ArgContext& c) {
    if (auto v = number_in(c, 0.0, kMaxAspectWindowDeg)) set(aspect_of(c.cli), *v);
  };
}

void apply_seed(const ArgContext& c) {
  const auto v = base::parse_unsigned(c.value);
  if (!v) {
    c.fail("the seed must be a whole number in [0, " +
           std::to_string(std::numeric_limits<std::uint64_t>::max()) + "]");
    return;
  }
  c.cli.seed = v;
}

void apply_output(const ArgContext& c) {
  if (base::trim(c.value).empty()) {
    c.fail("the file name is empty");
    return;
  }
  c.cli.output_path = std::string(c.value);
}

/// One option of the table: its key (before '='), its documentation and what it does.
struct OptionSpec {
  std::string key;
  OptionDoc doc;
  std::function<void(const ArgContext&)> apply;
  bool recorded = true;  ///< repeated in the header comment
};

const std::vector<OptionSpec>& option_table() {
  static const std::string window = interval(0.0, kMaxAspectWindowDeg);
  static const std::vector<OptionSpec> table = {
      {"--polygon",
       {"--polygon=POLY",
        "A convex region to place objects in, as x1,y1:x2,y2:... or pts={x1,y1:...}: at least "
        "3 vertices, convex, positive area. Repeatable: objects are spread uniformly over the "
        "union of the regions. Each region is written as one `region = pts={...}` line.",
        "none (needed when --objects is given)", "any convex polygon"},
       apply_polygon},
      {"--objects",
       {"--objects=N,TYPE",
        "Generate N objects of TYPE, hazard or benign (any case). Repeatable: the sets are "
        "written in argument order and share one pool of unique labels.",
        "none", "N a whole number >= 0, at most " + std::to_string(kMaxTotalObjects) +
                    " objects in total; TYPE hazard or benign"},
       apply_objects},
      {"--exp",
       {"--exp=E",
        "Give every object a hazard resemblance hr = q^E, q uniform on {0, 0.001, ..., 0.999}; "
        "hr is written for benign objects only. The higher E, the lower the resemblance.",
        "off (no hr)", interval(kMinResemblanceExp, kMaxResemblanceExp)},
       apply_exp},
      {"--aspect_base",
       {"--aspect_base=DEG",
        "Aspect: the optimal aspect is drawn uniformly in [DEG, DEG + aspect_range), modulo "
        "360, to 0.1 deg. Any aspect option gives every object aspect, aspect_min and "
        "aspect_max.",
        fmt(kDefaultAspectBaseDeg), "any number (taken modulo 360)"},
       apply_aspect_base},
      {"--aspect_range",
       {"--aspect_range=DEG", "Aspect: the width of the interval the optimal aspect is drawn from.",
        fmt(kDefaultAspectRangeDeg), interval(0.0, kMaxAspectRangeDeg)},
       apply_aspect_range},
      {"--aspect_min_base",
       {"--aspect_min_base=DEG",
        "Aspect: aspect_min (full sensor performance within this many degrees of the optimal "
        "aspect) is drawn uniformly in [DEG, DEG + aspect_min_range], at most 90, to 0.1 deg.",
        fmt(kDefaultAspectMinBaseDeg), window},
       window_option([](AspectOptions& a, double v) { a.min_base_deg = v; })},
      {"--aspect_min_range",
       {"--aspect_min_range=DEG", "Aspect: the width of the interval aspect_min is drawn from.",
        fmt(kDefaultAspectMinRangeDeg), window},
       window_option([](AspectOptions& a, double v) { a.min_range_deg = v; })},
      {"--aspect_max_base",
       {"--aspect_max_base=DEG",
        "Aspect: aspect_max (fully degraded beyond this many degrees) is drawn uniformly in "
        "[B, B + aspect_max_range], at most 90, where B is the larger of DEG and the object's "
        "aspect_min. When aspect_min + aspect_max would exceed 90, both are lowered by the same "
        "amount until their sum is 90.",
        "the object's aspect_min", window},
       window_option([](AspectOptions& a, double v) { a.max_base_deg = v; })},
      {"--aspect_max_range",
       {"--aspect_max_range=DEG", "Aspect: the width of the interval aspect_max is drawn from.",
        fmt(kDefaultAspectMaxRangeDeg), window},
       window_option([](AspectOptions& a, double v) { a.max_range_deg = v; })},
      {"--seed",
       {"--seed=N",
        "Seed of the random numbers: the same arguments and seed give the same file on every "
        "platform. The seed in use is always written at the end of the header comment.",
        "a seed from the operating system",
        "whole number in [0, " + std::to_string(std::numeric_limits<std::uint64_t>::max()) + "]"},
       apply_seed, false},
      {"--output",
       {"--output=FILE",
        "Write the field to FILE instead of standard output. A regular FILE appears complete "
        "or not at all: it is written to a temporary file in the same folder and renamed. A "
        "device or FIFO is written through; a link is followed and stays a link.",
        "standard output", "a file name"},
       apply_output, false},
  };
  return table;
}

void apply_argument(const std::string& arg, CommandLine& cli) {
  const auto eq = arg.find('=');
  const std::string_view key = std::string_view(arg).substr(0, eq);
  for (const auto& option : option_table()) {
    if (key != option.key) continue;
    if (option.recorded) cli.recorded_args.push_back(arg);
    if (eq == std::string::npos) {
      cli.errors.push_back(quoted(arg) + ": needs a value, as in " + option.doc.name);
      return;
    }
    option.apply(ArgContext{arg, std::string_view(arg).substr(eq + 1), cli});
    return;
  }
  cli.errors.push_back(quoted(arg) + ": unknown option (see gen_hazards --help)");
}

std::string shell_word(const std::string& arg) {
  if (!arg.empty() && arg.find_first_not_of(kShellSafe) == std::string::npos) return arg;
  std::string out = "'";
  for (char c : arg) {
    if (c == '\'') {
      out += "'\\''";  // close, escaped quote, reopen
    } else {
      out += c;
    }
  }
  return out + "'";
}

}  // namespace

std::uint64_t total_objects(const GeneratorConfig& config) {
  std::uint64_t total = 0;
  for (const auto& set : config.sets) total += set.count;
  return total;
}

CommandLine parse_command_line(const std::vector<std::string>& args) {
  CommandLine cli;
  for (const auto& arg : args) {
    // The MOOS-IvP forms of --help and --version; gen_hazards has no --example or --interface,
    // so those stay unknown options.
    const std::optional<moos::InfoSwitch> info = moos::information_switch(arg);
    if (info == moos::InfoSwitch::kHelp) {
      cli.help = true;
    } else if (info == moos::InfoSwitch::kVersion) {
      cli.version = true;
    } else {
      apply_argument(arg, cli);
    }
  }
  // The original read uninitialised bounds here (docs/gen_hazards.md, D31); objects need
  // somewhere to go. A
  // --polygon that was rejected has its own error already.
  const bool polygon_given = std::any_of(args.begin(), args.end(), [](const std::string& arg) {
    return arg == "--polygon" || arg.rfind("--polygon=", 0) == 0;
  });
  if (!cli.config.sets.empty() && !polygon_given) {
    cli.errors.push_back(quoted(cli.config.sets.front().argument) +
                         ": objects need at least one --polygon");
  }
  return cli;
}

const std::vector<OptionDoc>& option_docs() {
  static const std::vector<OptionDoc> docs = [] {
    std::vector<OptionDoc> out;
    for (const auto& option : option_table()) out.push_back(option.doc);
    out.push_back({"-h, --help, -help", "Print this help and exit.", "-", "-"});
    out.push_back({"-v, --version, -version", "Print the release and exit.", "-", "-"});
    return out;
  }();
  return docs;
}

std::string header_line(const std::vector<std::string>& recorded_args, std::uint64_t seed) {
  std::string out = "// gen_hazards";
  for (const auto& arg : recorded_args) out += " " + shell_word(arg);
  return out + " --seed=" + std::to_string(seed);
}

}  // namespace gen_hazards
