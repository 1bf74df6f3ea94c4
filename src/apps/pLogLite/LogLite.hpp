#pragma once
// LogLite: the pLogLite MOOS application, a small logger that writes what it hears as pLogger's
// asynchronous log (.alog), for communities on a real MOOSDB (moosdb-lite logs by itself with
// --log). Format: moos/alog.hpp, the same code moosdb-lite's --log uses.
//
// Contract
// - Configuration (pLogger's names, case-insensitive): `path` (folder, default "."; relative to
//   the current directory, as pLogger), `file` (name without .alog, default "MOOSLog"),
//   `file_timestamp` (default true: `_YYYY_MM_DD_____HH_MM_SS` after the name, local time),
//   `wildcard_logging` (default false: log every variable of every process), `log = VAR @ T`
//   (repeatable: log VAR, at most once per T MOOS seconds; T optional, 0 = every update),
//   `wildcard_omit_pattern = P1, P2` (variables matching one of the patterns are not written),
//   `async_log` (accepted; true is the only mode). Unknown or bad lines are configuration
//   warnings naming file, line and value. Without wildcard logging and without `log` lines
//   nothing would be logged: a configuration warning says so.
// - The file is created (with its folder) at start-up; the header's LOGSTART is the start-up
//   MOOS time. Each message is one line, TIME (message time - LOGSTART, 3 decimals) VARIABLE
//   SOURCE VALUE, in the order mail is handed to the app (sorted by time within a batch).
//   Framework mail the application base consumes (APPCAST_REQ) is not written.
// - The file is flushed every iteration and closed when the app ends. If it cannot be created,
//   start-up fails (exit 1) with a message naming the file: a logger that logs nothing must not
//   look alive. It is opened by the rule of every user-named output (base/output_file.hpp,
//   kInPlace): a regular file grows in place, a device or FIFO named `<file>.alog` is written
//   through, a link is followed and stays a link, a folder is refused; the header is written at
//   once, so a full device or a FIFO nobody reads fails at start-up too.

#include <optional>
#include <string>
#include <vector>

#include "base/output_file.hpp"
#include "mission_app.hpp"

namespace plog_lite {

inline constexpr const char* kAppName = "pLogLite";
/// Iterations only flush the file: 10 MOOS Hz keeps a crash's loss small.
inline constexpr double kDefaultAppTick_hz = 10.0;

moos::AppTraits logger_traits();

/// One `log = VAR @ T` line.
struct LogRequest {
  std::string variable;
  double interval_s = 0.0;
};
std::optional<LogRequest> parse_log_request(std::string_view text);

/// `_YYYY_MM_DD_____HH_MM_SS` of a Unix time, local time zone.
std::string file_time_stamp(double unix_s);

class LogLite final : public mission_app::MissionApp {
 public:
  LogLite();
  ~LogLite() override;

  /// The file being written ("" before start-up).
  const std::string& file_path() const { return file_path_; }
  long lines_written() const { return lines_written_; }

 protected:
  bool on_start_up() override;
  void on_new_mail(const std::vector<moos::Message>& mail) override;
  void on_iterate() override;
  std::string build_report() override;

 private:
  /// Applies one line of the block: "" when accepted, else the configuration warning.
  std::string apply(const moos::ConfigLine& line);
  bool omitted(const std::string& variable) const;
  /// Opens file_path_ and writes the header: "" on success, else the problem.
  std::string open_log(const std::string& name);
  /// One run warning for the first write error (the log keeps what was written before it).
  void write_failed(const std::string& problem);
  void close();

  std::string path_ = ".";
  std::string file_ = "MOOSLog";
  bool file_timestamp_ = true;
  bool wildcard_logging_ = false;
  std::vector<LogRequest> requests_;
  std::vector<std::string> omit_patterns_;

  std::optional<base::OutputFile> out_;
  std::string file_path_;
  long lines_written_ = 0;
  bool write_failed_ = false;
};

}  // namespace plog_lite
