#pragma once
// One load per field: the sensor's engine and the grader, as their blocks' lines configure them,
// built once per field and handed to every mission as copies (hazard::Engine::with_seed gives
// each mission its seed), so a study over a million-object field does not read, parse and index
// it per mission.
//
// Contract:
// - A field is the mission's hazard files, or a generated field (field.hpp) served from memory
//   under its name. start_field() begins the next one and drops everything built for the last.
// - A hazard file is read once per field (by its path relative to the mission file's folder),
//   however many blocks and settings name it (the last kMaxBuilds files read are kept).
// - An engine or a grader is built once per field for each distinct block configuration (the
//   lines with their file and line; the sensor's random_seed aside): a setting that --sets the
//   sensor's or the grader's block builds its own. At most kMaxBuilds of each are kept (the
//   oldest goes), so memory stays bounded over many settings.
// - A copy is the object the app would have built itself: the same field, configuration,
//   warnings and seed (random_seed = seed), so a mission's line does not change.

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "HazardMetric.hpp"
#include "base/result.hpp"
#include "hazard/effects.hpp"
#include "hazard/engine.hpp"
#include "moos/app.hpp"

namespace hazard_study {

/// Builds kept per kind (engines, graders) within one field.
inline constexpr std::size_t kMaxBuilds = 4;

class FieldCache {
 public:
  /// The next field: `generated` names the generated field and holds its text; nullopt: the
  /// mission's hazard files.
  void start_field(std::optional<std::pair<std::string, std::string>> generated);

  /// The sensor's engine for a mission with `seed` (its random_seed).
  hazard::Engine sensor_engine(const std::vector<moos::ConfigLine>& lines,
                               const moos::AppSettings& settings, hazard::PostingReaders readers,
                               std::uint64_t seed);
  /// The grader for a mission.
  ufld_hazard_metric::ConfiguredMetric metric(const std::vector<moos::ConfigLine>& lines,
                                              const std::string& mission_directory);

  /// Hazard files read and blocks built since the field started (tests count them).
  std::size_t files_read() const { return files_read_; }
  std::size_t builds() const { return builds_; }

 private:
  base::Result<std::string> read(const std::string& mission_directory, const std::string& path);

  std::optional<std::pair<std::string, std::string>> generated_;
  std::deque<std::pair<std::string, base::Result<std::string>>> texts_;  ///< by resolved path
  std::deque<std::pair<std::string, hazard::Engine>> engines_;
  std::deque<std::pair<std::string, ufld_hazard_metric::ConfiguredMetric>> metrics_;
  std::size_t files_read_ = 0;
  std::size_t builds_ = 0;
};

}  // namespace hazard_study
