#include "hazard/engine.hpp"

#include <algorithm>

#include "base/text.hpp"

namespace hazard {

Engine::Engine(EngineSetup setup, SeedChoice seed)
    : config_(std::move(setup.config)),
      field_(std::move(setup.field)),
      setup_warnings_(std::move(setup.config_warnings)),
      hazard_files_(std::move(setup.hazard_files)),
      effects_(choose_effects(config_, field_)),
      placement_(std::move(setup.placement)),
      seed_(seed),
      dice_(seed.seed) {
  field_.build_index();
  visuals_cursor_ = field_.size();
}

Engine Engine::with_seed(SeedChoice seed) const {
  Engine copy(*this);
  copy.seed_ = seed;
  copy.dice_ = Dice(seed.seed);
  return copy;
}

// The name index is the lookup: a binary search over the ids in name order (a few compares for
// a fleet of 100), so no second name -> id map has to be kept in step with it.
std::vector<VehicleId>::const_iterator Engine::name_position(std::string_view name) const {
  return std::lower_bound(by_name_.begin(), by_name_.end(), name,
                          [&](VehicleId a, std::string_view n) { return vehicles_[a].name < n; });
}

std::optional<VehicleId> Engine::find_vehicle(std::string_view name) const {
  const auto pos = name_position(name);
  if (pos == by_name_.end() || vehicles_[*pos].name != name) return std::nullopt;
  return *pos;
}

VehicleId Engine::vehicle_id(std::string_view name) {
  const auto pos = name_position(name);
  if (pos != by_name_.end() && vehicles_[*pos].name == name) return *pos;
  const auto id = static_cast<VehicleId>(vehicles_.size());
  VehicleState v;
  v.name = std::string(name);
  v.variable_suffix = "_" + base::to_upper(name);
  v.name_hash = hash_name(name);
  if (effects_.turn_blackout) v.heading_history.emplace();
  vehicles_.push_back(std::move(v));
  by_name_.insert(pos, id);
  return id;
}

// ---------------------------------------------------------------------------------------------
// Start-up and the iteration: the table of contents of the engine's rules.

Outputs Engine::start(double now_s) {
  Outputs out;
  start_time_s_ = now_s;
  out.config_warnings = setup_warnings_;
  restart_field_visuals(out);
  return out;
}

// The phases in order: the options summary (settings.cpp), sensing per vehicle in name order
// (sensing.cpp, detection.cpp), the release of classification answers (classification.cpp),
// the next batch of the field's visuals if a big field's are still being posted (visuals.cpp).
Outputs Engine::step(double now_s) {
  Outputs out;
  post_options_summary_if_due(now_s, out);
  for (VehicleId id : by_name_) sense(id, now_s, out);
  release_classifications(now_s, out);
  post_field_visuals_batch(out);
  return out;
}

void Engine::notify(const VehicleState& v, ObjectId id, std::uint32_t pass, DiePurpose purpose,
                    bool outcome) const {
  if (observer_) observer_(Decision{v.name, field_.label(id), pass, purpose, outcome});
}

}  // namespace hazard
