#include "hazard/driver.hpp"

#include <algorithm>
#include <string>

#include "base/same_text.hpp"
#include "base/text.hpp"

namespace hazard {

namespace {

// The engine's subscriptions (Engine::subscriptions() lists them with examples).
constexpr std::string_view kNodeReport = "NODE_REPORT";
constexpr std::string_view kSensorRequest = "UHZ_SENSOR_REQUEST";
constexpr std::string_view kConfigRequest = "UHZ_CONFIG_REQUEST";
constexpr std::string_view kClassifyRequest = "UHZ_CLASSIFY_REQUEST";
constexpr std::string_view kSensorClear = "UHZ_SENSOR_CLEAR";
constexpr std::string_view kPmvConnect = "PMV_CONNECT";

bool subscribed(std::string_view variable) {
  const auto& subs = Engine::subscriptions();
  return std::any_of(subs.begin(), subs.end(),
                     [&](const InterfaceVariable& s) { return s.name == variable; });
}

}  // namespace

Driver::Driver(EngineSetup setup, SeedChoice seed) : engine_(std::move(setup), seed) {}

Driver::Driver(Engine engine) : engine_(std::move(engine)) {}

double Driver::advance_to(double now_s) {
  const double t = last_time_s_ ? std::max(*last_time_s_, now_s) : now_s;
  last_time_s_ = t;
  return t;
}

TimedOutputs Driver::start(double now_s) {
  const double t = advance_to(now_s);
  return {engine_.start(t), t};
}

TimedOutputs Driver::deliver(const Mail& mail, double now_s) {
  TimedOutputs out;
  out.time_s = deliver(mail, now_s, out.outputs);
  return out;
}

double Driver::deliver(const Mail& mail, double now_s, Outputs& out) {
  const double t = advance_to(std::min(mail.time_s, now_s));
  dispatch(mail.variable, mail.value, t, out);
  return t;
}

TimedOutputs Driver::step(double now_s) {
  const double t = advance_to(now_s);
  return {engine_.step(t), t};
}

TimedOutputs Driver::restart_field_visuals(double now_s) {
  const double t = advance_to(now_s);
  TimedOutputs out{{}, t};
  engine_.restart_field_visuals(out.outputs);
  return out;
}

void Driver::dispatch(std::string_view variable, std::string_view value, double now_s,
                      Outputs& out) {
  // Node reports are nearly all the mail: known subscribed without the list's scan.
  const bool node_report = base::same_text(variable, kNodeReport);
  if (!node_report && !subscribed(variable)) return;
  if (value.size() > kMaxMailValueBytes) {
    out.run_warnings.push_back(std::string(variable) + ": value of " +
                               std::to_string(value.size()) + " bytes exceeds " +
                               std::to_string(kMaxMailValueBytes) + "; ignored: '" +
                               base::excerpt(value) + "'");
    return;
  }
  // Each message: its module's parser, then its handler; a parse failure is one warning.
  // (The parser and handler by reference: a closure passed by value went through memory.)
  auto route = [&](const auto& parse, const auto& handle) {
    const auto& parsed = parse(value);  // (a shared parse is handed out by reference)
    if (parsed) {
      handle(*parsed.value);
    } else {
      out.run_warnings.push_back(std::string(variable) + ": " + parsed.error + "; ignored: '" +
                                 base::excerpt(value) + "'");
    }
  };
  if (node_report) {
    const auto handle = [&](const NodeReport& r) { engine_.handle_node_report(r, now_s, out); };
    if (share_node_report_parses_) {
      route([&](std::string_view text) -> const Parsed<NodeReport>& {
              return NodeReportMemo::this_thread().parse(text, &engine_.placement());
            },
            handle);
    } else {  // the engine reads the name and the pose only
      route([&](std::string_view text) {
              return parse_node_report(text, &engine_.placement(), NodeReportKeep::kPose);
            },
            handle);
    }
  } else if (variable == kSensorRequest) {
    route(parse_sensor_request,
          [&](const SensorRequest& r) { engine_.handle_sensor_request(r, now_s, out); });
  } else if (variable == kConfigRequest) {
    route(parse_config_request,
          [&](const ConfigRequest& r) { engine_.handle_config_request(r, now_s, out); });
  } else if (variable == kClassifyRequest) {
    route(parse_classify_request,
          [&](const ClassifyRequest& r) { engine_.handle_classify_request(r, now_s, out); });
  } else if (variable == kSensorClear) {
    route(parse_sensor_clear,
          [&](const SensorClear& r) { engine_.handle_sensor_clear(r, now_s, out); });
  } else if (variable == kPmvConnect) {
    engine_.handle_viewer_connect(out);
  }
}

}  // namespace hazard
