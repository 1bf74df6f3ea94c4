// Classification (D7, D8, D10, D37): requests against detection credits, the queue, and the
// rate-limited release of answers.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hazard/engine.hpp"
#include "hazard/messages/detection_report.hpp"
#include "hazard/messages/hazard_report.hpp"
#include "hazard/sensor_model.hpp"
#include "base/text.hpp"
#include "hazard/time_rules.hpp"
#include "report_aspect.hpp"
#include "visuals.hpp"

namespace hazard {

namespace {

ObjectType flipped(ObjectType t) {
  return t == ObjectType::kHazard ? ObjectType::kBenign : ObjectType::kHazard;
}

std::optional<double> latest(std::optional<double> a, std::optional<double> b) {
  if (!a) return b;
  if (!b) return a;
  return std::max(*a, *b);
}

// The oldest unused credit of the pair (D7), removed; nullopt when it holds none.
std::optional<Credit> take_oldest_credit(VehicleState& v, ObjectId object) {
  const auto record = v.objects.find(object);
  if (record == v.objects.end() || record->second.credits.empty()) return std::nullopt;
  return v.credits.pop_front(record->second.credits);
}

// "Classify request queued for NAME: label L, pass N, pc FIX(pc, 5), die FIX(die, 4)", in
// one string (a request follows every detection).
std::string queued_event(std::string_view vname, std::string_view label, std::uint32_t pass,
                         double pc, double die) {
  std::string text;
  text.reserve(96 + vname.size() + label.size());
  text += "Classify request queued for ";
  text += vname;
  text += ": label ";
  text += label;
  text += ", pass ";
  text += std::to_string(pass);
  text += ", pc ";
  base::append_fix(text, pc, 5);
  text += ", die ";
  base::append_fix(text, die, 4);
  return text;
}

}  // namespace

void Engine::handle_classify_request(const ClassifyRequest& r, double now_s, Outputs& out) {
  if (r.action == ClassifyAction::kClear) return clear_queue(r.vname, now_s, out);
  const auto id = find_vehicle(r.vname);
  if (!id) {
    out.run_warnings.push_back("Classify request from unknown vehicle " + r.vname +
                               " (label " + base::log_excerpt(r.label) + "); refused");
    return;
  }
  VehicleState& v = vehicles_[*id];
  v.last_mail_s = now_s;
  ++v.counters.classify_requests;
  if (v.queue.size() >= kMaxClassifyQueue) return refuse_queue_full(v, r.label, out);
  const std::uint64_t label_hash = hash_name(r.label);
  const auto object = find_object(r.label, label_hash);
  if (!object) {
    out.run_warnings.push_back(v.name + " classify request for unknown label: " +
                               base::log_excerpt(r.label));
    return;
  }
  if (!v.setting) {
    out.run_warnings.push_back("No sensor setting (no classifier) for " + v.name +
                               "; classify request for " + base::log_excerpt(r.label) + " refused");
    return;
  }
  const std::optional<Credit> taken = take_oldest_credit(v, *object);
  if (!taken) {
    out.run_warnings.push_back("No detection credit for " + v.name + " and label " +
                               base::log_excerpt(r.label) +
                               " (one classification per detection); refused");
    return;
  }
  const Credit credit = *taken;

  // Decided now, with the settings in force now (differences.md "Credits"). The field is read
  // through its accessors, each table only when needed (roll_detection says why).
  const ObjectType type = field_.type(*object);
  const HazardField::Aspect* aspect = field_.aspect(*object);
  const double pc = v.setting->pclass;
  const std::optional<double> resemblance =
      (effects_.resemblance && type != ObjectType::kHazard) ? field_.resemblance(*object)
                                                            : std::nullopt;
  const double pc_resemblance =
      resemblance ? resemblance_classification_probability(pc, *resemblance) : pc;
  const double pc_aspect =
      (effects_.aspect && aspect && aspect->triple())
          ? aspect_classification_probability(pc_resemblance,
                                              degradation(*aspect, credit.heading_deg))
          : pc_resemblance;
  const std::string_view label = field_.label(*object);
  const double die = dice_.classification_v(v.name_hash, label_hash, credit.pass);
  const bool correct = classification_correct(die, pc_aspect);
  notify(v, *object, credit.pass, DiePurpose::kClassification, correct);
  PendingAnswer answer;
  answer.object = *object;
  answer.reported = correct ? type : flipped(type);
  answer.aspect_affected = !correct && classification_correct(die, pc_resemblance);
  answer.credit = credit;
  const bool top = r.action == ClassifyAction::kTop;
  v.queue.push(answer, r.priority.value_or(kDefaultClassifyPriority), top);
  if (top) v.last_top_s = now_s;
  out.events.push_back(queued_event(v.name, label, credit.pass, pc_aspect, die));
}

std::optional<ObjectId> Engine::find_object(std::string_view label, std::uint64_t hash) const {
  const ObjectId recent = recent_objects_[mix64(hash) & (kRecentObjectSlots - 1)];
  if (recent < field_.size() && field_.label(recent) == label) return recent;
  return field_.find(label);
}

void Engine::remember_object(ObjectId id, std::uint64_t hash) {
  recent_objects_[mix64(hash) & (kRecentObjectSlots - 1)] = id;
}

// The queue is bounded (kMaxClassifyQueue): the request is refused before its credit is used.
void Engine::refuse_queue_full(VehicleState& v, std::string_view label, Outputs& out) {
  ++drops_.classify_requests;
  if (!v.warned_queue_full) {
    out.run_warnings.push_back("Classify queue of " + v.name + " full (kMaxClassifyQueue = " +
                               std::to_string(kMaxClassifyQueue) + " requests): request for " +
                               base::log_excerpt(label) +
                               " refused, its credit kept (further refusals only counted)");
  }
  v.warned_queue_full = true;
}

void Engine::handle_sensor_clear(const SensorClear& r, double now_s, Outputs& out) {
  clear_queue(r.vname, now_s, out);
}

void Engine::clear_queue(std::string_view vname, double now_s, Outputs& out) {
  const auto id = find_vehicle(vname);
  if (!id) return;
  VehicleState& v = vehicles_[*id];
  v.last_mail_s = now_s;
  v.warned_queue_full = false;
  const std::vector<PendingAnswer> cleared = v.queue.clear();
  for (const PendingAnswer& a : cleared) {
    // The credit goes back in pass order, so the same die is rolled again (differences.md "Clear").
    v.credits.insert_in_pass_order(v.objects[a.object].credits, a.credit);
  }
  out.events.push_back("Classify queue cleared for " + v.name + " (" +
                       std::to_string(cleared.size()) + " entries)");
}

void Engine::release_classifications(double now_s, Outputs& out) {
  for (VehicleId id : by_name_) {
    VehicleState& v = vehicles_[id];
    if (v.queue.empty()) continue;
    const auto last = latest(v.last_release_s, v.last_top_s);
    if (last && !elapsed_at_least(now_s, *last, config_.min_classify_interval_s)) continue;
    const PendingAnswer answer = *v.queue.pop();
    if (v.queue.size() < kMaxClassifyQueue) v.warned_queue_full = false;
    v.last_release_s = now_s;
    ++v.counters.answers;
    const glm::dvec2 position = field_.position(answer.object);
    const std::string_view label = field_.label(answer.object);
    post_hazard_report(v, position, label, answer.reported, field_.aspect(answer.object), out);
    out.events.push_back(
        base::joined({"Hazard report sent to vehicle: ", v.name, " (label ", label, ")"}));
    if (!effects_.detection_visuals) continue;
    const ViewCircle c =
        classification_circle(position, now_s, answer.reported, answer.aspect_affected);
    out.post("VIEW_CIRCLE", format_view_circle(c));
  }
}

// UHZ_HAZARD_REPORT_<V>, then UHZ_HAZARD_REPORT: one text, the general variant with
// "vname=NAME," in front (as in post_detection_report).
void Engine::post_hazard_report(const VehicleState& v, glm::dvec2 position,
                                std::string_view label, ObjectType reported,
                                const HazardField::Aspect* aspect, Outputs& out) {
  HazardReport report{std::nullopt, position.x, position.y, std::string(label), reported,
                      std::nullopt, std::nullopt, std::nullopt};
  set_aspect(report, aspect);
  std::string for_vehicle = format_hazard_report(report);
  std::string general = with_vname(v.name, for_vehicle);
  out.post("UHZ_HAZARD_REPORT" + v.variable_suffix, std::move(for_vehicle));
  out.post("UHZ_HAZARD_REPORT", std::move(general));
}

}  // namespace hazard
