// moosdb_bench: how fast a MOOSDB relays small messages between two clients on loopback
// (throughput), and how long one takes at a steady rate (latency), for moosdb-lite and, when
// one is found, the reference MOOSDB side by side. See --help and docs/performance.md.
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "base/text.hpp"
#include "bench_support.hpp"
#include "moos/tcp_client.hpp"

namespace {

constexpr const char* kHelp = R"(Usage: moosdb_bench [OPTIONS]

Two asynchronous libmoos clients on loopback: one posts small double messages, the other
subscribes. Throughput: --messages messages as fast as the DB relays them (at most --window
unanswered); latency: --rate messages per second for --seconds (posted on a 1 ms tick),
each stamped with its send time.

  --moosdb=PATH        the DB to measure (default: our moosdb-lite)
  --reference=PATH|none a second DB measured the same way (default: MOOSDB on PATH)
  --messages=N         messages in the throughput run (default 500000)
  --window=N           messages in flight at most (default 20000)
  --rate=HZ            messages per second in the latency run (default 10000)
  --seconds=S          length of the latency run (default 5)
  --work-dir=DIR       mission files and DB logs (default: a new /tmp folder, removed at the
                       end unless a run failed)
)";

constexpr double kConnectTimeout_real_s = 10;
constexpr double kPhaseTimeout_real_s = 120;
constexpr const char* kWarmKey = "BENCH_WARM";
constexpr const char* kThroughputKey = "BENCH_TPUT";
constexpr const char* kLatencyKey = "BENCH_LAT";

struct Options {
  std::string moosdb = HAZARD_MOOSDB_LITE_PROGRAM;
  std::string reference;  // "" = MOOSDB on PATH
  long long messages = 500000;
  long long window = 20000;
  double rate_hz = 10000;
  double seconds = 5;
  std::string work_dir;
};

struct Result {
  bool ok = false;
  std::string error;
  double messages_per_s = 0;
  double db_cpu_us_per_message = 0;
  double p50_ms = -1, p99_ms = -1, max_ms = -1;
  std::size_t latency_received = 0, latency_sent = 0;
};

/// What the receiving client counts, filled by its comms thread.
struct Receiver {
  std::atomic<long long> warm{0};
  std::atomic<long long> throughput{0};
  std::atomic<double> last_throughput_s{0};
  std::mutex mutex;
  std::vector<double> delays_s;

  void on_mail(std::vector<moos::Message> mail) {
    const double now = bench::steady_now_s();
    for (const auto& m : mail) {
      if (m.key == kThroughputKey) {
        ++throughput;
        last_throughput_s = now;
      } else if (m.key == kLatencyKey) {
        std::lock_guard<std::mutex> lock(mutex);
        delays_s.push_back(now - m.dval);
      } else if (m.key == kWarmKey) {
        ++warm;
      }
    }
  }
};

bool wait_for(const std::function<bool()>& done, double timeout_s) {
  const double deadline = bench::steady_now_s() + timeout_s;
  while (!done()) {
    if (bench::steady_now_s() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return true;
}

moos::TcpClientOptions client_options(int port, const std::string& name) {
  moos::TcpClientOptions o;
  o.port = port;
  o.name = name;
  return o;
}

Result measure(const Options& o, const std::string& db_program, const std::string& dir) {
  Result r;
  std::filesystem::create_directories(dir);
  const auto port = bench::free_tcp_port();
  if (!port) {
    r.error = "no free port";
    return r;
  }
  std::ofstream(dir + "/bench.moos") << "ServerHost = localhost\nServerPort = " << *port
                                     << "\nCommunity = bench\nMOOSTimeWarp = 1\n";
  bench::Process db;
  if (!db.start(db_program, {"bench.moos"}, dir, dir + "/moosdb")) {
    r.error = "cannot start " + db_program;
    return r;
  }
  Receiver receiver;
  moos::TcpClient rx(client_options(*port, "bench_rx"));
  moos::TcpClient tx(client_options(*port, "bench_tx"));
  rx.set_on_mail([&] { receiver.on_mail(rx.fetch()); });
  for (const char* key : {kWarmKey, kThroughputKey, kLatencyKey}) rx.register_variable(key);
  if (!rx.start() || !tx.start() || !rx.wait_until_connected(kConnectTimeout_real_s) ||
      !tx.wait_until_connected(kConnectTimeout_real_s)) {
    r.error = "no connection to " + db_program + " (see " + dir + "/moosdb.err)";
    return r;
  }
  // The subscription is in place once a warm-up message comes through (one posted per 10 ms).
  double next_warm_s = 0;
  if (!wait_for([&] {
        if (bench::steady_now_s() >= next_warm_s) {
          tx.notify(kWarmKey, 0.0);
          next_warm_s = bench::steady_now_s() + 0.01;
        }
        return receiver.warm > 0;
      }, kConnectTimeout_real_s)) {
    r.error = "no message came through " + db_program;
    return r;
  }

  const auto cpu_before = bench::read_proc_usage(db.pid());
  const double t0 = bench::steady_now_s();
  for (long long sent = 0; sent < o.messages;) {
    if (sent - receiver.throughput < o.window) {
      tx.notify(kThroughputKey, static_cast<double>(sent));
      ++sent;
    } else {
      std::this_thread::sleep_for(std::chrono::microseconds(50));
    }
    if (bench::steady_now_s() - t0 > kPhaseTimeout_real_s) break;
  }
  if (!wait_for([&] { return receiver.throughput >= o.messages; }, kPhaseTimeout_real_s)) {
    r.error = "only " + std::to_string(receiver.throughput.load()) + " of " +
              std::to_string(o.messages) + " messages relayed in time";
    return r;
  }
  const auto cpu_after = bench::read_proc_usage(db.pid());
  r.messages_per_s = static_cast<double>(o.messages) / (receiver.last_throughput_s - t0);
  if (cpu_before && cpu_after)
    r.db_cpu_us_per_message =
        1e6 * (cpu_after->cpu_s - cpu_before->cpu_s) / static_cast<double>(o.messages);

  // Messages are posted on a 1 ms tick (those due by then, each stamped when posted): a
  // sender spinning on a 100 us period would take a core from the DB on a small machine.
  const auto count = static_cast<long long>(o.seconds * o.rate_hz);
  const double l0 = bench::steady_now_s();
  for (long long i = 0; i < count;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    const auto due = static_cast<long long>((bench::steady_now_s() - l0) * o.rate_hz);
    for (; i < count && i <= due; ++i) tx.notify(kLatencyKey, bench::steady_now_s());
  }
  r.latency_sent = static_cast<std::size_t>(count);
  wait_for([&] {
    std::lock_guard<std::mutex> lock(receiver.mutex);
    return receiver.delays_s.size() >= r.latency_sent;
  }, 5.0);
  rx.close();
  tx.close();
  db.stop(5);
  std::lock_guard<std::mutex> lock(receiver.mutex);
  r.latency_received = receiver.delays_s.size();
  r.p50_ms = 1000 * bench::percentile(receiver.delays_s, 0.5);
  r.p99_ms = 1000 * bench::percentile(receiver.delays_s, 0.99);
  r.max_ms = 1000 * bench::percentile(receiver.delays_s, 1.0);
  r.ok = true;
  return r;
}

const moos::SwitchTable& switch_table() {
  using moos::SwitchKind;
  using moos::switch_rule;
  static const moos::SwitchTable table = bench::bench_switch_table({
      switch_rule("--moosdb", SwitchKind::kText, "a program"),
      switch_rule("--reference", SwitchKind::kText, "a program"),
      switch_rule("--messages", SwitchKind::kInteger, "a whole number in [1, 1e8]", {1, 1e8}),
      switch_rule("--window", SwitchKind::kInteger, "a whole number in [1, 1e8]", {1, 1e8}),
      switch_rule("--rate", SwitchKind::kNumber, "a number in (0, 1e6]", {0, 1e6, true, false}),
      switch_rule("--seconds", SwitchKind::kNumber, "a number in (0, 3600]",
                  {0, 3600, true, false}),
      switch_rule("--work-dir", SwitchKind::kText, "a folder")});
  return table;
}

std::optional<Options> parse(int argc, char** argv) {
  const auto v = bench::read_switches("moosdb_bench", argc, argv, switch_table(), kHelp);
  if (!v) return std::nullopt;
  Options o;
  if (const auto text = v->text("--moosdb")) o.moosdb = *text;
  if (const auto text = v->text("--reference")) o.reference = *text;
  if (const auto n = v->integer("--messages")) o.messages = *n;
  if (const auto n = v->integer("--window")) o.window = *n;
  if (const auto hz = v->number("--rate")) o.rate_hz = *hz;
  if (const auto s = v->number("--seconds")) o.seconds = *s;
  if (const auto text = v->text("--work-dir")) o.work_dir = *text;
  o.moosdb = bench::absolute_program(o.moosdb);
  o.reference = bench::absolute_program(o.reference);
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  auto options = parse(argc, argv);
  if (!options) return 1;
  Options& o = *options;
  const bool temporary = o.work_dir.empty();  // removed at the end unless a run failed
  o.work_dir = bench::work_folder(o.work_dir, "moosdb_bench", std::cerr);
  if (o.work_dir.empty()) return 1;
  std::vector<std::pair<std::string, std::string>> dbs = {{"moosdb-lite", o.moosdb}};
  const std::string reference = o.reference.empty() ? bench::find_on_path("MOOSDB") : o.reference;
  if (!reference.empty() && reference != "none") dbs.emplace_back("MOOSDB", reference);
  else std::cerr << "moosdb_bench: no reference MOOSDB (give --reference=PATH)\n";

  std::vector<Result> results;
  for (const auto& [label, program] : dbs) {
    std::cerr << "moosdb_bench: " << label << " (" << program << ")\n";
    results.push_back(measure(o, program, o.work_dir + "/" + label));
  }
  std::cout << "\n" << o.messages << " small messages relayed between two clients on loopback; "
            << "latency at " << base::format_g(o.rate_hz) << " messages/s for "
            << base::format_g(o.seconds) << " s\n";
  auto row = [&](const std::string& what, auto value_of) {
    std::vector<std::string> cells;
    for (const auto& r : results) cells.push_back(r.ok ? value_of(r) : std::string("failed"));
    std::cout << bench::table_line(what, cells) << "\n";
  };
  std::vector<std::string> header;
  for (const auto& db : dbs) header.push_back(db.first);
  std::cout << bench::table_line("", header) << "\n";
  using bench::cell;
  row("relayed messages / s", [](const Result& r) { return cell(r.messages_per_s, 0); });
  row("DB CPU us / message", [](const Result& r) { return cell(r.db_cpu_us_per_message, 2); });
  row("delay p50 ms", [](const Result& r) { return cell(r.p50_ms, 3); });
  row("delay p99 ms", [](const Result& r) { return cell(r.p99_ms, 3); });
  row("delay max ms", [](const Result& r) { return cell(r.max_ms, 3); });
  row("received / sent", [](const Result& r) {
    return std::to_string(r.latency_received) + "/" + std::to_string(r.latency_sent); });
  int code = 0;
  for (std::size_t i = 0; i < results.size(); ++i)
    if (!results[i].ok) {
      std::cout << dbs[i].first << " failed: " << results[i].error << "\n";
      code = 2;
    }
  if (temporary && code == 0) std::filesystem::remove_all(o.work_dir);
  return code;
}
