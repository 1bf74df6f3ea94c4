#include "hazard/engine.hpp"

#include <algorithm>

#include "base/same_text.hpp"
#include "base/text.hpp"

namespace hazard {

Engine::Engine(EngineSetup setup, SeedChoice seed)
    : config_(std::move(setup.config)),
      options_summary_text_(format_options_summary(config_.options.summary())),
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

Engine Engine::with_seed(SeedChoice seed, PostingReaders readers) const {
  Engine copy(*this);
  copy.seed_ = seed;
  copy.dice_ = Dice(seed.seed);
  copy.effects_ = for_readers(effects_, readers);
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

std::optional<VehicleId> Engine::recent_vehicle(std::string_view name, std::size_t slot) const {
  const VehicleId id = recent_ids_[slot];
  if (id < vehicles_.size() && vehicles_[id].name == name) return id;
  return std::nullopt;
}

std::optional<VehicleId> Engine::vehicle_id(std::string_view name, double now_s, Outputs& out) {
  for (const VehicleId id : last_ids_) {
    if (id < vehicles_.size() && base::same_text(vehicles_[id].name, name)) {
      vehicles_[id].last_mail_s = now_s;
      return id;
    }
  }
  return hashed_vehicle_id(name, now_s, out);
}

std::optional<VehicleId> Engine::hashed_vehicle_id(std::string_view name, double now_s,
                                                   Outputs& out) {
  const auto id = find_or_add_vehicle(name, now_s, out);
  if (id) {
    last_ids_[next_last_id_] = *id;
    next_last_id_ = (next_last_id_ + 1) % last_ids_.size();
  }
  return id;
}

std::optional<VehicleId> Engine::find_or_add_vehicle(std::string_view name, double now_s,
                                                     Outputs& out) {
  const std::size_t recent = hash_name(name) % kRecentIdSlots;
  if (const auto id = recent_vehicle(name, recent)) {
    vehicles_[*id].last_mail_s = now_s;
    return id;
  }
  const auto pos = name_position(name);
  if (pos != by_name_.end() && vehicles_[*pos].name == name) {
    vehicles_[*pos].last_mail_s = now_s;
    recent_ids_[recent] = *pos;
    return *pos;
  }
  const auto slot = free_vehicle_slot(name, now_s, out);
  if (!slot) return std::nullopt;
  VehicleState v;
  v.name = std::string(name);
  v.variable_suffix = "_" + base::to_upper(name);
  v.name_hash = hash_name(name);
  v.last_mail_s = now_s;
  if (effects_.turn_blackout) v.heading_history.emplace();
  if (*slot == vehicles_.size()) {
    vehicles_.push_back(std::move(v));
  } else {
    vehicles_[*slot] = std::move(v);
  }
  by_name_.insert(name_position(name), *slot);
  recent_ids_[recent] = *slot;
  return *slot;
}

// The table is bounded (kMaxVehicles): a full table makes room only by forgetting a vehicle
// that has been silent for kForgetSilentAfter_s, which by then neither senses nor holds a width.
std::optional<VehicleId> Engine::free_vehicle_slot(std::string_view name, double now_s,
                                                   Outputs& out) {
  if (vehicles_.size() < kMaxVehicles) {
    warned_vehicle_table_full_ = false;
    return static_cast<VehicleId>(vehicles_.size());
  }
  const auto silent = std::min_element(
      vehicles_.begin(), vehicles_.end(),
      [](const VehicleState& a, const VehicleState& b) { return a.last_mail_s < b.last_mail_s; });
  const double silent_s = now_s - silent->last_mail_s;
  if (silent_s >= kForgetSilentAfter_s) {
    const auto id = static_cast<VehicleId>(silent - vehicles_.begin());
    out.run_warnings.push_back("Vehicle table full (kMaxVehicles = " +
                               std::to_string(kMaxVehicles) + " vehicles): forgot " +
                               silent->name + ", silent for " + base::fix(silent_s, 0) +
                               " s, to make room for " + base::excerpt(name));
    by_name_.erase(name_position(silent->name));
    ++drops_.vehicles_forgotten;
    warned_vehicle_table_full_ = false;  // a later refusal starts a new episode
    return id;
  }
  ++drops_.vehicles;
  if (!warned_vehicle_table_full_) {
    out.run_warnings.push_back("Vehicle table full (kMaxVehicles = " +
                               std::to_string(kMaxVehicles) + " vehicles, none silent for " +
                               base::fix(kForgetSilentAfter_s, 0) + " s): mail from new vehicle " +
                               base::excerpt(name) + " dropped (further drops only counted)");
  }
  warned_vehicle_table_full_ = true;
  return std::nullopt;
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
  // One swath polygon per vehicle, usually: room for them at once, not by doubling.
  if (effects_.swath_visuals) out.postings.reserve(by_name_.size() + 1);
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
