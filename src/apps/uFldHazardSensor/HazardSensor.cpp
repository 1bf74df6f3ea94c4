#include "HazardSensor.hpp"

#include <ostream>
#include <string_view>
#include <utility>

#include "HazardSensor_Info.hpp"
#include "app_support.hpp"
#include "hazard/report.hpp"
#include "moos/alog.hpp"
#include "base/text.hpp"

namespace ufld_hazard_sensor {

namespace {

/// The engine reads text: strings and binary values as they are (a view, no copy), doubles in
/// their shortest exact form, kept in `formatted` (a NODE_REPORT posted as a double then fails
/// to parse, with a warning).
std::string_view mail_text(const moos::Message& m, std::string& formatted) {
  if (!m.is_double()) return m.sval;
  formatted = base::format_shortest(m.dval);
  return formatted;
}

}  // namespace

moos::AppTraits hazard_sensor_traits() {
  moos::AppTraits t;
  t.default_name = kAppName;
  t.default_app_tick_hz = hazard::EngineConfig().app_tick_hz;
  t.default_max_appcast_events = kDefaultMaxAppCastEvents;
  t.repeated_parameters = moos::RepeatedParameter::kLastWinsWithWarning;
  return t;
}

namespace {

moos::AppTraits traits_for(const HazardSensorOptions& options) {
  moos::AppTraits t = hazard_sensor_traits();
  t.post_iteration_timing = options.post_iteration_timing;
  return t;
}

}  // namespace

HazardSensor::HazardSensor(HazardSensorOptions options)
    : moos::MoosApp(traits_for(options)), options_(std::move(options)) {
  if (!options_.os_seed) options_.os_seed = app_support::operating_system_seed;
}

hazard::Engine HazardSensor::build_engine() const {
  if (options_.make_engine) return options_.make_engine(config_lines(), settings(), options_.readers);
  hazard::Engine engine = app_support::make_sensor_engine(
      config_lines(), settings().mission_directory, app_support::mission_origin(settings()),
      std::nullopt, options_.os_seed);
  if (options_.readers != hazard::PostingReaders::kViewers)
    engine = engine.with_seed(engine.seed(), options_.readers);
  return engine;
}

bool HazardSensor::on_start_up() {
  driver_.emplace(build_engine());
  driver_->share_node_report_parses(options_.share_node_report_parses);
  for (const hazard::InterfaceVariable& v : hazard::Engine::subscriptions()) {
    register_variable(std::string(v.name));
  }
  if (options_.verbose) *options_.verbose << moos::alog_header(app_name(), cycle_time());
  start_up_connection_ = comms().connection_count();
  publish(driver_->start(cycle_time()));
  return true;
}

void HazardSensor::on_connect_to_server() {
  if (!driver_ || comms().connection_count() == start_up_connection_) return;
  // A new database is, for the field's visuals, a viewer that has seen nothing: they go out
  // again, in the engine's bounded batches (driver.hpp).
  publish(driver_->restart_field_visuals(cycle_time()));
}

void HazardSensor::on_new_mail(const std::vector<moos::Message>& mail) {
  if (backlog_.passes_through(mail.size())) {
    deliver(mail);  // every normal cycle: no copy into the backlog
  } else {
    report_dropped(backlog_.add(mail));
    handle_backlog();
  }
  handled_this_cycle_ = true;
}

void HazardSensor::handle_backlog() { deliver(backlog_.take()); }

void HazardSensor::deliver(const std::vector<moos::Message>& mail) {
  const double cycle_s = cycle_time();
  std::string formatted;
  hazard::TimedOutputs out;  // reused: most mail posts nothing
  for (const moos::Message& m : mail) {
    const std::string_view text = mail_text(m, formatted);
    out.time_s = driver_->deliver(hazard::Mail{m.key, text, m.time}, cycle_s, out.outputs);
    if (!out.outputs.empty()) {
      publish(std::move(out));
      out = {};
    }
  }
}

void HazardSensor::report_dropped(std::size_t dropped) {
  if (dropped == 0) return;
  backlog_dropped_ += dropped;
  if (!backlog_warning_.empty()) retract_run_warning(backlog_warning_);
  backlog_warning_ = "Mail arrived faster than the sensor handles it: " +
                     std::to_string(backlog_dropped_) +
                     " messages dropped, each the oldest of the client that sent the most";
  report_run_warning(backlog_warning_);
}

void HazardSensor::iterate() {
  // A cycle without new mail still takes its share of a backlog a flood left.
  if (!handled_this_cycle_ && !backlog_.empty()) handle_backlog();
  handled_this_cycle_ = false;
  publish(driver_->step(cycle_time()));
}

double HazardSensor::quiet_until_moos_s(double now_moos_s) const {
  if (!backlog_.empty()) return now_moos_s;  // the backlog's next share is due now
  return driver_ ? driver_->engine().quiet_until_s(now_moos_s) : now_moos_s;
}

std::string HazardSensor::build_report() {
  if (!driver_) return {};
  return hazard::format_report(hazard::collect_report_data(driver_->engine()));
}

void HazardSensor::publish(hazard::TimedOutputs&& timed) {
  hazard::Outputs& out = timed.outputs;
  if (out.empty()) return;  // most steps
  const double now_s = timed.time_s;
  for (hazard::Posting& p : out.postings) {
    write_verbose(now_s, p.variable, p.value);
    notify(std::move(p.variable), std::move(p.value));
  }
  using Report = void (HazardSensor::*)(const std::string&);
  const auto report = [&](const std::vector<std::string>& texts, Report to_appcast,
                          const char* verbose_variable) {
    for (const std::string& t : texts) {
      (this->*to_appcast)(t);
      write_verbose(now_s, verbose_variable, t);
    }
  };
  report(out.config_warnings, &HazardSensor::report_config_warning, kVerboseConfigWarning);
  report(out.run_warnings, &HazardSensor::report_run_warning, kVerboseRunWarning);
  report(out.retracted_run_warnings, &HazardSensor::retract_run_warning, kVerboseRetracted);
  report(out.events, &HazardSensor::report_event, kVerboseEvent);
}

void HazardSensor::write_verbose(double now_s, const std::string& variable,
                                 const std::string& value) const {
  if (!options_.verbose) return;
  *options_.verbose << moos::format_alog_line({now_s - start_time(), variable, app_name(), value});
  options_.verbose->flush();
}

}  // namespace ufld_hazard_sensor
