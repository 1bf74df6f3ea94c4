#pragma once
// Test helpers: a scratch folder, reading a file, and running the gen_hazards binary
// (arguments in, exit code and both output streams out).
//
// Contract of run_program: the child's stdout and stderr go to private temporary files (no pipe can fill up),
// it dies with the test process (PR_SET_PDEATHSIG), and it is killed at `deadline_s`, so a hang
// shows as `timed_out` instead of a stuck suite.

#include <string>
#include <vector>

namespace gen_hazards::test {

struct RunResult {
  int exit_code = -1;      ///< -1 when killed or not started
  bool timed_out = false;  ///< still running at the deadline (then killed)
  std::string out;         ///< standard output
  std::string err;         ///< standard error
};

/// Runs `binary` with `args` (argv[0] is `binary`).
RunResult run_program(const std::string& binary, const std::vector<std::string>& args,
                      double deadline_s);

/// A fresh folder under the test's temporary directory, removed (with its files) at the end.
class ScratchDir {
 public:
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::string& path() const { return path_; }
  /// Names of the files in the folder (no "." or "..").
  std::vector<std::string> entries() const;

 private:
  std::string path_;
};

/// The whole content of a file ("" if it cannot be read).
std::string read_file(const std::string& path);

}  // namespace gen_hazards::test
