// pass_bench: a scripted vehicle makes straight passes, back and forth, over a grid of
// hazards and benign objects (bench/validation/pass_scene.hpp) against any uFldHazardSensor
// through any MOOSDB, asks for a classification of every detection, and writes what the sensor
// reported per group of objects as a CSV file. bench/validation/validate.py turns such files of
// ours and of the original into the tables of docs/validation.md.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "base/text.hpp"
#include "bench_support.hpp"
#include "load_plan.hpp"
#include "moos/tcp_client.hpp"
#include "pass_scene.hpp"

namespace {

constexpr const char* kHelp = R"(Usage: pass_bench --out=FILE [OPTIONS]

Plays one vehicle, archie (NODE_REPORT at 10 Hz, UHZ_SENSOR_REQUEST every second, a
UHZ_CLASSIFY_REQUEST per detection), in straight lanes over the validation scene against a
uFldHazardSensor through a MOOSDB at a time warp, and writes per group and kind of object the
passes, detections, classification answers and correct answers to FILE (docs/validation.md).
A second vehicle, ctrl, drives the same track at pd = 1 without classifying: its detections
(groups ctrl_*) count the sensor events the sensor saw.

  --out=FILE         the result CSV (required)
  --sensor=PATH      the uFldHazardSensor to run (default: ours, built with this benchmark)
  --moosdb=PATH      the MOOSDB (default: our moosdb-lite)
  --seed=N|time      N: random_seed = N (ours); time: seed_random = true (the original seeds
                     from the clock; default)
  --lanes=N          lanes to drive (default 25; 1..100000)
  --pd=P             the requested probability of detection (default 0.8)
  --warp=W           MOOS time warp (default 20)
  --app-tick=HZ      the sensor's AppTick and CommsTick (default 10)
  --work-dir=DIR     where the scene, mission and logs go and stay (default: a new /tmp folder)
)";

constexpr const char* kVehicle = "archie";
/// A second vehicle on the same track at pd = 1 (so pfa = 1): its detections of the inside
/// hazards and benign objects without hr count the sensor events the sensor saw, the check
/// that no event was missed (a process held off the CPU longer than an object stays in the
/// swath would miss it).
constexpr const char* kControl = "ctrl";
constexpr const char* kCommunity = "shoreside";
constexpr double kWidth_m = 25;
constexpr double kExp = 4;
constexpr double kPclass = 0.8;
constexpr double kSwathLength_m = 10;
constexpr double kSpeed_mps = 4;
constexpr double kReportHz = 10;
constexpr double kConnectTimeout_real_s = 15;
constexpr double kStartupTimeout_real_s = 120;
constexpr double kDrainIdle_real_s = 10;
constexpr double kStopGrace_real_s = 5;

struct Options {
  std::string out;
  std::string sensor = HAZARD_SENSOR_PROGRAM;
  std::string moosdb = HAZARD_MOOSDB_LITE_PROGRAM;
  std::string seed = "time";
  long long lanes = 25;
  double pd = 0.8;
  double warp = 20;
  double app_tick_hz = 10;
  std::string work_dir;
};

std::optional<Options> parse(int argc, char** argv) {
  using moos::SwitchKind;
  using moos::switch_rule;
  static const moos::SwitchTable table = bench::bench_switch_table({
      switch_rule("--out", SwitchKind::kText, "a file name"),
      switch_rule("--sensor", SwitchKind::kText, "a program"),
      switch_rule("--moosdb", SwitchKind::kText, "a program"),
      switch_rule("--seed", SwitchKind::kText, "a whole number or time"),
      switch_rule("--lanes", SwitchKind::kInteger, "a whole number in [1, 100000]", {1, 1e5}),
      switch_rule("--pd", SwitchKind::kNumber, "a number in [0, 1]", {0, 1}),
      switch_rule("--warp", SwitchKind::kNumber, "a number in (0, 100]", {0, 100, true, false}),
      switch_rule("--app-tick", SwitchKind::kNumber, "a number in [1, 50]", {1, 50}),
      switch_rule("--work-dir", SwitchKind::kText, "a folder")});
  const auto switches = bench::read_switches("pass_bench", argc, argv, table, kHelp);
  if (!switches) return std::nullopt;
  Options o;
  if (const auto v = switches->text("--out")) o.out = *v;
  if (const auto v = switches->text("--sensor")) o.sensor = *v;
  if (const auto v = switches->text("--moosdb")) o.moosdb = *v;
  if (const auto v = switches->text("--seed")) o.seed = *v;
  if (const auto v = switches->text("--work-dir")) o.work_dir = *v;
  if (const auto v = switches->integer("--lanes")) o.lanes = *v;
  if (const auto v = switches->number("--pd")) o.pd = *v;
  if (const auto v = switches->number("--warp")) o.warp = *v;
  if (const auto v = switches->number("--app-tick")) o.app_tick_hz = *v;
  if (o.out.empty()) {
    std::cerr << "pass_bench: --out=FILE is required (see --help)\n";
    return std::nullopt;
  }
  if (o.seed != "time" && !base::parse_integer(o.seed, 0, 4294967295LL)) {
    std::cerr << "pass_bench: --seed must be a whole number in [0, 4294967295] or time, not '"
              << base::excerpt(o.seed) << "'\n";
    return std::nullopt;
  }
  for (std::string* program : {&o.sensor, &o.moosdb}) *program = bench::absolute_program(*program);
  return o;
}

/// The mission file: both programs read every line of the block the same way.
std::string mission_text(const Options& o, int port) {
  const std::string tick = base::format_g(o.app_tick_hz);
  std::string text = "// Written by pass_bench (docs/validation.md)\n";
  text += "ServerHost = localhost\nServerPort = " + std::to_string(port) + "\n";
  text += std::string("Community = ") + kCommunity + "\n";
  text += "MOOSTimeWarp = " + base::format_g(o.warp) + "\n\n";
  text += "ProcessConfig = uFldHazardSensor\n{\n";
  text += "  AppTick = " + tick + "\n  CommsTick = " + tick + "\n";
  text += "  hazard_file = scene.txt\n";
  text += "  sensor_config = width=" + base::format_g(kWidth_m) + ", exp=" + base::format_g(kExp) +
          ", pclass=" + base::format_g(kPclass) + "\n";
  text += "  swath_length = " + base::format_g(kSwathLength_m) + "\n";
  text += "  min_classify_interval = 0\n  max_vehicle_speed = 5\n";
  text += "  show_hazards = false\n  show_swath = false\n  show_detections = 0\n";
  text += o.seed == "time" ? "  seed_random = true\n" : "  random_seed = " + o.seed + "\n";
  text += "}\n";
  return text;
}

class Run {
 public:
  explicit Run(const Options& o) : o_(o), objects_(validation::make_scene(spec_)) {
    for (std::size_t i = 0; i < objects_.size(); ++i) index_[objects_[i].label] = i;
  }
  ~Run() {
    sensor_.stop(kStopGrace_real_s);
    if (client_) client_->close();
    db_.stop(kStopGrace_real_s);
  }

  bool go() {
    namespace fs = std::filesystem;
    dir_ = bench::work_folder(o_.work_dir, "pass_bench", std::cerr);
    if (dir_.empty()) return false;
    const auto port = bench::free_tcp_port();
    if (!port) return fail("no free TCP port");
    std::ofstream(dir_ + "/scene.txt") << validation::hazard_file_text(objects_, spec_.resemblance);
    std::ofstream(dir_ + "/mission.moos") << mission_text(o_, *port);
    if (!db_.start(o_.moosdb, {"mission.moos"}, dir_, dir_ + "/moosdb"))
      return fail("cannot start " + o_.moosdb + ": " + db_.error());
    moos::TcpClientOptions options;
    options.port = *port;
    options.name = "uValidationVehicle";
    options.time_warp = o_.warp;
    client_.emplace(options);
    client_->set_on_mail([this] {
      auto mail = client_->fetch();
      std::lock_guard<std::mutex> lock(mutex_);
      for (auto& m : mail) inbox_.push_back(std::move(m));
    });
    for (const char* var : {"UHZ_DETECTION_REPORT", "UHZ_HAZARD_REPORT"})
      client_->register_variable(var);
    client_->register_wildcard("UHZ_CONFIG_ACK*");
    if (!client_->start() || !connect())
      return fail("no connection to " + o_.moosdb + " (see " + dir_ + "/moosdb.err)");
    if (!sensor_.start(o_.sensor, {"mission.moos", "uFldHazardSensor"}, dir_, dir_ + "/sensor"))
      return fail("cannot start " + o_.sensor + ": " + sensor_.error());
    if (!configure()) return fail("no UHZ_CONFIG_ACK (see " + dir_ + "/sensor.err)");
    std::cerr << "pass_bench: " << o_.sensor << " acknowledged: " << ack_ << "\n";
    if (!play()) return fail("the sensor exited during the passes (see " + dir_ + "/sensor.err)");
    drain();
    return write();
  }

 private:
  bool fail(const std::string& why) {
    std::cerr << "pass_bench: " << why << "\n";
    return false;
  }

  bool connect() {
    const double deadline = bench::steady_now_s() + kConnectTimeout_real_s;
    while (bench::steady_now_s() < deadline && db_.running())
      if (client_->wait_until_connected(0.1)) return true;
    return false;
  }

  std::vector<moos::Message> take() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::exchange(inbox_, {});
  }

  void post_config_request(const char* vname, double pd) {
    moos::Message m = moos::make_string_notify(
        "UHZ_CONFIG_REQUEST",
        std::string("vname=") + vname + ",width=" + base::format_g(kWidth_m) +
            ",pd=" + base::format_g(pd),
        std::string(), moos::kUnsetDouble);
    m.community = vname;  // the original answers only a request from the vehicle's community
    client_->post(std::move(m));
  }

  /// Repeats both vehicles' requests until both are acknowledged.
  bool configure() {
    const double deadline = bench::steady_now_s() + kStartupTimeout_real_s;
    double next = 0;
    bool control_acked = false;
    while (bench::steady_now_s() < deadline && sensor_.running()) {
      if (bench::steady_now_s() >= next) {
        if (ack_.empty()) post_config_request(kVehicle, o_.pd);
        if (!control_acked) post_config_request(kControl, 1.0);
        next = bench::steady_now_s() + 0.5;
      }
      for (const auto& m : take()) {
        if (!base::starts_with(m.key, "UHZ_CONFIG_ACK")) continue;
        const std::string vname = bench::value_of(m.sval, "vname");
        if (vname == kVehicle) ack_ = m.sval;
        if (vname == kControl) control_acked = true;
      }
      if (!ack_.empty() && control_acked) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
  }

  validation::Tally& tally_of(const validation::SceneObject& o, bool control = false) {
    return tallies_[(control ? "ctrl_" : "") + o.group + "," + o.kind];
  }

  void handle_mail() {
    for (const auto& m : take()) {
      if (m.key != "UHZ_DETECTION_REPORT" && m.key != "UHZ_HAZARD_REPORT") continue;
      const std::string vname = bench::value_of(m.sval, "vname");
      if (vname != kVehicle && vname != kControl) continue;
      const std::string label = bench::value_of(m.sval, "label");
      const auto found = index_.find(label);
      if (found == index_.end()) {
        ++unknown_labels_;
        continue;
      }
      const auto& object = objects_[found->second];
      if (vname == kControl) {
        if (m.key == "UHZ_DETECTION_REPORT") ++tally_of(object, true).detections;
        continue;
      }
      auto& t = tally_of(object);
      if (m.key == "UHZ_DETECTION_REPORT") {
        ++t.detections;
        ++t.classify_requests;
        ++requests_;
        client_->notify("UHZ_CLASSIFY_REQUEST", std::string("vname=") + kVehicle + ",label=" + label);
      } else {
        ++t.answers;
        ++answers_;
        const bool said_hazard = bench::value_of(m.sval, "type") == "hazard";
        if (said_hazard == (object.kind == "H")) ++t.correct;
      }
    }
  }

  bool play() {
    const double lane = validation::lane_length_m(spec_);
    const double step_real_s = 1.0 / (kReportHz * o_.warp);
    const auto steps = static_cast<long long>(
        std::ceil(static_cast<double>(o_.lanes) * lane / kSpeed_mps * kReportHz)) + 1;
    const double t0 = bench::steady_now_s();
    for (long long step = 0; step < steps; ++step) {
      const double due = t0 + static_cast<double>(step) * step_real_s;
      const double now = bench::steady_now_s();
      if (due > now) std::this_thread::sleep_for(std::chrono::duration<double>(due - now));
      const double distance = std::min(static_cast<double>(step) / kReportHz * kSpeed_mps,
                                       static_cast<double>(o_.lanes) * lane);
      const auto pose = validation::pose_at(spec_, distance);
      for (const char* vname : {kVehicle, kControl}) {
        client_->notify("NODE_REPORT",
                        bench::node_report(vname, {pose.x_m, pose.y_m, pose.heading_deg},
                                           kSpeed_mps, client_->moos_time()));
        if (step % static_cast<long long>(kReportHz) == 0)
          client_->notify("UHZ_SENSOR_REQUEST", std::string("vname=") + vname);
      }
      handle_mail();
      if (step % 64 == 0 && !sensor_.running()) return false;
    }
    return true;
  }

  /// Reads mail until every classification is answered or none came for a while.
  void drain() {
    double last_progress = bench::steady_now_s();
    long long seen = -1;
    while (answers_ < requests_ && bench::steady_now_s() - last_progress < kDrainIdle_real_s) {
      handle_mail();
      if (answers_ != seen) {
        seen = answers_;
        last_progress = bench::steady_now_s();
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }

  bool write() {
    for (const auto& o : objects_) {
      for (const bool control : {false, true}) {
        auto& t = tally_of(o, control);
        ++t.objects;
        t.passes += validation::passes_by(o, o_.lanes);
      }
    }
    const std::vector<std::pair<std::string, std::string>> header = {
        {"sensor", o_.sensor},
        {"seed", o_.seed},
        {"lanes", std::to_string(o_.lanes)},
        {"pd", base::format_g(o_.pd)},
        {"exp", base::format_g(kExp)},
        {"pclass", base::format_g(kPclass)},
        {"hr", base::format_g(spec_.resemblance)},
        {"warp", base::format_g(o_.warp)},
        {"app_tick", base::format_g(o_.app_tick_hz)},
        {"ack", "\"" + ack_ + "\""},
        {"unknown_labels", std::to_string(unknown_labels_)},
        {"unanswered", std::to_string(requests_ - answers_)}};
    std::ofstream out(o_.out);
    out << validation::tallies_csv(header, tallies_);
    out.close();
    if (!out) return fail("cannot write " + o_.out);
    std::cerr << "pass_bench: " << requests_ << " detections, " << answers_ << " answers -> "
              << o_.out << "\n";
    return true;
  }

  const Options& o_;
  validation::SceneSpec spec_;
  std::vector<validation::SceneObject> objects_;
  std::map<std::string, std::size_t> index_;
  validation::Tallies tallies_;
  std::string dir_;
  std::string ack_;
  long long requests_ = 0;
  long long answers_ = 0;
  long long unknown_labels_ = 0;
  bench::Process db_;
  bench::Process sensor_;
  std::mutex mutex_;
  std::vector<moos::Message> inbox_;
  std::optional<moos::TcpClient> client_;  // last: its thread calls into the inbox until closed
};

}  // namespace

int main(int argc, char** argv) {
  const auto options = parse(argc, argv);
  if (!options) return 2;
  return Run(*options).go() ? 0 : 1;
}
