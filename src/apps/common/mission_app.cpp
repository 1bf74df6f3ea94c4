#include "mission_app.hpp"

#include <algorithm>

#include "app_support.hpp"
#include "base/text.hpp"
#include "base/version.hpp"
#include "moos/mission.hpp"

namespace mission_app {

namespace {

/// Width of the '=' rules of the MOOS-IvP information screens.
constexpr std::size_t kRuleWidth = 63;
/// Width of the '-' rule under an --interface section title.
constexpr std::size_t kSectionRuleWidth = 40;

/// Decimals of a double handed to a text parser (a pose or a flag never needs more).
constexpr int kMailDoubleDecimals = 6;

std::string padded(std::string_view text, std::size_t width) {
  return std::string(text) + std::string(width > text.size() ? width - text.size() : 0, ' ');
}

std::string interface_section(const std::string& title,
                              const std::vector<InterfaceVariable>& variables) {
  std::string out = title + "\n" + std::string(kSectionRuleWidth, '-') + "\n";
  for (const InterfaceVariable& v : variables)
    out += "  " + v.name + " = " + v.example + "\n      " + v.meaning + "\n";
  return out;
}

}  // namespace

// ---- text frames ---------------------------------------------------------------------------

std::string rule() { return std::string(kRuleWidth, '=') + "\n"; }

std::string banner(const std::string& title) { return rule() + title + "\n" + rule(); }

std::string help_text(const std::string& app_name, const std::string& description,
                      const std::string& app_options) {
  return banner("Usage: " + app_name + " file.moos [OPTIONS]") + "\n" + description +
         "\n"
         "Options:\n" +
         app_options +
         app_support::information_switches_help(app_name) + app_support::generic_switches_help() +
         "Exit codes: 0 after SIGINT/SIGTERM or an information switch; 1 if the\n"
         "mission file cannot be read, the MOOSDB refuses the name or start-up fails.\n";
}

std::string example_body(double app_tick_hz, const std::vector<ParameterSection>& sections,
                         const std::map<std::string, std::string>& examples) {
  const std::string tick = base::format_g(app_tick_hz);
  std::string out = "  AppTick   = " + tick + "\n  CommsTick = " + tick + "\n";
  for (const ParameterSection& s : sections)
    out += "\n  // " + s.title + "\n" + parameter_lines(*s.params, examples);
  return out;
}

std::string example_text(const std::string& app_name, const std::string& body) {
  std::string out;
  for (const std::string& line : {rule(), app_name + " Example MOOS Configuration\n", rule()})
    out += "// " + line;
  return out + "\nProcessConfig = " + app_name + "\n{\n" + body + "}\n";
}

std::string parameter_lines(const std::vector<mission::ParamInfo>& params,
                            const std::map<std::string, std::string>& examples) {
  struct Line {
    std::string key, value, help;
    bool commented;
  };
  std::vector<Line> lines;
  for (const mission::ParamInfo& p : params) {
    const auto example = examples.find(p.name);
    const bool has_default = p.default_text[0] != '\0';
    const std::string value =
        has_default ? p.default_text : (example != examples.end() ? example->second : "");
    lines.push_back({p.name, value, p.help, !has_default && example == examples.end()});
  }
  std::size_t key_width = 0, value_width = 0;
  for (const Line& l : lines) {
    key_width = std::max(key_width, l.key.size() + (l.commented ? 3 : 0));
    value_width = std::max(value_width, l.value.size());
  }
  std::string out;
  for (const Line& l : lines) {
    const std::string key = (l.commented ? "// " : "") + l.key;
    out += "  " + padded(key, key_width) + " = " + padded(l.value, value_width) + "  // " +
           l.help + "\n";
  }
  return out;
}

std::string interface_text(const std::string& app_name,
                           const std::vector<InterfaceVariable>& subscriptions,
                           const std::vector<InterfaceVariable>& publications,
                           const std::string& notes) {
  return banner(app_name + " INTERFACE") + "\n" + interface_section("SUBSCRIPTIONS:", subscriptions) +
         "\n" + interface_section("PUBLICATIONS:", publications) + (notes.empty() ? "" : "\n") +
         notes;
}

std::vector<InterfaceVariable> framework_publications(const std::string& app_name) {
  const std::string upper = base::to_upper(app_name);
  return {
      {"APPCAST", "proc=" + app_name + "!@#iter=12!@#node=jake!@#...",
       "the AppCast report (the terminal report's content), while requested (APPCAST_REQ)"},
      {upper + "_STATUS",
       "AppErrorFlag=false,Uptime=12.3,MOOSName=" + app_name + ",Publishing=\"...\",...",
       "<APPNAME>_STATUS: the process status, every 2 s"},
  };
}

std::string version_text(const std::string& app_name) {
  return base::version_line(app_name);
}

// ---- the application base ----------------------------------------------------------------

std::string at_line(const moos::ConfigLine& line, const std::string& text) {
  if (line.file.empty()) return text;
  return line.file + ":" + std::to_string(line.line) + ": " + text;
}

moos::AppTraits mission_traits(const std::string& app_name, double app_tick_hz) {
  moos::AppTraits t;
  t.default_name = app_name;
  t.default_app_tick_hz = app_tick_hz;
  t.post_iteration_timing = false;
  t.repeated_parameters = moos::RepeatedParameter::kLastWinsWithWarning;
  return t;
}

std::string bool_param(const std::string& key, const std::string& value, bool& field) {
  const auto b = base::parse_bool(value);
  if (!b) return "parameter " + key + "='" + value + "' is not true or false";
  field = *b;
  return {};
}

std::string name_param(const std::string& key, const std::string& value, std::string& field,
                       const std::string& what) {
  if (!is_name(value)) return "parameter " + key + "='" + value + "' is not " + what;
  field = value;
  return {};
}

std::string column(const std::string& text, std::size_t width) {
  return text + std::string(text.size() < width ? width - text.size() : 1, ' ');
}

bool is_name(std::string_view text) {
  return !text.empty() && text.find_first_of(" \t,=#") == std::string_view::npos;
}

std::string mail_text(const moos::Message& m) {
  return m.is_double() ? base::fmt(m.dval, kMailDoubleDecimals) : m.sval;
}

bool MissionApp::send(const mission::Posting& p) {
  return p.number ? notify(p.variable, *p.number) : notify(p.variable, p.text);
}

void MissionApp::publish_all(const mission::Outputs& out) {
  // Postings made while disconnected wait in the comms' outbox (comms.hpp); a refused one is
  // counted there and reported by the app base.
  for (const mission::Posting& p : out.postings) send(p);
  for (const std::string& w : out.config_warnings) report_config_warning(w);
  for (const std::string& w : out.run_warnings) report_run_warning(w);
  for (const std::string& e : out.events) report_event(e);
}

void MissionApp::iterate() { on_iterate(); }

void MissionApp::warn_at(const moos::ConfigLine& line, const std::string& text) {
  report_config_warning(at_line(line, text));
}

void MissionApp::apply_config_lines(
    const std::function<std::string(const moos::ConfigLine&)>& apply) {
  for (const moos::ConfigLine& line : config_lines()) {
    const std::string problem = apply(line);
    if (!problem.empty()) warn_at(line, problem);
  }
}

std::string MissionApp::vehicle_name(const std::string& configured) {
  std::string name = configured.empty() ? community() : configured;
  if (!is_name(name)) {
    report_config_warning("no vehicle name: set vname (the community name '" + name +
                          "' is not one)");
    name = traits().default_name;
  }
  return name;
}

}  // namespace mission_app
