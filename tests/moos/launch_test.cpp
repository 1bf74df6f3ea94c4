// moos::decide_launch with an application's own switches: the extension point that
// uFldHazardSensor's --verbose uses (the whole sequence runs in the apps' process tests).
#include <gtest/gtest.h>

#include "moos/launch.hpp"

namespace moos {
namespace {

CommandLine parse(std::vector<std::string> args) {
  args.insert(args.begin(), "pFoo");
  return parse_command_line(args);
}

/// Own switches that refuse `--loud` and count their calls.
OwnSwitches refusing_loud(int* calls) {
  return [calls](const CommandLine& cl) -> std::string {
    ++*calls;
    for (const std::string& arg : cl.unhandled)
      if (arg == "--loud") return "'--loud' is not a switch of pFoo";
    return "";
  };
}

TEST(Launch, WithoutOwnSwitchesTheCommandLineDecides_Spec2) {
  EXPECT_EQ(decide_launch(parse({"m.moos"}), OwnSwitches{}).action, LaunchAction::kRun);
  EXPECT_EQ(decide_launch(parse({}), OwnSwitches{}).action, LaunchAction::kHelp);
  EXPECT_EQ(decide_launch(parse({"m.moos", "-i"}), OwnSwitches{}).action, LaunchAction::kInterface);
}

TEST(Launch, OwnSwitchesAreReadOnceAndTheirErrorBeatsTheInformationSwitches) {
  int calls = 0;
  const LaunchDecision bad = decide_launch(parse({"--help", "m.moos", "--loud"}), refusing_loud(&calls));
  EXPECT_EQ(bad.action, LaunchAction::kUsageError);
  EXPECT_EQ(bad.error, "'--loud' is not a switch of pFoo");
  EXPECT_EQ(calls, 1);
  const LaunchDecision good = decide_launch(parse({"m.moos", "-v"}), refusing_loud(&calls));
  EXPECT_EQ(good.action, LaunchAction::kVersion);
  EXPECT_TRUE(good.error.empty());
  EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace moos
