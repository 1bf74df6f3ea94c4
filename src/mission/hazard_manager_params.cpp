// The hazard manager's parameters: one table of names, defaults, help and checks that the
// parser (apply_manager_param), the validation (validate) and --example (manager_parameters)
// read. Contract: include/mission/hazard_manager.hpp.

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "base/text.hpp"
#include "mission/hazard_manager.hpp"

namespace mission {

namespace {

using Checked = base::Result<void>;

/// Fine when `ok`, else the parameter's value and the rule it breaks.
Checked holds(bool ok, std::string_view name, double value, const char* rule) {
  if (ok) return Checked::ok();
  return Checked::fail("parameter " + std::string(name) + "=" + base::fmt(value, 6) + " " + rule);
}
Checked check_positive(std::string_view name, double v) {
  return holds(v > 0.0, name, v, "must be > 0");
}
Checked check_non_negative(std::string_view name, double v) {
  return holds(v >= 0.0, name, v, "must be >= 0");
}
Checked check_probability(std::string_view name, double v) {
  return holds(v >= 0.0 && v <= 1.0, name, v, "must be in [0, 1]");
}
Checked check_open_probability(std::string_view name, double v) {
  return holds(v > 0.0 && v < 1.0, name, v, "must be in (0, 1)");
}
Checked check_fraction(std::string_view name, double v) {
  return holds(v > 0.0 && v <= 1.0, name, v, "must be in (0, 1]");
}

using NumberCheck = Checked (*)(std::string_view, double);

struct ParamRow {
  ParamInfo info;
  std::function<Checked(ManagerConfig&, std::string_view)> apply;
  /// The row's rule applied to a configuration built in code (fine when there is none).
  std::function<Checked(const ManagerConfig&)> check = [](const ManagerConfig&) {
    return Checked::ok();
  };
};

ParamRow number_row(ParamInfo info, double ManagerConfig::*field, NumberCheck check) {
  return {info, [info, field, check](ManagerConfig& c, std::string_view value) {
            const auto v = base::parse_number(value);
            if (!v) {
              return Checked::fail("parameter " + std::string(info.name) + "='" +
                                   std::string(value) + "' is not a number");
            }
            if (Checked checked = check(info.name, *v); !checked) return checked;
            c.*field = *v;
            return Checked::ok();
          },
          [info, field, check](const ManagerConfig& c) { return check(info.name, c.*field); }};
}

ParamRow bool_row(ParamInfo info, bool ManagerConfig::*field) {
  return {info, [info, field](ManagerConfig& c, std::string_view value) {
            const auto v = base::parse_bool(value);
            if (!v) {
              return Checked::fail("parameter " + std::string(info.name) + "='" +
                                   std::string(value) + "' is not true or false");
            }
            c.*field = *v;
            return Checked::ok();
          }};
}

const std::vector<ParamRow>& param_rows() {
  static const std::vector<ParamRow> rows = {
      number_row({"swath_width", "25", "requested swath width W, m to each side (> 0)"},
                 &ManagerConfig::swath_width_m, check_positive),
      number_row({"sensor_pd", "0.9", "requested probability of detection, [0, 1] (alias: pd)"},
                 &ManagerConfig::pd, check_probability),
      number_row({"prior_hazard", "0.5", "prior P(hazard) of a newly detected object, (0, 1)"},
                 &ManagerConfig::prior_hazard, check_open_probability),
      {{"report_name", "", "name= part of HAZARDSET_REPORT (quotes stripped)"},
       [](ManagerConfig& c, std::string_view value) {
         std::string v(base::trim(value));
         v.erase(std::remove(v.begin(), v.end(), '"'), v.end());
         c.report_name = v;
         return Checked::ok();
       }},
      {{"region", "", "search region (convex polygon) for the transit lane; else the grader's"},
       [](ManagerConfig& c, std::string_view value) {
         auto parsed = ConvexPolygon::parse(value);
         if (!parsed) return Checked::fail("parameter region: " + parsed.error);
         c.region = std::move(parsed.value);
         return Checked::ok();
       }},
      bool_row({"report_xpath", "false", "add the xpath= part to HAZARDSET_REPORT"},
               &ManagerConfig::report_xpath),
      bool_row({"classify", "true", "request a classification of every detection"},
               &ManagerConfig::classify),
      {{"classify_lookahead", "2", "answers valued together for a request's priority, 1..20"},
       [](ManagerConfig& c, std::string_view value) {
         const auto v = base::parse_unsigned(value);
         if (!v || *v < 1 || *v > static_cast<std::uint64_t>(kMaxLookaheadAnswers)) {
           return Checked::fail("parameter classify_lookahead='" + std::string(value) +
                                "' is not a whole number in [1, 20]");
         }
         c.classify_lookahead = static_cast<int>(*v);
         return Checked::ok();
       },
       [](const ManagerConfig& c) {
         if (c.classify_lookahead >= 1 && c.classify_lookahead <= kMaxLookaheadAnswers)
           return Checked::ok();
         return Checked::fail("parameter classify_lookahead=" +
                              std::to_string(c.classify_lookahead) + " must be in [1, 20]");
       }},
      bool_row({"count_missed_passes", "true", "use passes without a detection as evidence"},
               &ManagerConfig::count_missed_passes),
      number_row({"sensor_swath_length", "5", "the sensor's swath_length, m in total (> 0)"},
                 &ManagerConfig::sensor_swath_length_m, check_positive),
      number_row({"sensor_max_turn_rate", "1.5", "the sensor's max_turn_rate, deg/s (> 0)"},
                 &ManagerConfig::sensor_max_turn_rate_dps, check_positive),
      number_row({"sensor_max_speed", "2.0", "the sensor's max_vehicle_speed, m/s (> 0)"},
                 &ManagerConfig::sensor_max_speed_mps, check_positive),
      number_row({"pass_margin", "0.1", "a missed pass must come within W - margin, m (>= 0)"},
                 &ManagerConfig::pass_margin_m, check_non_negative),
      number_row({"clear_turn_fraction", "0.5", "a missed pass needs turn rate <= this x limit"},
                 &ManagerConfig::clear_turn_fraction, check_fraction),
      number_row({"detection_latency", "10", "how late a detection may come after a pass, s"},
                 &ManagerConfig::detection_latency_s, check_non_negative),
      number_row({"track_sample_spacing", "1", "own-track memory resolution, m (> 0)"},
                 &ManagerConfig::track_sample_spacing_m, check_positive),
      number_row({"sensor_request_interval", "5", "seconds between UHZ_SENSOR_REQUEST postings"},
                 &ManagerConfig::sensor_request_interval_s, check_positive),
      number_row({"config_retry_interval", "30", "seconds between UHZ_CONFIG_REQUEST until acked"},
                 &ManagerConfig::config_retry_interval_s, check_positive),
  };
  return rows;
}

}  // namespace

const std::vector<ParamInfo>& manager_parameters() {
  static const std::vector<ParamInfo> infos = param_infos(param_rows());
  return infos;
}

Checked apply_manager_param(ManagerConfig& config, std::string_view key,
                            std::string_view value) {
  std::string name = base::to_lower(base::trim(key));
  if (name == "pd") name = "sensor_pd";  // as uFldHazardMgr: both names are accepted
  for (const ParamRow& row : param_rows())
    if (name == row.info.name) return row.apply(config, value);
  return Checked::fail("unknown parameter '" + std::string(base::trim(key)) + "'");
}

Checked validate(const ManagerConfig& c) {
  if (c.vname.empty()) return Checked::fail("the vehicle name is empty");
  for (const ParamRow& row : param_rows())
    if (Checked checked = row.check(c); !checked) return checked;
  return Checked::ok();
}

}  // namespace mission
