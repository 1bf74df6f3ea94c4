#include "bench_support.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <thread>

#include "base/text.hpp"

namespace bench {

namespace {

/// Fields 14 (utime) and 15 (stime) of /proc/<pid>/stat are the 12th and 13th after the
/// command name (field 2): the state is field 3.
constexpr std::size_t kUtimeIndexAfterName = 11;

std::string read_whole(const std::string& path) {
  std::ifstream in(path);
  if (!in) return {};
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

double steady_now_s() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

std::optional<unsigned long long> cpu_ticks_from_stat(std::string_view stat_line) {
  const auto close = stat_line.rfind(')');
  if (close == std::string_view::npos) return std::nullopt;
  const auto fields = base::split(base::trim(stat_line.substr(close + 1)), ' ');
  if (fields.size() <= kUtimeIndexAfterName + 1) return std::nullopt;
  const auto utime = base::parse_unsigned(fields[kUtimeIndexAfterName]);
  const auto stime = base::parse_unsigned(fields[kUtimeIndexAfterName + 1]);
  if (!utime || !stime) return std::nullopt;
  return *utime + *stime;
}

std::optional<unsigned long long> run_ns_from_schedstat(std::string_view schedstat_line) {
  const auto fields = base::split(base::trim(schedstat_line), ' ');
  if (fields.size() != 3) return std::nullopt;
  return base::parse_unsigned(fields[0]);
}

std::optional<long long> status_kb(std::string_view status_text, std::string_view field) {
  for (const auto line : base::split(status_text, '\n')) {
    const auto colon = line.find(':');
    if (colon == std::string_view::npos || line.substr(0, colon) != field) continue;
    std::string_view value = base::trim(line.substr(colon + 1));
    if (!base::ends_with(value, "kB")) return std::nullopt;
    value.remove_suffix(2);
    return base::parse_integer(value, 0, std::numeric_limits<long long>::max());
  }
  return std::nullopt;
}

namespace {

/// The run time of every live thread of `pid` (schedstat), in seconds; nullopt if any is missing.
std::optional<double> threads_cpu_s(const std::string& proc_dir) {
  std::error_code ec;
  unsigned long long total_ns = 0;
  bool any = false;
  for (const auto& task : std::filesystem::directory_iterator(proc_dir + "/task", ec)) {
    const auto ns = run_ns_from_schedstat(read_whole(task.path().string() + "/schedstat"));
    if (!ns) continue;  // a thread that ended meanwhile
    total_ns += *ns;
    any = true;
  }
  if (ec || !any) return std::nullopt;
  constexpr double kNsPerSecond = 1e9;
  return static_cast<double>(total_ns) / kNsPerSecond;
}

}  // namespace

std::optional<ProcUsage> read_proc_usage(pid_t pid) {
  const std::string dir = "/proc/" + std::to_string(pid);
  const auto ticks = cpu_ticks_from_stat(read_whole(dir + "/stat"));
  const std::string status = read_whole(dir + "/status");
  const auto rss = status_kb(status, "VmRSS");
  const auto hwm = status_kb(status, "VmHWM");
  if (!ticks || !rss || !hwm) return std::nullopt;
  ProcUsage usage;
  usage.cpu_s = threads_cpu_s(dir).value_or(static_cast<double>(*ticks) /
                                            static_cast<double>(::sysconf(_SC_CLK_TCK)));
  usage.rss_kb = *rss;
  usage.hwm_kb = *hwm;
  return usage;
}

moos::SwitchTable bench_switch_table(std::vector<moos::SwitchRule> rules) {
  moos::SwitchTable t;
  t.rules = std::move(rules);
  t.rules.push_back(moos::help_switch_rule());
  t.bad_value = [](const std::string& arg, const moos::SwitchRule& r) {
    return r.name + " needs " + r.problem + ": '" + base::excerpt(arg, 80) + "'";
  };
  t.unknown = [](const std::string& arg) {
    return "unknown argument '" + base::excerpt(arg, 80) + "'";
  };
  return t;
}

std::optional<moos::SwitchValues> read_switches(const char* program, int argc, char** argv,
                                                const moos::SwitchTable& table,
                                                const char* help) {
  moos::SwitchValues v =
      moos::parse_switches(std::vector<std::string>(argv + 1, argv + argc), table);
  if (v.has("--help")) {
    std::cout << help;
    std::exit(0);
  }
  std::string problem = v.errors.empty() ? "" : v.errors.front();
  if (problem.empty() && !v.free.empty())
    problem = "unexpected argument '" + base::excerpt(v.free.front(), 80) + "'";
  if (problem.empty()) return v;
  std::cerr << program << ": " << problem << " (see --help)\n";
  return std::nullopt;
}

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double f = std::clamp(fraction, 0.0, 1.0);
  const auto rank = static_cast<std::size_t>(std::ceil(f * static_cast<double>(values.size())));
  return values[rank == 0 ? 0 : rank - 1];
}

double cpu_per_h_at_nominal_tick(double cpu_per_h, double iterations_per_s, double app_tick_hz) {
  // Within 1 % counts as kept: the two APPCASTs that count iterations are not whole periods apart.
  constexpr double kKeptFraction = 0.99;
  if (!(iterations_per_s > 0)) return std::numeric_limits<double>::quiet_NaN();
  if (iterations_per_s >= kKeptFraction * app_tick_hz) return cpu_per_h;
  return cpu_per_h * app_tick_hz / iterations_per_s;
}

std::optional<int> free_tcp_port() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return std::nullopt;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = 0;
  socklen_t length = sizeof(address);
  std::optional<int> port;
  if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0 &&
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) == 0)
    port = ntohs(address.sin_port);
  ::close(fd);
  return port;
}

std::string find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return {};
  for (const auto folder : base::split(path, ':')) {
    if (folder.empty()) continue;
    const std::string candidate = std::string(folder) + "/" + name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

std::string canonical_path(const std::string& path) {
  std::error_code error;
  const auto canonical = std::filesystem::canonical(path, error);
  return error ? std::string() : canonical.string();
}

std::string absolute_program(const std::string& program) {
  if (program.find('/') == std::string::npos) return program;
  return std::filesystem::absolute(program).string();
}

std::string work_folder(const std::string& requested, const std::string& stem, std::ostream& err) {
  std::string folder = requested;
  if (folder.empty()) {
    folder = "/tmp/" + stem + ".XXXXXX";
    if (::mkdtemp(folder.data()) == nullptr) folder.clear();
  } else {
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) folder.clear();
  }
  if (folder.empty())
    err << stem << ": cannot create the folder " << (requested.empty() ? "in /tmp" : requested)
        << "\n";
  return folder;
}

std::string cell(double value, int decimals) {
  return value < 0 || std::isnan(value) ? "-" : base::fix(value, decimals);
}

std::string table_line(std::string label, const std::vector<std::string>& cells) {
  label.resize(std::max(label.size(), kLabelColumns), ' ');
  for (const auto& text : cells)
    label += text + std::string(text.size() < kCellColumns ? kCellColumns - text.size() : 1, ' ');
  return label;
}

Process::~Process() { stop(1.0); }

bool Process::start(const std::string& program, const std::vector<std::string>& args,
                    const std::string& working_dir, const std::string& log_stem) {
  if (pid_ > 0) {
    error_ = "already running";
    return false;
  }
  // Everything the child needs is built before fork: the benchmark has threads.
  std::vector<std::string> text = {program};
  text.insert(text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : text) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string out_path = log_stem + ".out";
  const std::string err_path = log_stem + ".err";
  const pid_t pid = ::fork();
  if (pid < 0) {
    error_ = "fork failed";
    return false;
  }
  if (pid == 0) {
    const int out = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0 || ::dup2(out, STDOUT_FILENO) < 0 || ::dup2(err, STDERR_FILENO) < 0 ||
        ::chdir(working_dir.c_str()) != 0)
      ::_exit(127);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  pid_ = pid;
  return true;
}

bool Process::running() {
  if (pid_ <= 0) return false;
  if (::waitpid(pid_, nullptr, WNOHANG) == 0) return true;
  pid_ = -1;
  return false;
}

bool Process::wait_exit(double timeout_s) {
  const double deadline = steady_now_s() + timeout_s;
  while (running()) {
    if (steady_now_s() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

bool Process::stop(double grace_s) {
  if (!running()) return false;
  ::kill(pid_, SIGINT);
  if (wait_exit(grace_s)) return true;
  if (pid_ > 0) ::kill(pid_, SIGTERM);
  if (wait_exit(1.0)) return false;
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
  return false;
}

}  // namespace bench
