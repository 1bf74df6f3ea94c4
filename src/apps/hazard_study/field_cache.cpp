// hazard_study: one load per field. Contract in field_cache.hpp.

#include "field_cache.hpp"

#include <algorithm>
#include <filesystem>

#include "app_support.hpp"
#include "base/file.hpp"
#include "base/text.hpp"

namespace hazard_study {

namespace {

/// The block's lines as one key: each line's key, value, file and line; `skipped` left out.
std::string key_of(const std::vector<moos::ConfigLine>& lines, const char* skipped) {
  std::string key;
  for (const moos::ConfigLine& l : lines) {
    if (skipped && base::iequals(l.key, skipped)) continue;
    key += l.key + '\n' + l.value + '\n' + l.file + ':' + std::to_string(l.line) + '\n';
  }
  return key;
}

/// The value kept under `key`, or nullptr.
template <class T>
T* find(std::deque<std::pair<std::string, T>>& kept, const std::string& key) {
  const auto it =
      std::find_if(kept.begin(), kept.end(), [&](const auto& k) { return k.first == key; });
  return it == kept.end() ? nullptr : &it->second;
}

/// Keeps `value` under `key`, dropping the oldest beyond kMaxBuilds.
template <class T>
T& keep(std::deque<std::pair<std::string, T>>& kept, std::string key, T value) {
  if (kept.size() >= kMaxBuilds) kept.pop_front();
  kept.emplace_back(std::move(key), std::move(value));
  return kept.back().second;
}

}  // namespace

void FieldCache::start_field(std::optional<std::pair<std::string, std::string>> generated) {
  generated_ = std::move(generated);
  texts_.clear();
  engines_.clear();
  metrics_.clear();
  files_read_ = builds_ = 0;
}

base::Result<std::string> FieldCache::read(const std::string& mission_directory,
                                           const std::string& path) {
  if (generated_ && path == generated_->first)
    return base::Result<std::string>::ok(generated_->second);
  const std::filesystem::path p(path);
  const std::string resolved =
      (p.is_relative() ? std::filesystem::path(mission_directory) / p : p).string();
  if (const auto* text = find(texts_, resolved)) return *text;
  ++files_read_;
  return keep(texts_, resolved, base::read_file_text(resolved));
}

hazard::Engine FieldCache::sensor_engine(const std::vector<moos::ConfigLine>& lines,
                                         const moos::AppSettings& settings,
                                         hazard::PostingReaders readers, std::uint64_t seed) {
  std::string key = key_of(lines, "random_seed");
  const hazard::Engine* built = find(engines_, key);
  if (!built) {
    ++builds_;
    const auto reader = [&](const std::string& path) {
      return read(settings.mission_directory, path);
    };
    // random_seed is always given (mission_plan.hpp), so the operating system is never asked.
    const auto no_os_seed = [] { return hazard::kUnseededSeed; };
    built = &keep(engines_, std::move(key),
                  app_support::make_sensor_engine(lines, reader,
                                                  app_support::mission_origin(settings),
                                                  std::nullopt, no_os_seed));
  }
  return built->with_seed(hazard::SeedChoice{seed, hazard::SeedSource::kRandomSeed}, readers);
}

ufld_hazard_metric::ConfiguredMetric FieldCache::metric(const std::vector<moos::ConfigLine>& lines,
                                                        const std::string& mission_directory) {
  std::string key = key_of(lines, nullptr);
  if (const auto* built = find(metrics_, key)) return *built;
  ++builds_;
  const auto reader = [&](const std::string& path) { return read(mission_directory, path); };
  return keep(metrics_, std::move(key), ufld_hazard_metric::configure_metric(lines, reader));
}

}  // namespace hazard_study
