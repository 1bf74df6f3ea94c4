#include "load_run.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "base/text.hpp"
#include "bench_support.hpp"
#include "load_plan.hpp"
#include "load_samples.hpp"
#include "moos/tcp_client.hpp"

namespace bench {

namespace {

constexpr const char* kSensorName = "uFldHazardSensor";
constexpr const char* kCommunity = "shoreside";
constexpr const char* kClientName = "uBenchLoad";
/// Real seconds allowed for a MOOSDB to accept the load client, and for an APPCAST to answer.
constexpr double kConnectTimeout_real_s = 15;
constexpr double kAppcastTimeout_real_s = 30;
/// Real seconds between repeated configuration requests while waiting for the ACKs.
constexpr double kConfigRepeat_real_s = 0.5;
/// Node reports kept per vehicle for matching detections (600 MOOS seconds at 10 Hz).
constexpr std::size_t kHistoryReports = 6000;
constexpr double kStopGrace_real_s = 5;
/// The sensor's iteration timing (<MOOSNAME>_ITER_GAP / _ITER_LEN, MOOSNAME in capitals).
constexpr const char* kIterGap = "UFLDHAZARDSENSOR_ITER_GAP";
constexpr const char* kIterLen = "UFLDHAZARDSENSOR_ITER_LEN";
/// Detections a paced vehicle keeps waiting for classification (the newest win).
constexpr std::size_t kMaxUnclassified = 50;

struct Vehicle {
  std::string name;
  Lawnmower track;
  std::deque<SentReport> history;
  bool acked = false;
  std::deque<std::string> unclassified;  ///< labels detected, not yet asked (paced classify)
  double next_config_sim_s = 0;
  double next_classify_sim_s = 0;
};

struct Received {
  double real_s;
  moos::Message message;
};

/// The load client's mail, stamped on arrival by the comms thread.
class Inbox {
 public:
  void attach(moos::TcpClient& client) {
    client.set_on_mail([this, &client] {
      const double now = steady_now_s();
      auto mail = client.fetch();
      std::lock_guard<std::mutex> lock(mutex_);
      for (auto& m : mail) items_.push_back({now, std::move(m)});
    });
  }
  std::vector<Received> take() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::exchange(items_, {});
  }

 private:
  std::mutex mutex_;
  std::vector<Received> items_;
};

struct AppcastSample {
  double moos_s;
  long long iteration;
};

std::string appcast_request() {
  return std::string("node=") + kCommunity + ",app=" + kSensorName +
         ",duration=30,key=process_bench,thresh=any";
}

/// Everything a run collects from the mail.
struct Tally {
  std::vector<double> delays_s;
  std::vector<AppcastSample> appcasts;
  std::size_t detections = 0;
  std::size_t hazard_reports = 0;
};

class Run {
 public:
  Run(const LoadSpec& spec, const Target& target, std::ostream& log)
      : spec_(spec), target_(target), log_(log) {}

  LoadResult go() {
    LoadResult result;
    result.ok = execute(result);
    sensor_.stop(kStopGrace_real_s);
    if (client_) client_->close();
    db_.stop(kStopGrace_real_s);
    return result;
  }

 private:
  bool fail(LoadResult& r, const std::string& why) {
    r.error = why;
    return false;
  }

  bool execute(LoadResult& r) {
    namespace fs = std::filesystem;
    fs::create_directories(target_.work_dir);
    const auto port = free_tcp_port();
    if (!port) return fail(r, "no free TCP port");
    MissionSpec mission;
    mission.port = *port;
    mission.time_warp = spec_.time_warp;
    mission.community = kCommunity;
    mission.app_tick_hz = spec_.app_tick_hz;
    mission.idle_app_tick_hz = target_.idle_app_tick_hz;
    mission.hazard_file = fs::absolute(target_.hazard_file).string();
    mission.swath_length_m = spec_.swath_length_m;
    mission.show_hazards = spec_.show_hazards;
    const std::string mission_path = target_.work_dir + "/mission.moos";
    std::ofstream(mission_path) << mission_text(mission);

    std::vector<std::string> db_args = {"mission.moos"};
    if (!spec_.moosdb_log.empty()) db_args.push_back("--log=" + spec_.moosdb_log);
    if (spec_.sample_every_s > 0 && !samples_.open(target_.work_dir + "/" + spec_.samples_csv))
      return fail(r, "cannot write " + spec_.samples_csv);
    if (!db_.start(target_.moosdb, db_args, target_.work_dir,
                   target_.work_dir + "/moosdb"))
      return fail(r, "cannot start " + target_.moosdb + ": " + db_.error());
    moos::TcpClientOptions options;
    options.port = *port;
    options.name = kClientName;
    options.time_warp = spec_.time_warp;
    client_.emplace(options);
    inbox_.attach(*client_);
    client_->register_variable("UHZ_DETECTION_REPORT");
    client_->register_variable("UHZ_HAZARD_REPORT");
    client_->register_variable("APPCAST");
    client_->register_wildcard("UHZ_CONFIG_ACK_*");
    client_->register_variable(kIterGap);
    client_->register_variable(kIterLen);
    if (!client_->start() || !connect_while_db_runs())
      return fail(r, "no connection to " + target_.moosdb + " on port " + std::to_string(*port) +
                         " (see " + target_.work_dir + "/moosdb.err)");

    make_vehicles();
    const double started = steady_now_s();
    if (!sensor_.start(target_.sensor, {"mission.moos", kSensorName}, target_.work_dir,
                       target_.work_dir + "/sensor"))
      return fail(r, "cannot start " + target_.sensor + ": " + sensor_.error());
    if (!configure_all(started))
      return fail(r, "the sensor did not iterate and acknowledge every vehicle's configuration in "
                     "time (see " + target_.work_dir + "/sensor.err)");
    r.startup_real_s = steady_now_s() - started;
    log_ << "  " << target_.label << ": sensor ready after " << base::fix(r.startup_real_s, 1)
         << " s, playing " << base::format_g(spec_.duration_s) << " simulated s\n";
    return play(r);
  }

  /// Waits for the load client's connection, giving up early if the MOOSDB has exited.
  bool connect_while_db_runs() {
    const double deadline = steady_now_s() + kConnectTimeout_real_s;
    while (steady_now_s() < deadline && db_.running())
      if (client_->wait_until_connected(0.1)) return true;
    return false;
  }

  void make_vehicles() {
    const auto strips = split_field(spec_.field_side_m, spec_.vehicles);
    for (int i = 0; i < spec_.vehicles; ++i) {
      std::string name = "veh" + std::to_string(i + 1);
      // Periodic requests are staggered over the vehicles, as independent vehicles would be.
      const double share = static_cast<double>(i) / spec_.vehicles;
      vehicles_.push_back({name, Lawnmower(strips[static_cast<std::size_t>(i)],
                                           2 * spec_.sensor_width_m), {}, false, {},
                           spec_.config_every_s * (1 + share), spec_.classify_every_s * share});
      index_[name] = static_cast<std::size_t>(i);
    }
  }

  bool configure_all(double started) {
    double next_request = 0;
    std::size_t acked = 0;
    bool iterated = false;  // the first APPCAST comes with the first iteration, after loading
    while (acked < vehicles_.size() || !iterated) {
      const double now = steady_now_s();
      if (now - started > spec_.startup_timeout_real_s || !sensor_.running()) return false;
      if (now >= next_request) {
        for (const auto& v : vehicles_)
          if (!v.acked)
            post_config_request(v.name, "0.9");
        next_request = now + kConfigRepeat_real_s;
      }
      for (const auto& item : inbox_.take()) {
        if (item.message.key == "APPCAST") iterated = true;
        if (!base::starts_with(item.message.key, "UHZ_CONFIG_ACK_")) continue;
        const auto found = index_.find(value_of(item.message.sval, "vname"));
        if (found == index_.end() || vehicles_[found->second].acked) continue;
        vehicles_[found->second].acked = true;
        ++acked;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return true;
  }

  void handle_mail(double half_length) {
    for (auto& item : inbox_.take()) {
      const auto& m = item.message;
      if (m.key == kIterGap) {
        samples_.note_iteration_gap(m.dval);
      } else if (m.key == kIterLen) {
        samples_.note_iteration_length(m.dval);
      } else if (m.key == "APPCAST") {
        if (const auto iteration = appcast_iteration(m.sval))
          tally_.appcasts.push_back({m.time, *iteration});
      } else if (m.key == "UHZ_HAZARD_REPORT") {
        ++tally_.hazard_reports;
      } else if (m.key == "UHZ_DETECTION_REPORT") {
        ++tally_.detections;
        const auto found = index_.find(value_of(m.sval, "vname"));
        const auto x = base::parse_number(value_of(m.sval, "x"));
        const auto y = base::parse_number(value_of(m.sval, "y"));
        if (found == index_.end() || !x || !y) continue;
        const Vehicle& v = vehicles_[found->second];
        if (const auto delay = detection_delay(v.history, item.real_s, *x, *y,
                                               spec_.sensor_width_m, half_length))
          tally_.delays_s.push_back(*delay);
        classify(vehicles_[found->second], value_of(m.sval, "label"));
      }
    }
  }

  void classify(Vehicle& v, const std::string& label) {
    if (spec_.classify_every_s <= 0) {
      client_->notify("UHZ_CLASSIFY_REQUEST", "vname=" + v.name + ",label=" + label);
      return;
    }
    v.unclassified.push_back(label);
    if (v.unclassified.size() > kMaxUnclassified) v.unclassified.pop_front();
  }

  /// The periodic requests due at `sim_s`: configuration (pd alternating 0.9 / 0.85, so each
  /// A vehicle's UHZ_CONFIG_REQUEST, stamped as coming from the vehicle's own community: the
  /// original sensor answers only a request whose originating community is its vname (ours
  /// does not check it; docs/messages.md, UHZ_CONFIG_REQUEST), and every vehicle here shares one
  /// client.
  void post_config_request(const std::string& vname, const std::string& pd) {
    moos::Message m = moos::make_string_notify(
        "UHZ_CONFIG_REQUEST",
        "vname=" + vname + ",width=" + base::format_g(spec_.sensor_width_m) + ",pd=" + pd,
        std::string(), moos::kUnsetDouble);
    m.community = vname;
    client_->post(std::move(m));
  }

  /// is a real update) and paced classification.
  void periodic_requests(Vehicle& v, double sim_s) {
    if (spec_.config_every_s > 0 && sim_s >= v.next_config_sim_s) {
      const bool odd = std::fmod(std::floor(v.next_config_sim_s / spec_.config_every_s), 2) != 0;
      post_config_request(v.name, odd ? "0.85" : "0.9");
      v.next_config_sim_s += spec_.config_every_s;
    }
    if (spec_.classify_every_s > 0 && sim_s >= v.next_classify_sim_s) {
      if (!v.unclassified.empty()) {
        client_->notify("UHZ_CLASSIFY_REQUEST",
                        "vname=" + v.name + ",label=" + v.unclassified.back());
        v.unclassified.pop_back();
      }
      v.next_classify_sim_s += spec_.classify_every_s;
    }
  }

  /// One sample when due (every sample_every_s simulated seconds).
  void sample_if_due(double sim_s) {
    if (spec_.sample_every_s <= 0 || sim_s < next_sample_sim_s_) return;
    next_sample_sim_s_ += spec_.sample_every_s;
    const auto sensor = read_proc_usage(sensor_.pid());
    const auto db = read_proc_usage(db_.pid());
    samples_.write(sim_s, sensor ? sensor->rss_kb : -1, db ? db->rss_kb : -1);
  }

  /// After the load: mail is read (answers still pending arrive), nothing is sent.
  void drain(double t0) {
    const double end = steady_now_s() + spec_.drain_s / spec_.time_warp;
    while (steady_now_s() < end && sensor_.running()) {
      handle_mail(spec_.swath_half_length_m);
      sample_if_due((steady_now_s() - t0) * spec_.time_warp);
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }

  /// The first APPCAST stamped at or after `moos_s`, waiting up to `timeout_real_s` for it.
  std::optional<AppcastSample> appcast_after(double moos_s, double timeout_real_s) {
    const double deadline = steady_now_s() + timeout_real_s;
    while (true) {
      for (const auto& a : tally_.appcasts)
        if (a.moos_s >= moos_s) return a;
      if (steady_now_s() > deadline || !sensor_.running()) return std::nullopt;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      handle_mail(spec_.swath_half_length_m);
    }
  }

  bool play(LoadResult& r) {
    const double step_real_s = 1.0 / (spec_.report_hz * spec_.time_warp);
    const double request_every_s = 1.0 / spec_.request_hz;
    const auto sensor_start = read_proc_usage(sensor_.pid());
    const auto db_start = read_proc_usage(db_.pid());
    if (!sensor_start || !db_start) return fail(r, "a process ended before the load started");
    const double start_moos = client_->moos_time();
    client_->notify("APPCAST_REQ", appcast_request());
    const double t0 = steady_now_s();
    double next_request_sim = 0;
    const auto steps = std::llround(spec_.duration_s * spec_.report_hz);
    for (long long step = 0; step < steps; ++step) {
      const double due = t0 + static_cast<double>(step) * step_real_s;
      const double now = steady_now_s();
      if (due > now) std::this_thread::sleep_for(std::chrono::duration<double>(due - now));
      const double sent = steady_now_s();
      const double sim_s = (sent - t0) * spec_.time_warp;
      const double moos_now = client_->moos_time();
      const bool request = sim_s >= next_request_sim;
      if (request) next_request_sim += request_every_s;
      for (auto& v : vehicles_) {
        const Pose pose = v.track.at(sim_s * spec_.speed_mps);
        client_->notify("NODE_REPORT", node_report(v.name, pose, spec_.speed_mps, moos_now));
        v.history.push_back({sent, pose});
        if (v.history.size() > kHistoryReports) v.history.pop_front();
        if (request) client_->notify("UHZ_SENSOR_REQUEST", "vname=" + v.name);
        periodic_requests(v, sim_s);
        ++r.reports_sent;
      }
      handle_mail(spec_.swath_half_length_m);
      sample_if_due(sim_s);
      if (step % 64 == 0 && !sensor_.running()) return fail(r, "the sensor exited during the load");
    }
    // The window ends one step after the last reports were posted.
    const double end = t0 + static_cast<double>(steps) * step_real_s;
    if (end > steady_now_s())
      std::this_thread::sleep_for(std::chrono::duration<double>(end - steady_now_s()));
    const double t1 = steady_now_s();
    const auto sensor_end = read_proc_usage(sensor_.pid());
    const auto db_end = read_proc_usage(db_.pid());
    if (!sensor_end || !db_end) return fail(r, "a process ended during the load");
    const double end_moos = client_->moos_time();
    client_->notify("APPCAST_REQ", appcast_request());

    r.window_real_s = t1 - t0;
    r.simulated_h = r.window_real_s * spec_.time_warp / 3600.0;
    r.sensor_cpu_per_h = (sensor_end->cpu_s - sensor_start->cpu_s) / r.simulated_h;
    r.moosdb_cpu_per_h = (db_end->cpu_s - db_start->cpu_s) / r.simulated_h;
    r.sensor_cpu_share = (sensor_end->cpu_s - sensor_start->cpu_s) / r.window_real_s;
    r.sensor_rss_kb = sensor_end->rss_kb;
    r.sensor_hwm_kb = sensor_end->hwm_kb;
    r.moosdb_hwm_kb = db_end->hwm_kb;
    r.reports_nominal = spec_.duration_s * spec_.report_hz * spec_.vehicles;

    const auto first = appcast_after(start_moos, kAppcastTimeout_real_s);
    const auto last = appcast_after(end_moos, kAppcastTimeout_real_s);
    if (first && last && last->moos_s > first->moos_s)
      r.iterations_per_s = static_cast<double>(last->iteration - first->iteration) /
                           (last->moos_s - first->moos_s);
    drain(t0);
    r.detections = tally_.detections;
    r.matched = tally_.delays_s.size();
    r.hazard_reports = tally_.hazard_reports;
    if (!tally_.delays_s.empty()) {
      r.delay_p50_ms = 1000 * percentile(tally_.delays_s, 0.5);
      r.delay_p99_ms = 1000 * percentile(tally_.delays_s, 0.99);
    }
    return true;
  }

  const LoadSpec& spec_;
  const Target& target_;
  std::ostream& log_;
  Process db_;
  Process sensor_;
  Inbox inbox_;  // before client_: the client's thread calls into it until the client closes
  std::optional<moos::TcpClient> client_;
  std::vector<Vehicle> vehicles_;
  std::map<std::string, std::size_t> index_;
  Tally tally_;
  SampleLog samples_;
  double next_sample_sim_s_ = 0;
};

}  // namespace

LoadResult run_load(const LoadSpec& spec, const Target& target, std::ostream& log) {
  return Run(spec, target, log).go();
}

}  // namespace bench
