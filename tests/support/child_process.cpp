#include "child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>
#include <utility>

namespace test_support {

namespace {

/// How often a wait looks whether the child has finished.
constexpr std::chrono::milliseconds kPollInterval{2};
constexpr const char* kStdoutFile = "stdout.txt";
constexpr const char* kStderrFile = "stderr.txt";
constexpr const char* kDiscard = "/dev/null";

/// The child's side of spawn: only async-signal-safe calls (the test process may have threads),
/// so every string was built before fork.
[[noreturn]] void exec_child(pid_t parent, const char* out_path, const char* err_path,
                             const char* working_dir, const rlim_t* max_file_bytes,
                             char* const* argv) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (max_file_bytes != nullptr) {
    rlimit limit{};
    ::getrlimit(RLIMIT_FSIZE, &limit);
    limit.rlim_cur = *max_file_bytes;
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(kExecFailed);
  }
  if (::getppid() != parent) ::_exit(kExecFailed);  // the parent died before the request
  const int out = ::open(out_path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
  const int err = ::open(err_path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
  if (out < 0 || err < 0 || ::dup2(out, STDOUT_FILENO) < 0 || ::dup2(err, STDERR_FILENO) < 0)
    ::_exit(kExecFailed);
  if (working_dir != nullptr && ::chdir(working_dir) != 0) ::_exit(kExecFailed);
  ::execv(argv[0], argv);
  ::_exit(kExecFailed);
}

}  // namespace

double steady_now_s() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

std::optional<Child> Child::spawn(const std::string& program, const std::vector<std::string>& args,
                                  const SpawnOptions& options) {
  Child child{ScratchDir("child")};
  const std::string out_path = options.keep_output ? (child.dir_ / kStdoutFile).string() : kDiscard;
  const std::string err_path = options.keep_output ? (child.dir_ / kStderrFile).string() : kDiscard;
  std::vector<std::string> argv_text = {program};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  const char* working_dir = options.working_dir.empty() ? nullptr : options.working_dir.c_str();
  const rlim_t max_file_bytes = options.max_file_bytes.value_or(0);
  const rlim_t* limit = options.max_file_bytes ? &max_file_bytes : nullptr;

  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) return std::nullopt;
  if (pid == 0)
    exec_child(parent, out_path.c_str(), err_path.c_str(), working_dir, limit, argv.data());
  child.pid_ = pid;
  return child;
}

Child::Child(Child&& other) noexcept
    : dir_(std::move(other.dir_)), pid_(std::exchange(other.pid_, -1)) {}

Child& Child::operator=(Child&& other) noexcept {
  if (this != &other) {
    kill_now();
    dir_ = std::move(other.dir_);
    pid_ = std::exchange(other.pid_, -1);
  }
  return *this;
}

Child::~Child() { kill_now(); }

std::optional<int> Child::wait(double timeout_s) {
  const double deadline = steady_now_s() + timeout_s;
  while (running()) {
    int status = 0;
    const pid_t r = ::waitpid(pid_, &status, WNOHANG);
    if (r == pid_) {
      pid_ = -1;
      if (!WIFEXITED(status)) return std::nullopt;
      return WEXITSTATUS(status);
    }
    if (r < 0) {  // no such child any more: nothing left to wait for
      pid_ = -1;
      return std::nullopt;
    }
    if (steady_now_s() >= deadline) return std::nullopt;
    std::this_thread::sleep_for(kPollInterval);
  }
  return std::nullopt;
}

void Child::kill_now() {
  if (!running()) return;
  ::kill(pid_, SIGKILL);
  ::waitpid(pid_, nullptr, 0);
  pid_ = -1;
}

std::optional<int> Child::stop(double timeout_s) {
  if (!running()) return std::nullopt;
  ::kill(pid_, SIGTERM);
  const std::optional<int> code = wait(timeout_s);
  kill_now();
  return code;
}

std::string Child::stdout_text() const { return read_file(dir_ / kStdoutFile); }
std::string Child::stderr_text() const { return read_file(dir_ / kStderrFile); }

RunResult run_program(const std::string& program, const std::vector<std::string>& args,
                      double deadline_s, const SpawnOptions& options) {
  RunResult result;
  std::optional<Child> child = Child::spawn(program, args, options);
  if (!child) return result;
  result.exit_code = child->wait(deadline_s);
  result.timed_out = child->running();
  child->kill_now();
  result.out = child->stdout_text();
  result.err = child->stderr_text();
  return result;
}

}  // namespace test_support
