// Who reads the postings (effects.hpp, PostingReaders): an engine built for report counts
// (hazard_replay --seeds) builds no visual at all, and everything else it does is what the
// engine built for viewers does: every other posting, event and warning, every die.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "base/text.hpp"
#include "hazard/driver.hpp"
#include "scenario.hpp"
#include "scenario/reference_scenario.hpp"

namespace hazard {
namespace {

struct Played {
  std::string text;  // every output of every call except the VIEW_* postings, in order
  std::vector<std::string> decisions;
  int visuals = 0;  // VIEW_* postings
  std::vector<std::string> visual_kinds;
};

Played play(PostingReaders readers, std::uint64_t seed) {
  // The reference survey with every visual on, the markers too, and a viewer that connects.
  Scenario s = reference_survey(4.0);
  for (const ConfigEntry& e :
       testing::entries("show_swath = true\nshow_hazards = true\nshow_detections = 30\n")) {
    s.config.push_back(e);
  }
  s.mail.insert(s.mail.begin() + static_cast<std::ptrdiff_t>(s.mail.size() / 2),
                TimedMail{s.mail[s.mail.size() / 2].time_s, "PMV_CONNECT", "true"});
  const Engine built(load_configuration(s.config, testing::no_files),
                     SeedChoice{1, SeedSource::kFixed});
  Driver driver(built.with_seed({seed, SeedSource::kCommandLine}, readers));
  Played r;
  driver.set_decision_observer(
      [&](const Decision& d) { r.decisions.push_back(testing::decision_tuple(d)); });
  const auto record = [&](const Outputs& o) {
    for (const Posting& p : o.postings) {
      if (base::starts_with(p.variable, "VIEW_")) {
        ++r.visuals;
        r.visual_kinds.push_back(p.variable);
      } else {
        r.text += "P " + p.variable + "=" + p.value + "\n";
      }
    }
    for (const auto& e : o.events) r.text += "E " + e + "\n";
    for (const auto& w : o.run_warnings) r.text += "W " + w + "\n";
    for (const auto& w : o.retracted_run_warnings) r.text += "R " + w + "\n";
    for (const auto& w : o.config_warnings) r.text += "C " + w + "\n";
  };
  record(driver.start(0).outputs);
  play_mail(driver, s.mail, 4.0, s.end_time_s, record, record);
  return r;
}

bool has(const std::vector<std::string>& kinds, const std::string& kind) {
  return std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
}

TEST(PostingReaders, ReportCountsBuildNoVisualAndChangeNothingElse) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const Played viewers = play(PostingReaders::kViewers, seed);
    const Played counts = play(PostingReaders::kReportCounts, seed);
    // The scene draws every kind of visual for viewers ...
    for (const char* kind : {"VIEW_POLYGON", "VIEW_CIRCLE", "VIEW_MARKER", "VIEW_SEGLIST"}) {
      EXPECT_TRUE(has(viewers.visual_kinds, kind)) << kind;
    }
    // ... and none for report counts, with the same reports, events, warnings and dice.
    EXPECT_EQ(counts.visuals, 0) << "seed " << seed;
    EXPECT_EQ(counts.text, viewers.text) << "seed " << seed;
    EXPECT_EQ(counts.decisions, viewers.decisions) << "seed " << seed;
    EXPECT_NE(viewers.text.find("P UHZ_DETECTION_REPORT="), std::string::npos);
    EXPECT_NE(viewers.text.find("P UHZ_HAZARD_REPORT="), std::string::npos);
  }
}

TEST(PostingReaders, OnlyTheVisualEffectsDependOnTheReaders) {
  Effects all;
  all.speed_gate = all.turn_blackout = all.resemblance = all.aspect = true;
  all.swath_visuals = all.detection_visuals = all.hazard_markers = true;
  all.swept_swath = all.swath_substeps = all.geodesy = true;
  EXPECT_EQ(for_readers(all, PostingReaders::kViewers).active_names(), all.active_names());
  EXPECT_EQ(for_readers(all, PostingReaders::kReportCounts).active_names(),
            (std::vector<std::string_view>{"speed_gate", "turn_blackout", "resemblance", "aspect",
                                           "swept_swath", "swath_substeps", "geodesy"}));
}

}  // namespace
}  // namespace hazard
