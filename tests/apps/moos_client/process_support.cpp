#include "process_support.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

namespace moos::process_test {

namespace {

constexpr double kPollInterval_s = 0.01;
/// How long moosdb-lite may take to start listening.
constexpr double kServerStartTimeout_s = 10.0;

std::string temp_path(const std::string& what) {
  static int counter = 0;
  return "/tmp/moos_client_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) +
         "_" + what;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

double steady_now_s() {
  using namespace std::chrono;
  return duration_cast<duration<double>>(steady_clock::now().time_since_epoch()).count();
}

std::optional<Child> Child::spawn(const std::string& path, const std::vector<std::string>& args) {
  Child c;
  c.out_path_ = temp_path("out");
  c.err_path_ = temp_path("err");
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) return std::nullopt;
  if (pid == 0) {
    // Child: die with the test process, whatever happens to it.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    const int out = ::open(c.out_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int err = ::open(c.err_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (out >= 0) ::dup2(out, 1);
    if (err >= 0) ::dup2(err, 2);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(path.c_str()));
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(path.c_str(), argv.data());
    ::_exit(127);
  }
  c.pid_ = pid;
  return c;
}

Child::Child(Child&& other) noexcept { *this = std::move(other); }

Child& Child::operator=(Child&& other) noexcept {
  if (this != &other) {
    kill_now();
    pid_ = other.pid_;
    reaped_ = other.reaped_;
    out_path_ = std::move(other.out_path_);
    err_path_ = std::move(other.err_path_);
    other.pid_ = -1;
    other.reaped_ = true;
  }
  return *this;
}

Child::~Child() {
  kill_now();
  if (!out_path_.empty()) std::remove(out_path_.c_str());
  if (!err_path_.empty()) std::remove(err_path_.c_str());
}

std::optional<int> Child::wait(double timeout_s) {
  if (pid_ < 0) return std::nullopt;
  const double deadline = steady_now_s() + timeout_s;
  while (true) {
    int status = 0;
    const pid_t r = ::waitpid(pid_, &status, WNOHANG);
    if (r == pid_) {
      reaped_ = true;
      pid_ = -1;
      if (WIFEXITED(status)) return WEXITSTATUS(status);
      return std::nullopt;
    }
    if (steady_now_s() >= deadline) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::duration<double>(kPollInterval_s));
  }
}

void Child::kill_now() {
  if (pid_ < 0 || reaped_) return;
  ::kill(pid_, SIGKILL);
  int status = 0;
  ::waitpid(pid_, &status, 0);
  reaped_ = true;
  pid_ = -1;
}

void Child::stop(double timeout_s) {
  if (pid_ < 0) return;
  ::kill(pid_, SIGTERM);
  if (!wait(timeout_s)) kill_now();
}

std::string Child::stdout_text() const { return read_file(out_path_); }
std::string Child::stderr_text() const { return read_file(err_path_); }

std::optional<Server> Server::start(int port, const std::vector<std::string>& extra) {
  Server s;
  const std::string port_file = temp_path("port");
  std::remove(port_file.c_str());
  std::vector<std::string> args = {"--moos_port=" + std::to_string(port), "--port-file=" + port_file};
  args.insert(args.end(), extra.begin(), extra.end());
  s.child_ = Child::spawn(MOOSDB_LITE_PATH, args);
  if (!s.child_) return std::nullopt;
  const double deadline = steady_now_s() + kServerStartTimeout_s;
  while (steady_now_s() < deadline) {
    std::ifstream in(port_file);
    int p = 0;
    if (in >> p && p > 0) {
      s.port_ = p;
      std::remove(port_file.c_str());
      return s;
    }
    if (s.child_->wait(kPollInterval_s)) break;  // it exited: failed to start
  }
  std::remove(port_file.c_str());
  return std::nullopt;
}

Child run_cli(const std::vector<std::string>& args, double timeout_s, std::optional<int>* exit_code) {
  auto child = Child::spawn(MOOS_CLI_PATH, args);
  if (!child) {
    *exit_code = std::nullopt;
    return std::move(*Child::spawn("/bin/false", {}));
  }
  *exit_code = child->wait(timeout_s);
  return std::move(*child);
}

}  // namespace moos::process_test
