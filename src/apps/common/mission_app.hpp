#pragma once
// What the mission helper applications (uSimSurveyVehicle, pHazardMgr, uFldHazardMetric, pLogLite)
// share besides their main (which is moos::launch, as for every MOOS app): the frames of their
// information texts, and a MoosApp base that publishes a libmission Outputs value.
//
// Contract
// - moos::run_app (through moos::launch) reads the mission file once; the app finds the file's
//   folder and globals (LatOrigin, LongOrigin) in its settings (moos::AppSettings).
// - MissionApp::publish posts every posting of an Outputs value in order (doubles as MOOS doubles)
//   and hands events and warnings to the AppCast. Postings made while the client is not
//   connected wait in its outbox and leave, in order, after the next handshake (the delivery
//   contract of moos/comms.hpp): start-up postings are never lost to a slow first connection.

#include <functional>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mission/outputs.hpp"
#include "mission/params.hpp"
#include "moos/app.hpp"

namespace mission_app {

// ---- text frames ---------------------------------------------------------------------------

/// A line of 63 '=' (the MOOS-IvP information screens, manual listings 10.3 and 11.4).
std::string rule();
/// `title` between two rules.
std::string banner(const std::string& title);

/// --help: the usage banner, `description` (lines ending in '\n'), the application's own
/// command-line options (may be empty) and the standard ones, the pAntler note and exit codes.
std::string help_text(const std::string& app_name, const std::string& description,
                      const std::string& app_options = {});

/// One titled group of parameters of an --example block.
struct ParameterSection {
  std::string title;  ///< a comment line, e.g. "The application"
  const std::vector<mission::ParamInfo>* params;
};
/// The body of an --example block: AppTick / CommsTick, then each section's parameter_lines.
std::string example_body(double app_tick_hz, const std::vector<ParameterSection>& sections,
                         const std::map<std::string, std::string>& examples = {});

/// --example: the commented banner and `ProcessConfig = app_name { body }`.
std::string example_text(const std::string& app_name, const std::string& body);

/// Example lines for a parameter table, `=` and `//` aligned: `  name = default  // help`.
/// A parameter without a default shows its value from `examples` when there is one, else it is
/// shown commented out with an empty value.
std::string parameter_lines(const std::vector<mission::ParamInfo>& params,
                            const std::map<std::string, std::string>& examples = {});

/// One variable of --interface.
struct InterfaceVariable {
  std::string name;
  std::string example;
  std::string meaning;
};
/// --interface: subscriptions and publications with example payloads, then `notes`.
std::string interface_text(const std::string& app_name,
                           const std::vector<InterfaceVariable>& subscriptions,
                           const std::vector<InterfaceVariable>& publications,
                           const std::string& notes = {});
/// The framework's own publications of an app (APPCAST, <APP>_STATUS), for --interface.
std::vector<InterfaceVariable> framework_publications(const std::string& app_name);

/// One line: "<app> <release> (HazardSensor)".
std::string version_text(const std::string& app_name);

// ---- the application base ----------------------------------------------------------------

/// The framework settings the mission apps share: the process name, AppTick (MOOS-time Hz),
/// D36's rule for repeated framework parameters, and no `<APP>_ITER_GAP` / `_ITER_LEN`: at a high
/// warp those two postings per iteration would outnumber everything the mission says (libmoos
/// still posts `<APP>_STATUS`).
moos::AppTraits mission_traits(const std::string& app_name, double app_tick_hz);

/// A name for a vehicle, variable or type: non-empty, without blanks, ',', '=' or '#' (the
/// separators of MOOS strings).
bool is_name(std::string_view text);

/// A message's value as text: strings as they are, doubles as FMT(., 6).
std::string mail_text(const moos::Message& message);

/// "file:line: text" for a configuration line (the place of a configuration warning).
std::string at_line(const moos::ConfigLine& line, const std::string& text);

/// A true/false parameter into `field`: "" when set, else "parameter <key>='<value>' is not true
/// or false" (the field is unchanged).
std::string bool_param(const std::string& key, const std::string& value, bool& field);
/// A name parameter (is_name) into `field`: "" when set, else "parameter <key>='<value>' is not
/// <what>" (the field is unchanged).
std::string name_param(const std::string& key, const std::string& value, std::string& field,
                       const std::string& what);

/// `text` as a report-table column: padded with blanks to `width`, and at least one blank after.
std::string column(const std::string& text, std::size_t width);

class MissionApp : public moos::MoosApp {
 public:
  using moos::MoosApp::MoosApp;

 protected:
  /// Runs on_iterate().
  void iterate() final;
  /// The app's own iteration (the hook apps override instead of iterate()).
  virtual void on_iterate() {}

  /// Posts `out` in order and reports its events and warnings (see the contract). Inline:
  /// most iterations of most apps have nothing to publish, and then no call is made.
  void publish(const mission::Outputs& out) {
    if (!out.empty()) publish_all(out);
  }
  /// A configuration warning naming the line.
  void warn_at(const moos::ConfigLine& line, const std::string& text);
  /// Hands every line of the block to `apply`, in file order; a non-empty answer is a
  /// configuration warning naming the line (warn_at).
  void apply_config_lines(const std::function<std::string(const moos::ConfigLine&)>& apply);
  /// The vehicle name: `configured`, else the community name; when that is not a name (is_name),
  /// a configuration warning and the app's default process name.
  std::string vehicle_name(const std::string& configured);

 private:
  /// publish() of a non-empty Outputs.
  void publish_all(const mission::Outputs& out);
  bool send(const mission::Posting& posting);
};

}  // namespace mission_app
