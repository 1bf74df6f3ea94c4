#include "server_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

namespace moosdb_lite::test {

namespace {

constexpr auto kPollPeriod = std::chrono::milliseconds(10);

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}


// fork + exec with stdout/stderr redirected to files; the child dies with its parent.
pid_t spawn(const std::vector<std::string>& args, const std::string& out_path,
            const std::string& err_path) {
  std::vector<char*> argv;
  std::string program = MOOSDB_LITE_PATH;
  argv.push_back(program.data());
  std::vector<std::string> copy = args;
  for (auto& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    const int out = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out >= 0) ::dup2(out, STDOUT_FILENO);
    if (err >= 0) ::dup2(err, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    std::_Exit(127);
  }
  return pid;
}

// Waits for `pid` up to `timeout_s`; returns the exit status, or nullopt-like -2 on timeout.
int wait_for_exit(pid_t pid, double timeout_s) {
  const double deadline = now_s() + timeout_s;
  for (;;) {
    int status = 0;
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (r < 0) return -1;
    if (now_s() > deadline) return -2;
    std::this_thread::sleep_for(kPollPeriod);
  }
}

}  // namespace

ScopedDir::ScopedDir() {
  std::string pattern = ::testing::TempDir() + "/moosdb_lite_XXXXXX";
  if (::mkdtemp(pattern.data()) == nullptr) {
    ADD_FAILURE() << "cannot create a temporary folder in " << ::testing::TempDir();
    return;
  }
  path_ = pattern;
}

ScopedDir::~ScopedDir() {
  std::error_code ignored;
  if (!path_.empty()) std::filesystem::remove_all(path_, ignored);
}

double now_s() {
  using namespace std::chrono;
  return duration<double>(system_clock::now().time_since_epoch()).count();
}

ServerProcess::ServerProcess(const std::vector<std::string>& extra_args) {
  const std::string port_file = dir_.path() + "/port";
  stderr_path_ = dir_.path() + "/stderr.txt";
  std::vector<std::string> args = {"--moos_port=0", "--port-file=" + port_file};
  args.insert(args.end(), extra_args.begin(), extra_args.end());
  pid_ = spawn(args, dir_.path() + "/stdout.txt", stderr_path_);
  const double deadline = now_s() + kStartTimeout_s;
  while (now_s() < deadline) {
    const std::string text = read_file(port_file);
    if (!text.empty() && text.back() == '\n') {
      port_ = std::atoi(text.c_str());
      return;
    }
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      ADD_FAILURE() << "moosdb-lite exited at start-up: " << stderr_text();
      return;
    }
    std::this_thread::sleep_for(kPollPeriod);
  }
  ADD_FAILURE() << "moosdb-lite did not write its port within " << kStartTimeout_s << " s";
}

ServerProcess::~ServerProcess() { stop(); }

int ServerProcess::stop() {
  if (pid_ <= 0) return -1;
  ::kill(pid_, SIGTERM);
  int status = wait_for_exit(pid_, kStopTimeout_s);
  if (status == -2) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
    status = -1;
  }
  pid_ = -1;
  return status;
}

std::string ServerProcess::stderr_text() const { return read_file(stderr_path_); }

bool ServerProcess::wait_for_log(const std::string& fragment, double timeout_s) const {
  const double deadline = now_s() + timeout_s;
  do {
    if (stderr_text().find(fragment) != std::string::npos) return true;
    std::this_thread::sleep_for(kPollPeriod);
  } while (now_s() < deadline);
  return false;
}

int run_server_to_exit(const std::vector<std::string>& args, std::string* out, std::string* err) {
  const ScopedDir dir;
  const pid_t pid = spawn(args, dir.path() + "/out.txt", dir.path() + "/err.txt");
  int status = wait_for_exit(pid, kStartTimeout_s);
  if (status == -2) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
  }
  if (out) *out = read_file(dir.path() + "/out.txt");
  if (err) *err = read_file(dir.path() + "/err.txt");
  return status;
}

}  // namespace moosdb_lite::test
