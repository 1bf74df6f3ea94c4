// mission_app, what the mission helper applications share: the launch decision, libMOOS's
// --moos_tw_delay_factor switch, the text frames, and MissionApp::publish (order kept, nothing
// lost before the first connection).
#include <gtest/gtest.h>

#include "app_on_bus.hpp"
#include "mission_app.hpp"
#include "moos/command_line.hpp"

namespace mission_app {
namespace {

moos::CommandLine cl(std::vector<std::string> args) {
  args.insert(args.begin(), "app");
  return moos::parse_command_line(args);
}

TEST(MissionAppLaunch, FirstInformationSwitchDecides_Spec2) {
  EXPECT_EQ(moos::decide_launch(cl({"m.moos"})), moos::LaunchAction::kRun);
  EXPECT_EQ(moos::decide_launch(cl({})), moos::LaunchAction::kHelp);  // no mission file: the help
  EXPECT_EQ(moos::decide_launch(cl({"m.moos", "-e", "--help"})), moos::LaunchAction::kExample);
  EXPECT_EQ(moos::decide_launch(cl({"--interface", "-v"})), moos::LaunchAction::kInterface);
  EXPECT_EQ(moos::decide_launch(cl({"-version"})), moos::LaunchAction::kVersion);
  EXPECT_EQ(moos::decide_launch(cl({"m.moos", "-help"})), moos::LaunchAction::kHelp);
}

TEST(MissionAppText, ParameterLinesAlignAndCommentOutWhatHasNoValue_Practice5) {
  const std::vector<mission::ParamInfo> params = {
      {"speed", "1.5", "cruise speed"}, {"region", "", "survey area"}, {"vname", "", "name"}};
  EXPECT_EQ(parameter_lines(params, {{"vname", "archie"}}),
            "  speed     = 1.5     // cruise speed\n"
            "  // region =         // survey area\n"
            "  vname     = archie  // name\n");
}

TEST(MissionAppText, FramesHaveTheMoosIvpShape) {
  const std::string help = help_text("pFoo", "Does foo.\n", "  --bar\n      Bars.\n");
  EXPECT_EQ(help.rfind(rule() + "Usage: pFoo file.moos [OPTIONS]\n" + rule(), 0), 0u);
  for (const char* part : {"Does foo.", "--bar", "--alias=<ProcessName>", "--example, -e",
                           "--interface, -i", "--version,-v", "run alias", "Exit codes"})
    EXPECT_NE(help.find(part), std::string::npos) << part;
  EXPECT_EQ(example_text("pFoo", "  a = 1\n"),
            "// " + rule() + "// pFoo Example MOOS Configuration\n// " + rule() +
                "\nProcessConfig = pFoo\n{\n  a = 1\n}\n");
  EXPECT_EQ(rule().size(), 64u);
  EXPECT_EQ(at_line({"k", "v", "m.moos", 7}, "bad"), "m.moos:7: bad");
  EXPECT_EQ(at_line({"k", "v", "", 0}, "bad"), "bad");
}

// An app that publishes at start-up, before the client may be connected.
class StartupPoster : public MissionApp {
 public:
  StartupPoster() : MissionApp(traits()) {}
  static moos::AppTraits traits() {
    moos::AppTraits t;
    t.default_name = "pStartup";
    return t;
  }

 protected:
  bool on_start_up() override {
    mission::Outputs out;
    out.post("FIRST", "1");
    out.post_double("SECOND", 2.0);
    out.post("THIRD", "3");
    out.events.push_back("started");
    out.run_warnings.push_back("a run warning");
    publish(out);
    return true;
  }
};

TEST(MissionAppPublish, PostingsMadeBeforeTheConnectionAreSentInOrderOnceConnected) {
  mission_test::Bus bus;
  StartupPoster app;
  bus.comms = bus.bus.connect("pStartup");
  bus.comms->simulate_disconnect();
  moos::AppSettings settings;
  settings.app_name = settings.moos_name = "pStartup";
  ASSERT_TRUE(app.start(*bus.comms, settings));
  EXPECT_TRUE(bus.variables_posted_by("pStartup").empty());
  EXPECT_EQ(app.appcast().run_warning_count(), 1u);
  EXPECT_EQ(app.appcast().events().size(), 1u);
  app.run_for(1.0);  // not connected: libmoos does not iterate
  ASSERT_TRUE(bus.comms->simulate_reconnect());
  app.run_for(1.0);
  auto posted = bus.variables_posted_by("pStartup");
  // Only the app's own postings (not the framework's status, timing and appcast).
  posted.erase(std::remove_if(posted.begin(), posted.end(),
                              [](const std::string& v) {
                                return v == "APPCAST" || v == "PSTARTUP_STATUS" ||
                                       v.find("_ITER_") != std::string::npos;
                              }),
               posted.end());
  EXPECT_EQ(posted, (std::vector<std::string>{"FIRST", "SECOND", "THIRD"}));
  EXPECT_TRUE(bus.bus.postings_of("SECOND")[0].is_double());
}

}  // namespace
}  // namespace mission_app
