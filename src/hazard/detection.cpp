// Detection (manual 3.1, 6.1, 7.1; D5): one sensor event, one die, one report.
#include <string>

#include "hazard/engine.hpp"
#include "hazard/messages/detection_report.hpp"
#include "hazard/sensor_model.hpp"
#include "base/text.hpp"
#include "report_aspect.hpp"
#include "visuals.hpp"

namespace hazard {

double Engine::degradation(const HazardField::Aspect& a, double heading_deg) const {
  return aspect_degradation(aspect_difference_deg(heading_deg, *a.aspect_deg), *a.aspect_min_deg,
                            *a.aspect_max_deg);
}

// The field is read through its accessors, each table only when needed: in a dense field every
// read of an object's row is a cache miss, and most objects are rolled for and not reported.
void Engine::roll_detection(VehicleState& v, ObjectId id, double heading_deg, double now_s,
                            Outputs& out) {
  const bool hazard = field_.is_hazard(id);
  const HazardField::Aspect* aspect = field_.aspect(id);
  const SensorSetting& s = *v.setting;
  ObjectRecord& record = v.objects[id];
  const std::uint32_t pass = ++record.passes;
  ++(hazard ? v.counters.hazard_chances : v.counters.benign_chances);

  // Thresholds (manual 3.1, 6.1, 7.1; D5): hazards detect with pd; benign objects with pfa,
  // degraded by aspect (pfa' = pd^exp'), then combined with resemblance.
  double plain_p = s.pd, degraded_p = s.pd;
  if (!hazard) {
    plain_p = degraded_p = s.pfa;
    if (effects_.aspect && aspect && aspect->triple()) {
      degraded_p = roc_false_alarm_probability(
          s.pd, degraded_exponent(s.exp, degradation(*aspect, heading_deg)));
    }
    const std::optional<double> resemblance =
        effects_.resemblance ? field_.resemblance(id) : std::nullopt;
    if (resemblance) {
      plain_p = resemblance_false_alarm_probability(plain_p, *resemblance);
      degraded_p = resemblance_false_alarm_probability(degraded_p, *resemblance);
    }
  }
  const std::string_view label = field_.label(id);
  const std::uint64_t label_hash = hash_name(label);
  const double u = dice_.detection_u(v.name_hash, label_hash, pass);
  const bool detected = detection_succeeds(u, degraded_p);
  notify(v, id, pass, DiePurpose::kDetection, detected);
  if (!detected) return;

  ++v.counters.detections;
  remember_object(id, label_hash);  // its classify request follows
  ++(hazard ? v.counters.hazard_reports : v.counters.benign_reports);
  grant_credit(v, id, record, Credit{pass, heading_deg}, out);
  const glm::dvec2 position = field_.position(id);
  post_detection_report(v, position, label, aspect, out);
  out.events.push_back(
      base::joined({"Detection report sent to vehicle: ", v.name, " (label ", label, ")"}));
  if (!effects_.detection_visuals) return;
  const ViewCircle c = detection_circle(position, now_s, config_.show_detections.duration_s,
                                        !detection_succeeds(u, plain_p));
  out.post("VIEW_CIRCLE", format_view_circle(c));
}

// Both variants from one text: the general one is the vehicle's with "vname=NAME," in front
// (format_detection_report writes vname first), so the numbers are formatted once.
void Engine::post_detection_report(const VehicleState& v, glm::dvec2 position,
                                   std::string_view label, const HazardField::Aspect* aspect,
                                   Outputs& out) {
  DetectionReport report{std::nullopt, position.x, position.y, std::string(label),
                         std::nullopt, std::nullopt, std::nullopt};
  set_aspect(report, aspect);
  std::string for_vehicle = format_detection_report(report);
  out.post("UHZ_DETECTION_REPORT", with_vname(v.name, for_vehicle));
  out.post("UHZ_DETECTION_REPORT" + v.variable_suffix, std::move(for_vehicle));
}

// Credits are bounded per (vehicle, object) (kMaxCreditsPerObject): an object passed that often
// without a request is reported again but grants no further credit.
void Engine::grant_credit(VehicleState& v, ObjectId id, ObjectRecord& record,
                          const Credit& credit, Outputs& out) {
  if (record.credits.size < kMaxCreditsPerObject) {
    return v.credits.push_back(record.credits, credit);
  }
  ++drops_.credits;
  if (!v.warned_credits_full) {
    out.run_warnings.push_back(v.name + " holds " + std::to_string(kMaxCreditsPerObject) +
                               " unused credits for label " +
                               base::excerpt(field_.object(id).label) +
                               " (kMaxCreditsPerObject): further detections grant no credit "
                               "(only counted)");
  }
  v.warned_credits_full = true;
}

}  // namespace hazard
