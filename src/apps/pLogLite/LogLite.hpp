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
// - The file is written through moos::AlogFile (moos/alog_file.hpp): mail is queued, every
//   iteration writes what the file takes without waiting, and the file is closed when the app
//   ends. If it cannot be created, start-up fails (exit 1) with a message naming the file: a
//   logger that logs nothing must not look alive. It is opened by the rule of every user-named
//   output (base/output_file.hpp, kInPlace): a regular file grows in place, a device or FIFO
//   named `<file>.alog` is written through, a link is followed and stays a link, a folder is
//   refused; the header is written at once, so a full device or a FIFO nobody reads fails at
//   start-up too.
// - A log is whole or says what it is missing: records are written whole; after a write error
//   (a full disk) the records lost are counted and a gap marker line `%% GAP: N records lost
//   (REASON)` stands where they are missing; a file deleted while it is written (its folder
//   too) is created again, with its header and a gap marker; a message time that is not finite
//   or beyond a log reader's ±1e10 s of the app's clock is logged at the app's clock. Each such
//   problem is a run warning and a line on standard error; the report counts records written
//   and lost.
// - The outcome (records lost) goes to the LogOutcome given at construction when the file is
//   closed; main exits kExitLogNotWhole when records were lost.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mission_app.hpp"
#include "moos/alog_file.hpp"

namespace plog_lite {

inline constexpr const char* kAppName = "pLogLite";
/// Iterations only flush the file: 10 MOOS Hz keeps a crash's loss small.
inline constexpr double kDefaultAppTick_hz = 10.0;
/// Exit code after a stop when records were lost (the log is not whole).
inline constexpr int kExitLogNotWhole = 3;

/// What the log came to, filled in when the file is closed (the app may be gone by then).
struct LogOutcome {
  std::uint64_t records_written = 0;
  std::uint64_t records_lost = 0;
  std::string problem;  ///< why it is not whole ("" when it is)
};

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
  explicit LogLite(std::shared_ptr<LogOutcome> outcome = nullptr);
  ~LogLite() override;

  /// The file being written ("" before start-up).
  const std::string& file_path() const { return file_path_; }
  std::uint64_t records_written() const { return log_ ? log_->records_written() : 0; }
  std::uint64_t records_lost() const { return log_ ? log_->records_lost() : 0; }

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
  std::string open_log();
  /// A problem of the log (moos/alog_file.hpp): a run warning and a line on standard error.
  void log_notice(const std::string& text);
  void close();

  std::string path_ = ".";
  std::string file_ = "MOOSLog";
  bool file_timestamp_ = true;
  bool wildcard_logging_ = false;
  std::vector<LogRequest> requests_;
  std::vector<std::string> omit_patterns_;

  std::optional<moos::AlogFile> log_;
  std::string file_path_;
  std::shared_ptr<LogOutcome> outcome_;
  bool closing_ = false;  ///< notices while closing go to standard error only
};

}  // namespace plog_lite
