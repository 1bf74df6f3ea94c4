// Detection (manual 3.1, 6.1, 7.1; D5): one sensor event, one die, one report.
#include <string>

#include "hazard/engine.hpp"
#include "hazard/messages/detection_report.hpp"
#include "hazard/sensor_model.hpp"
#include "base/text.hpp"
#include "visuals.hpp"

namespace hazard {

double Engine::degradation(const HazardObject& o, double heading_deg) const {
  return aspect_degradation(aspect_difference_deg(heading_deg, *o.aspect_deg), *o.aspect_min_deg,
                            *o.aspect_max_deg);
}

void Engine::roll_detection(VehicleState& v, ObjectId id, double heading_deg, double now_s,
                            Outputs& out) {
  const HazardObject& o = field_.object(id);
  const SensorSetting& s = *v.setting;
  ObjectRecord& record = v.objects[id];
  const std::uint32_t pass = ++record.passes;
  ++(o.is_hazard() ? v.counters.hazard_chances : v.counters.benign_chances);

  // Thresholds (manual 3.1, 6.1, 7.1; D5): hazards detect with pd; benign objects with pfa,
  // degraded by aspect (pfa' = pd^exp'), then combined with resemblance.
  double plain_p = s.pd, degraded_p = s.pd;
  if (!o.is_hazard()) {
    plain_p = degraded_p = s.pfa;
    if (effects_.aspect && o.has_aspect_triple()) {
      degraded_p = roc_false_alarm_probability(
          s.pd, degraded_exponent(s.exp, degradation(o, heading_deg)));
    }
    if (effects_.resemblance && o.resemblance) {
      plain_p = resemblance_false_alarm_probability(plain_p, *o.resemblance);
      degraded_p = resemblance_false_alarm_probability(degraded_p, *o.resemblance);
    }
  }
  const double u = dice_.detection_u(v.name_hash, field_.label_hash(id), pass);
  const bool detected = detection_succeeds(u, degraded_p);
  notify(v, id, pass, DiePurpose::kDetection, detected);
  if (!detected) return;

  ++v.counters.detections;
  ++(o.is_hazard() ? v.counters.hazard_reports : v.counters.benign_reports);
  grant_credit(v, id, record, Credit{pass, heading_deg}, out);
  DetectionReport report{v.name, o.x_m, o.y_m, o.label,
                         o.aspect_deg, o.aspect_min_deg, o.aspect_max_deg};
  out.post("UHZ_DETECTION_REPORT", format_detection_report(report));
  report.vname.reset();
  out.post("UHZ_DETECTION_REPORT" + v.variable_suffix, format_detection_report(report));
  out.events.push_back(
      base::joined({"Detection report sent to vehicle: ", v.name, " (label ", o.label, ")"}));
  if (!effects_.detection_visuals) return;
  const ViewCircle c = detection_circle(o, now_s, config_.show_detections.duration_s,
                                        !detection_succeeds(u, plain_p));
  out.post("VIEW_CIRCLE", format_view_circle(c));
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
