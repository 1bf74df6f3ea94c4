// hazard_study: one mission in lockstep. Contract in mission_run.hpp.

#include "mission_run.hpp"

#include <memory>

#include "HazardMetric.hpp"
#include "HazardMgr.hpp"
#include "HazardSensor.hpp"
#include "SimSurveyVehicle.hpp"
#include "base/text.hpp"
#include "mission/messages/hazardset_report.hpp"
#include "moos/alog.hpp"
#include "moos/bus.hpp"
#include "moos/clock.hpp"
#include "moos/lockstep.hpp"

namespace hazard_study {

namespace {

constexpr const char* kRunnerName = "hazard_study";

/// `logged`: every posting is read (--alog), so the sensor builds its visuals too. With
/// `fields`, the sensor and the grader take their field from it.
std::unique_ptr<moos::MoosApp> make_app(const std::string& program, bool logged,
                                        FieldCache* fields, std::uint64_t seed) {
  if (base::iequals(program, "uFldHazardSensor")) {
    ufld_hazard_sensor::HazardSensorOptions options;
    if (fields)
      options.make_engine = [fields, seed](const auto& lines, const auto& settings, auto readers) {
        return fields->sensor_engine(lines, settings, readers, seed);
      };
    options.share_node_report_parses = true;  // the managers read the same reports
    if (!logged) {
      options.readers = hazard::PostingReaders::kReportCounts;
      options.post_iteration_timing = false;
    }
    return std::make_unique<ufld_hazard_sensor::HazardSensor>(std::move(options));
  }
  if (base::iequals(program, "uFldHazardMetric")) {
    ufld_hazard_metric::MetricSource source;
    if (fields)
      source = [fields](const auto& lines, const auto& dir) { return fields->metric(lines, dir); };
    return std::make_unique<ufld_hazard_metric::HazardMetricApp>(std::move(source));
  }
  if (base::iequals(program, "pHazardMgr")) return std::make_unique<phazard_mgr::HazardMgr>();
  auto vehicle = std::make_unique<usim_survey_vehicle::SimSurveyVehicle>();  // (plan checked)
  vehicle->share_node_report_parses(true);  // the sensor and managers read its reports here
  // They read X and Y, which every report carries: LAT and LON are for the log alone.
  vehicle->report_lat_lon(logged);
  return vehicle;
}

/// What the runner learns from the mail it observes (every posting, by a wildcard).
class Observer {
 public:
  Observer(const MissionPlan& plan, MissionResult& result, std::string* alog, double t0)
      : result_(result), alog_(alog), t0_(t0) {
    for (const std::string& v : plan.final_vehicles)
      finals_.push_back(Final{v, "HAZARDSET_EVAL_" + base::to_upper(v)});
  }

  void take(const std::vector<moos::Message>& mail) {
    for (const moos::Message& m : mail) {
      if (alog_) *alog_ += moos::format_alog_line(moos::alog_entry(m, t0_));
      note(m);
    }
  }

  /// "" while the mission runs, else how it ended.
  std::string end() const {
    bool all_graded = true;
    for (const Final& f : finals_) {
      if (!f.graded && !f.empty_report) return {};
      all_graded = all_graded && f.graded;
    }
    return all_graded ? "graded" : "empty_report";
  }

 private:
  struct Final {
    std::string vehicle;
    std::string eval_var;
    bool graded = false;
    bool empty_report = false;
  };

  void note(const moos::Message& m) {
    if (m.key == "UHZ_DETECTION_REPORT") ++result_.detections;
    else if (m.key == "UHZ_HAZARD_REPORT") ++result_.classifications;
    else if (m.key == "HAZARD_SEARCH_SCORE" && m.is_double()) result_.score = m.dval;
    else if (m.key == "HAZARDSET_REPORT") note_report(m.sval);
    else if (base::starts_with(m.key, "HAZARDSET_EVAL_")) note_eval(m);
  }

  void note_report(const std::string& text) {
    const mission::HazardsetReport report = mission::parse_hazardset_report(text);
    for (Final& f : finals_)
      if (f.vehicle == report.source) f.empty_report = report.objects.empty();
  }

  void note_eval(const moos::Message& m) {
    for (Final& f : finals_) {
      if (m.key != f.eval_var) continue;
      f.graded = true;
      if (auto eval = mission::parse_hazardset_eval(m.sval); eval.value) result_.eval = *eval.value;
    }
  }

  MissionResult& result_;
  std::string* alog_;
  double t0_;
  std::vector<Final> finals_;
};

}  // namespace

MissionResult run_mission(const MissionPlan& plan, const Setting& setting, std::uint64_t seed,
                          const RunOptions& options, std::string* alog) {
  MissionResult result;
  result.setting = setting.label;
  result.seed = seed;

  moos::ManualClock clock;
  const double t0 = clock.unix_now_s();
  // The runner reads the mail through its own client: the bus keeps no copy of the postings.
  moos::InProcessBus bus(clock, moos::InProcessBus::Options{
                                    plan.community.empty() ? moos::kDefaultCommunity : plan.community,
                                    1.0, false});
  if (alog) *alog += moos::alog_header(plan.community.empty() ? "hazard_study" : plan.community, t0);
  auto runner = bus.connect(kRunnerName);
  // Without a log the runner reads only what the result needs (fewer copies of the mail).
  if (alog) {
    runner->register_wildcard("*", "*");
  } else {
    for (const char* var : {"UHZ_DETECTION_REPORT", "UHZ_HAZARD_REPORT", "HAZARD_SEARCH_SCORE",
                            "HAZARDSET_REPORT"})
      runner->register_variable(var);
    runner->register_wildcard("HAZARDSET_EVAL_*", "*");
  }
  Observer observer(plan, result, alog, t0);

  std::vector<std::unique_ptr<moos::MoosApp>> apps;
  std::vector<std::unique_ptr<moos::BusClient>> clients;
  moos::Lockstep lockstep(bus, clock);
  for (const Process& p : plan.processes) {
    auto app = make_app(p.program, alog != nullptr, options.fields, seed);
    moos::AppSettings settings = process_settings(plan, p, app->traits(), setting, seed);
    settings.post_status = alog != nullptr;  // without a log nobody reads <APP>_STATUS
    clients.push_back(bus.connect(settings.moos_name));
    app->start(*clients.back(), std::move(settings));
    for (const std::string& w : app->appcast().config_warnings())
      result.config_warnings.push_back(p.name + ": " + w);
    lockstep.add(*app);
    apps.push_back(std::move(app));
  }
  auto observe = [&] {
    observer.take(runner->fetch());
    return !observer.end().empty();
  };
  const double deploy = t0 + options.deploy_s;
  lockstep.run_until(deploy, observe);
  runner->notify("DEPLOY_ALL", std::string("true"));
  runner->notify("HAZARD_SEARCH_START", std::string("true"));
  observe();
  const bool ended = lockstep.run_until(deploy + options.max_time_s, observe);
  result.end = ended ? observer.end() : "max_time";
  result.sim_s = lockstep.moos_time() - deploy;
  return result;
}

}  // namespace hazard_study
