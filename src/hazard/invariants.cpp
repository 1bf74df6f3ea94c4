// The engine's internal invariants, checked by the tests after each step.
#include "hazard/engine.hpp"
#include "hazard/sensor_model.hpp"

namespace hazard {

std::vector<std::string> Engine::invariant_violations() const {
  std::vector<std::string> bad;
  auto check = [&](bool ok, const std::string& what) {
    if (!ok) bad.push_back(what);
  };
  check(by_name_.size() == vehicles_.size(), "name index size");
  for (std::size_t i = 1; i < by_name_.size(); ++i) {
    check(vehicles_[by_name_[i - 1]].name < vehicles_[by_name_[i]].name, "name order");
  }
  for (const VehicleState& v : vehicles_) {
    const std::string who = v.name + ": ";
    check(v.heading_history.has_value() == effects_.turn_blackout, who + "heading history");
    check(v.track.empty() || track_mode(), who + "a track without sweeping or sub-stepping");
    check(v.track.size() <= kMaxTrackPoses, who + "track longer than its bound");
    for (std::size_t i = 0; i < v.inside.size(); ++i) {
      check(v.inside[i] < field_.size(), who + "inside id out of range");
      check(i == 0 || v.inside[i - 1] < v.inside[i], who + "inside list not sorted");
      check(v.objects.count(v.inside[i]) == 1, who + "inside object without a pass");
    }
    std::size_t credits_held = 0;
    for (const auto& [id, record] : v.objects) {
      const std::vector<Credit> list = v.credits.to_vector(record.credits);
      credits_held += list.size();
      check(id < field_.size(), who + "record of an object out of range");
      check(record.passes >= 1, who + "object record without a pass");
      check(list.size() == record.credits.size, who + "credit list length");
      for (std::size_t i = 0; i < list.size(); ++i) {
        check(list[i].pass <= record.passes, who + "credit beyond passes");
        check(i == 0 || list[i - 1].pass < list[i].pass, who + "credits not in pass order");
      }
    }
    // Every slot of the pool holds a credit of some list or is free: none is lost.
    check(credits_held + v.credits.free_slots() == v.credits.slots(), who + "credit pool slots");
    if (v.setting) {
      const SensorSetting& s = *v.setting;
      // Every setting comes from a configuration or sensor request, which starts the hold.
      check(v.last_width_claim_s.has_value(), who + "a setting without a width claim");
      check(s.option < config_.options.size(), who + "option index");
      if (s.option < config_.options.size()) {
        check(s.width_m == config_.options.option(s.option).width_m, who + "width of option");
      }
      check(s.pd >= 0.0 && s.pd <= 1.0, who + "pd range");
      check(s.pfa == roc_false_alarm_probability(s.pd, s.exp), who + "pfa = pd^exp");
    }
  }
  return bad;
}

}  // namespace hazard
