#pragma once
// Test support for the mission helper applications (uSimSurveyVehicle, pHazardMgr,
// uFldHazardMetric, pLogLite): the app class started on libmoos's in-process bus with a manual
// clock, as main would start it (libmoos's command line and mission reader), from a mission
// file written into a scratch folder (tests/support). Cycles are instant and exact; a peer client
// posts mail and reads the app's postings.

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "moos/app.hpp"
#include "moos/bus.hpp"
#include "moos/clock.hpp"
#include "moos/command_line.hpp"
#include "moos/mission.hpp"
#include "scratch_files.hpp"

namespace mission_test {

/// Lines 1-5 of every test mission: globals, then the block header. The block's first line is
/// line kFirstBlockLine of the file.
inline std::string mission_text(const std::string& app, const std::string& block,
                                const std::string& globals = "LatOrigin = 43.8253\nLongOrigin = -70.3304\n") {
  return "Community = jake\n" + globals + "ProcessConfig = " + app + "\n{\n" + block + "}\n";
}
inline int first_block_line(const std::string& globals_lines = "LatOrigin = 43.8253\nLongOrigin = -70.3304\n") {
  int lines = 0;
  for (char c : globals_lines) lines += c == '\n';
  return 4 + lines;
}

/// The bus, its clock and a peer client; one app at a time.
class Bus {
 public:
  static constexpr double kT0 = moos::ManualClock::kDefaultStartUnix_s;

  Bus() = default;

  /// Writes m.moos (`mission_file`) into the scratch folder and starts `app` under `app_name`
  /// (its block) as main would. Returns false if on_start_up failed.
  bool start(moos::MoosApp& app, const std::string& app_name, const std::string& mission_file) {
    test_support::write_file(dir / "m.moos", mission_file);
    std::vector<moos::MissionError> errors;
    mission = moos::MissionFile::load((dir / "m.moos").string(), {}, &errors);
    EXPECT_TRUE(mission.has_value());
    const std::vector<std::string> args = {app_name, (dir / "m.moos").string(), app_name};
    moos::AppSettings settings = moos::resolve_app_settings(
        app.traits(), moos::parse_command_line(args), &*mission, errors);
    settings.time_warp = bus.time_warp();
    comms = bus.connect(settings.moos_name);
    EXPECT_TRUE(comms);
    return app.start(*comms, std::move(settings));
  }

  void post(const std::string& var, const std::string& value) { ASSERT_TRUE(peer->notify(var, value)); }
  void post(const std::string& var, double value) { ASSERT_TRUE(peer->notify(var, value)); }

  /// The string values `source` posted to `var`, in order.
  std::vector<std::string> values_of(const std::string& var, const std::string& source) const {
    std::vector<std::string> out;
    for (const auto& m : bus.postings_of(var))
      if (m.source == source) out.push_back(m.is_double() ? std::to_string(m.dval) : m.sval);
    return out;
  }
  /// Every posting of `source`, in order (variable names).
  std::vector<std::string> variables_posted_by(const std::string& source) const {
    std::vector<std::string> out;
    for (const auto& m : bus.postings())
      if (m.source == source) out.push_back(m.key);
    return out;
  }

  test_support::ScratchDir dir{"mission_app"};
  moos::ManualClock clock{kT0};
  moos::InProcessBus bus{clock, moos::InProcessBus::Options{"jake", 1.0}};
  std::unique_ptr<moos::BusClient> peer = bus.connect("peer");
  std::unique_ptr<moos::BusClient> comms;
  std::optional<moos::MissionFile> mission;
};

/// The body of an --example text's `ProcessConfig = app { ... }` block (between "{\n" and the
/// last "}"); nullopt when the text has no block.
inline std::optional<std::string> example_block(const std::string& example_text) {
  const auto open = example_text.find("{\n"), close = example_text.rfind("}");
  if (open == std::string::npos) return std::nullopt;
  return example_text.substr(open + 2, close - open - 2);
}

/// True if some text in `texts` contains `part`.
inline bool any_contains(const std::vector<std::string>& texts, const std::string& part) {
  for (const auto& t : texts)
    if (t.find(part) != std::string::npos) return true;
  return false;
}

/// Run warnings of an AppCast as a list of texts.
inline std::vector<std::string> run_warning_texts(const moos::AppCast& cast) {
  std::vector<std::string> out;
  for (const auto& [text, count] : cast.run_warnings()) out.push_back(text);
  return out;
}

}  // namespace mission_test
