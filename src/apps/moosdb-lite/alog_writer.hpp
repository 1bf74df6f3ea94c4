#pragma once
// `--log=FILE`: every NOTIFY the DB accepts, written as pLogger would log it, through
// moos::AlogFile (moos/alog_file.hpp), so that the server never waits for its log.
//
// Contract:
// - The file starts with the alog header; LOGSTART is the server's MOOS time at start-up.
// - One line per accepted NOTIFY, in acceptance order: TIME (message time - LOGSTART),
//   VARIABLE, SOURCE, VALUE. Doubles are written in the shortest form that reads back to
//   the same double; strings as they are (a newline becomes a blank, see alog.hpp); binary
//   values as `<binary:N:HEX>` (N bytes in lower-case hex), the form moos-cli prints, so the
//   text file loses nothing. A message time that is not finite or beyond a log reader's
//   ±1e10 s of the server's clock is logged at the server's clock (moos/alog_file.hpp).
// - FILE is opened by the rule of every user-named output (base/output_file.hpp, kInPlace): a
//   regular file is created or truncated and grows in place (a reader may follow it), a device
//   or FIFO is written through, a link is followed and stays a link, a folder is refused. The
//   header is written at once, so a full device or a missing FIFO reader fails at start-up.
// - write() only queues; flush() (every poll round) writes what the file takes without
//   waiting. A FIFO whose reader stalls, a full disk or a deleted file never stop the server:
//   records are dropped and counted, a gap marker in the file says how many, a deleted file is
//   created again (moos/alog_file.hpp). Each problem is reported once through the log sink.
// - close() writes what is left (a stalled FIFO's reader gets up to
//   moos::AlogFileOptions::close_wait_s) and reports the records lost: false when any were.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "moos/alog_file.hpp"
#include "moos/message.hpp"

namespace moosdb_lite {

class AlogWriter {
 public:
  using LogSink = std::function<void(const std::string&)>;
  /// The server's MOOS time now.
  using MoosClock = std::function<double()>;

  AlogWriter() = default;
  ~AlogWriter();
  AlogWriter(const AlogWriter&) = delete;
  AlogWriter& operator=(const AlogWriter&) = delete;

  /// Creates (truncates) `path` and writes the header. False, with `error` filled, if the
  /// file cannot be opened or the header cannot be written. `now` is the clock message times
  /// are checked against (empty: the system clock, unwarped).
  bool open(const std::string& path, double logstart_moos_s, LogSink log, std::string* error,
            MoosClock now = {}, moos::AlogFileOptions options = {});
  void write(const moos::Message& msg);
  void flush();
  /// Writes what is left and closes: false when records were lost (reported through the sink).
  bool close();
  bool is_open() const { return file_.has_value(); }
  std::uint64_t records_lost() const { return lost_; }

 private:
  void report(const std::string& problem);

  std::optional<moos::AlogFile> file_;
  MoosClock now_;
  LogSink log_;
  std::uint64_t lost_ = 0;
};

}  // namespace moosdb_lite
