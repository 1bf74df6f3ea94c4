#include "mission/messages/hazardset_eval.hpp"

#include <cmath>

#include "base/text.hpp"

namespace mission {

using Result = hazard::Parsed<HazardsetEval>;

namespace {

std::string object_part(const ObjectEval& o) {
  std::string out = "label=" + o.label + ",truth=" + o.truth;
  out += o.reported ? ",report=hazard" : ",report=nothing";
  if (o.penalty) out += ",penalty=" + base::fmt(*o.penalty, 2);
  return out;
}

std::string bad(std::string_view key, std::string_view value, const char* what) {
  return "HAZARDSET_EVAL field '" + std::string(key) + "' value '" + std::string(value) + "' " +
         what;
}

// Parses `{label=..,truth=..,report=..[,penalty=..]#...}`.
std::string parse_object_report(std::string_view text, std::vector<ObjectEval>& out) {
  text = base::trim(text);
  if (text.size() < 2 || text.front() != '{' || text.back() != '}')
    return bad("object_report", text, "is not enclosed in {}");
  for (std::string_view part : base::split_trimmed(text.substr(1, text.size() - 2), '#')) {
    if (part.empty()) continue;
    ObjectEval o;
    for (const base::KeyValue& kv : base::split_key_values(part)) {
      const std::string key = base::to_lower(kv.key);
      if (key == "label") o.label = std::string(kv.value);
      if (key == "truth") o.truth = std::string(kv.value);
      if (key == "report") o.reported = kv.value == "hazard";
      if (key == "penalty") {
        o.penalty = base::parse_number(kv.value);
        if (!o.penalty) return bad("penalty", kv.value, "is not a number");
      }
    }
    out.push_back(std::move(o));
  }
  return {};
}

}  // namespace

Result parse_hazardset_eval(std::string_view text) {
  HazardsetEval e;
  struct NumberSlot {
    const char* key;
    double* value;
  };
  struct CountSlot {
    const char* key;
    long* value;
  };
  const NumberSlot numbers[] = {{"total_score", &e.total_score},
                                {"norm_score", &e.norm_score},
                                {"score_missed_hazards", &e.score_missed_hazards},
                                {"score_false_alarms", &e.score_false_alarms},
                                {"score_time_overage", &e.score_time_overage},
                                {"total_time", &e.total_time_s},
                                {"received_time", &e.received_time_s},
                                {"start_time", &e.start_time_s},
                                {"penalty_false_alarm", &e.penalty_false_alarm},
                                {"penalty_missed_hazard", &e.penalty_missed_hazard},
                                {"penalty_max_time_over", &e.penalty_max_time_over},
                                {"penalty_max_time_rate", &e.penalty_max_time_rate},
                                {"max_time", &e.max_time_s}};
  const CountSlot counts[] = {{"total_objects", &e.total_objects},
                              {"missed_hazards", &e.missed_hazards},
                              {"correct_hazards", &e.correct_hazards},
                              {"false_alarms", &e.false_alarms}};
  bool has_vname = false;
  for (const base::KeyValue& kv : base::split_key_values(text, ',', /*respect_braces=*/true)) {
    const std::string key = base::to_lower(kv.key);
    if (key == "vname") {
      e.vname = std::string(kv.value);
      has_vname = true;
    } else if (key == "report_name") {
      e.report_name = std::string(kv.value);
    } else if (key == "object_report") {
      if (std::string error = parse_object_report(kv.value, e.object_report); !error.empty())
        return Result::fail(error);
    }
    for (const NumberSlot& slot : numbers) {
      if (key != slot.key) continue;
      const auto v = base::parse_number(kv.value);
      if (!v) return Result::fail(bad(key, kv.value, "is not a number"));
      *slot.value = *v;
    }
    for (const CountSlot& slot : counts) {
      if (key != slot.key) continue;
      const auto v = base::parse_unsigned(kv.value);
      if (!v || *v > 1000000000000ULL) return Result::fail(bad(key, kv.value, "is not a count"));
      *slot.value = static_cast<long>(*v);
    }
  }
  if (!has_vname) return Result::fail("HAZARDSET_EVAL has no 'vname' field");
  return Result::ok(std::move(e));
}

std::string format_hazardset_eval(const HazardsetEval& e) {
  std::string out = "vname=" + e.vname;
  if (!e.report_name.empty()) out += ",report_name=" + e.report_name;
  out += ",total_score=" + base::fmt(e.total_score, 2);
  out += ",norm_score=" + base::fmt(e.norm_score, 2);
  out += ",score_missed_hazards=" + base::fmt(e.score_missed_hazards);
  out += ",score_false_alarms=" + base::fmt(e.score_false_alarms);
  out += ",score_time_overage=" + base::fmt(e.score_time_overage, 2);
  out += ",total_objects=" + std::to_string(e.total_objects);
  out += ",total_time=" + base::fmt(e.total_time_s);
  out += ",received_time=" + base::fmt(e.received_time_s);
  out += ",start_time=" + base::fmt(e.start_time_s);
  out += ",missed_hazards=" + std::to_string(e.missed_hazards);
  out += ",correct_hazards=" + std::to_string(e.correct_hazards);
  out += ",false_alarms=" + std::to_string(e.false_alarms);
  out += ",penalty_false_alarm=" + base::fmt(e.penalty_false_alarm);
  out += ",penalty_missed_hazard=" + base::fmt(e.penalty_missed_hazard);
  out += ",penalty_max_time_over=" + base::fmt(e.penalty_max_time_over);
  out += ",penalty_max_time_rate=" + base::fmt(e.penalty_max_time_rate);
  out += ",max_time=" + base::fmt(e.max_time_s);
  return out;
}

std::string format_hazardset_eval_full(const HazardsetEval& e) {
  std::string objects;
  for (const ObjectEval& o : e.object_report)
    objects += (objects.empty() ? "" : "#") + object_part(o);
  return format_hazardset_eval(e) + ",object_report={" + objects + "}";
}

}  // namespace mission
