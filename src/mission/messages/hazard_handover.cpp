#include "mission/messages/hazard_handover.hpp"

#include "base/text.hpp"

namespace mission {

using Result = hazard::Parsed<Handover>;

namespace {

/// A count above this is certainly corrupt (a mission has far fewer passes).
constexpr std::uint64_t kMaxCount = 1000000000;

/// The value of `key=value` when it is the part's first pair; "" otherwise (an empty part, as
/// in `source=a##prior=0.5`, has no pair at all).
std::string header_value(std::string_view part, std::string_view key) {
  const std::vector<base::KeyValue> pairs = base::split_key_values(part);
  if (pairs.empty()) return {};
  return base::to_lower(pairs.front().key) == key ? std::string(pairs.front().value)
                                                  : std::string();
}

// Parses one object part; returns the problem ("" when fine).
std::string parse_object(std::string_view part, HandoverObject& o) {
  bool has_label = false, has_x = false, has_y = false, has_evidence = false;
  for (const base::KeyValue& kv : base::split_key_values(part)) {
    const std::string key = base::to_lower(kv.key);
    auto number = [&](double& out) -> bool {
      const auto v = base::parse_number(kv.value);
      if (v) out = *v;
      return v.has_value();
    };
    auto count = [&](int& out) -> bool {
      const auto v = base::parse_unsigned(kv.value);
      if (v && *v <= kMaxCount) out = static_cast<int>(*v);
      return v && *v <= kMaxCount;
    };
    bool ok = true;
    if (key == "label") {
      o.label = std::string(kv.value);
      has_label = !o.label.empty();
    } else if (key == "x") {
      ok = has_x = number(o.x_m);
    } else if (key == "y") {
      ok = has_y = number(o.y_m);
    } else if (key == "evidence") {
      ok = has_evidence = number(o.evidence.log_lr);
    } else if (key == "det") {
      ok = count(o.evidence.detections);
    } else if (key == "miss") {
      ok = count(o.evidence.missed_passes);
    } else if (key == "said_hazard") {
      ok = count(o.evidence.said_hazard);
    } else if (key == "said_benign") {
      ok = count(o.evidence.said_benign);
    }
    if (!ok) return "field '" + key + "' value '" + std::string(kv.value) + "' is not valid";
  }
  if (!has_label) return "missing field 'label'";
  if (!has_x) return "missing field 'x'";
  if (!has_y) return "missing field 'y'";
  if (!has_evidence) return "missing field 'evidence'";
  return {};
}

}  // namespace

Result parse_handover(std::string_view text) {
  const auto parts = base::split_trimmed(base::trim(text), '#');
  if (parts.size() < 3) return Result::fail("HAZARD_HANDOVER needs source, dest and prior parts");
  Handover h;
  h.source = header_value(parts[0], "source");
  h.dest = header_value(parts[1], "dest");
  const std::string prior_text = header_value(parts[2], "prior");
  if (h.source.empty()) {
    return Result::fail("HAZARD_HANDOVER first part '" + std::string(parts[0]) +
                        "' is not source=<vehicle>");
  }
  if (h.dest.empty()) {
    return Result::fail("HAZARD_HANDOVER second part '" + std::string(parts[1]) +
                        "' is not dest=<vehicle>");
  }
  const auto prior = base::parse_number(prior_text);
  if (!prior || !(*prior > 0.0) || !(*prior < 1.0))
    return Result::fail("HAZARD_HANDOVER part '" + std::string(parts[2]) +
                        "' is not prior=<p> with p in (0, 1)");
  h.prior_hazard = *prior;
  for (std::size_t i = 3; i < parts.size(); ++i) {
    if (parts[i].empty()) continue;
    HandoverObject o;
    if (std::string problem = parse_object(parts[i], o); !problem.empty()) {
      h.warnings.push_back("HAZARD_HANDOVER object '" + base::excerpt(parts[i]) +
                           "': " + problem);
      continue;
    }
    h.objects.push_back(std::move(o));
  }
  return Result::ok(std::move(h));
}

std::string format_handover(const Handover& h) {
  std::string out =
      "source=" + h.source + "#dest=" + h.dest + "#prior=" + base::fmt(h.prior_hazard, 6);
  for (const HandoverObject& o : h.objects) {
    out += "#label=" + o.label;
    out += ",x=" + base::fmt(o.x_m, 2) + ",y=" + base::fmt(o.y_m, 2);
    out += ",evidence=" + base::fmt(o.evidence.log_lr, 6);
    out += ",det=" + std::to_string(o.evidence.detections);
    out += ",miss=" + std::to_string(o.evidence.missed_passes);
    out += ",said_hazard=" + std::to_string(o.evidence.said_hazard);
    out += ",said_benign=" + std::to_string(o.evidence.said_benign);
  }
  return out;
}

std::string handover_variable_for(std::string_view dest) {
  return std::string(kHazardHandoverVar) + "_" + base::to_upper(dest);
}

}  // namespace mission
