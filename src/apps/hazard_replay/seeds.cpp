// hazard_replay --seeds: one replay per seed, summarised as a JSON line (contract in replay.hpp).
#include <string>

#include "base/text.hpp"
#include "replay.hpp"

namespace hazard_replay {

namespace {

constexpr const char* kDetectionReport = "UHZ_DETECTION_REPORT";
constexpr const char* kHazardReport = "UHZ_HAZARD_REPORT";

}  // namespace

hazard::Engine study_engine(const hazard::Engine& built, std::uint64_t seed) {
  return built.with_seed({seed, hazard::SeedSource::kCommandLine},
                         hazard::PostingReaders::kReportCounts);
}

SeedCounts count_reports(hazard::Driver& driver, const Timeline& timeline) {
  SeedCounts counts;
  replay(driver, timeline, [&](const hazard::TimedOutputs& t) {
    for (const hazard::Posting& p : t.outputs.postings) {
      // Each report is posted twice, once per vehicle variable: count the shared one.
      if (p.variable == kDetectionReport) ++counts.detections;
      if (p.variable == kHazardReport) ++counts.classifications;
    }
  });
  return counts;
}

std::string seed_summary_json(std::uint64_t seed, const SeedCounts& counts,
                              std::optional<double> score) {
  std::string out = "{\"seed\":" + std::to_string(seed) + ",\"detections\":" +
                    std::to_string(counts.detections) + ",\"classifications\":" +
                    std::to_string(counts.classifications);
  // The grader's scores are finite (clipped to [0, 100]): a JSON number.
  if (score) out += ",\"score\":" + base::format_shortest(*score);
  return out + "}";
}

}  // namespace hazard_replay
