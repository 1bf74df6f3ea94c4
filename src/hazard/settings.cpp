// Settings (manual 4; differences.md "Settings", "Width choice"; D3, D4, D11, D20): the width
// choice under `max`, who holds a width, configuration requests, the default setting and the
// options summary.
#include <string>

#include "hazard/engine.hpp"
#include "hazard/messages/config_ack.hpp"
#include "hazard/messages/options_summary.hpp"
#include "hazard/sensor_model.hpp"
#include "hazard/time_rules.hpp"

namespace hazard {

// A vehicle holds its width from its accepted configuration request (or its default setting)
// until kWidthHoldWindow_s pass with no configuration or sensor request from it
// (docs/differences.md D20): holding does not wait for a sensor request.
bool Engine::holds_width(const VehicleState& v, double now_s) const {
  return v.setting && v.last_width_claim_s &&
         !elapsed_at_least(now_s, *v.last_width_claim_s, kWidthHoldWindow_s);
}

bool Engine::option_full(OptionIndex option, VehicleId asking, double now_s) const {
  const int max = config_.options.option(option).max_vehicles;
  if (max == 0) return false;
  int holders = 0;
  for (VehicleId id = 0; id < vehicles_.size(); ++id) {
    const VehicleState& other = vehicles_[id];
    if (id != asking && holds_width(other, now_s) && other.setting->option == option) {
      ++holders;
    }
  }
  return holders >= max;
}

std::optional<OptionIndex> Engine::choose_option(double width_m, VehicleId asking,
                                                 double now_s) const {
  return config_.options.choose(
      width_m, [&](OptionIndex i) { return option_full(i, asking, now_s); });
}

void Engine::set_option(VehicleState& v, OptionIndex option, double pd) {
  const SensorOption& o = config_.options.option(option);
  v.setting = SensorSetting{option, o.width_m, o.exp, o.pclass, pd,
                            roc_false_alarm_probability(pd, o.exp)};
}

void Engine::post_ack(const VehicleState& v, Outputs& out) const {
  const SensorSetting& s = *v.setting;
  const std::string ack = format_config_ack(ConfigAck{v.name, s.width_m, s.pd, s.pfa, s.pclass});
  out.post("UHZ_CONFIG_ACK", ack);
  out.post("UHZ_CONFIG_ACK" + v.variable_suffix, ack);
}

OptionIndex Engine::option_or_smallest(std::optional<OptionIndex> choice, const VehicleState& v,
                                       Outputs& out) const {
  if (!choice) {
    out.run_warnings.push_back("Every sensor option is full; " + v.name +
                               " gets the smallest width");
  }
  return choice.value_or(0);
}

// A successful width setting counts in the report; only a requested one opens the
// min_reset_interval window (D4, D11).
void Engine::record_width_setting(VehicleState& v, double now_s, bool opens_window) {
  ++v.counters.width_resets;
  v.counters.last_width_reset_s = now_s;
  if (opens_window) v.width_window_start_s = now_s;
}

// D4: the default width through the width choice (so `max` applies; differences.md "Width choice"),
// with `pd`. Counts as a width setting but opens no min_reset_interval window.
void Engine::set_default_width(VehicleId id, double pd, double now_s, Outputs& out) {
  VehicleState& v = vehicles_[id];
  const auto choice = choose_option(config_.options.default_width_m(), id, now_s);
  set_option(v, option_or_smallest(choice, v, out), pd);
  ++v.counters.width_attempts;
  record_width_setting(v, now_s, /*opens_window=*/false);
}

// A sensing vehicle without a setting gets the default one, announced like a request's (D4).
void Engine::apply_default_setting(VehicleId id, double now_s, Outputs& out) {
  set_default_width(id, kDefaultPd, now_s, out);
  const VehicleState& v = vehicles_[id];
  out.events.push_back("Setting default sensor settings for: " + v.name);
  post_ack(v, out);
}

// Exactly one ack per accepted request, with the settings in force after it (differences.md
// "Settings").
void Engine::handle_config_request(const ConfigRequest& r, double now_s, Outputs& out) {
  if (config_.options.empty()) {
    out.run_warnings.push_back("UHZ_CONFIG_REQUEST from " + r.vname +
                               ": no sensor_config options exist; ignored");
    return;
  }
  const auto found = vehicle_id(r.vname, now_s, out);
  if (!found) return;  // the vehicle table is full (warned, counted)
  const VehicleId id = *found;
  VehicleState& v = vehicles_[id];
  v.last_width_claim_s = now_s;  // accepted: the width it ends with is held from now
  const char* what =
      r.width_m ? "Setting sensor settings for: " : "Setting sensor PD settings for: ";
  out.events.push_back(what + v.name);
  auto set_pd = [&](double pd) {
    v.setting->pd = pd;
    v.setting->pfa = roc_false_alarm_probability(pd, v.setting->exp);
    ++v.counters.pd_resets;
    v.counters.last_pd_reset_s = now_s;
  };

  if (!r.width_m) {
    if (!v.setting) {
      // pd-only without a setting: the default width with the requested pd, in one ack.
      set_default_width(id, *r.pd, now_s, out);
    }
    set_pd(*r.pd);  // pd-only updates are never rate-limited (D11)
    return post_ack(v, out);
  }

  ++v.counters.width_attempts;
  const auto choice = choose_option(*r.width_m, id, now_s);
  if (!v.setting) {
    set_option(v, option_or_smallest(choice, v, out), r.pd.value_or(kDefaultPd));
  } else if (!choice) {
    out.run_warnings.push_back("Every sensor option is full; " + v.name +
                               " keeps its current setting");
    set_pd(r.pd.value_or(v.setting->pd));
    return post_ack(v, out);
  } else if (*choice == v.setting->option) {
    set_pd(r.pd.value_or(v.setting->pd));  // "Unchanged width": a pd-only update
    return post_ack(v, out);
  } else if (v.width_window_start_s &&
             !elapsed_at_least(now_s, *v.width_window_start_s, config_.min_reset_interval_s)) {
    out.events.push_back("Sensor reset denied (too soon) for vehicle: " + v.name);
    set_pd(r.pd.value_or(v.setting->pd));  // D11: the width stays, the pd applies
    return post_ack(v, out);
  } else {
    set_option(v, *choice, r.pd.value_or(v.setting->pd));
  }
  record_width_setting(v, now_s, /*opens_window=*/true);
  post_ack(v, out);
}


void Engine::post_options_summary_if_due(double now_s, Outputs& out) {
  if (last_summary_s_ &&
      !elapsed_at_least(now_s, *last_summary_s_, config_.options_summary_interval_s)) {
    return;
  }
  last_summary_s_ = now_s;
  out.post("UHZ_OPTIONS_SUMMARY", options_summary_text_);
}

}  // namespace hazard
