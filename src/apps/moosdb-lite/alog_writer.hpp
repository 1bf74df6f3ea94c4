#pragma once
// `--log=FILE`: every NOTIFY the DB accepts, written as pLogger would log it
// (moos::alog_header, moos::format_alog_line; times relative to LOGSTART).
//
// Contract:
// - The file starts with the alog header; LOGSTART is the server's MOOS time at start-up.
// - One line per accepted NOTIFY, in acceptance order: TIME (message time - LOGSTART),
//   VARIABLE, SOURCE, VALUE. Doubles are written in the shortest form that reads back to
//   the same double; strings as they are (a newline becomes a blank, see alog.hpp); binary
//   values as `<binary:N:HEX>` (N bytes in lower-case hex), the form moos-cli prints, so the
//   text file loses nothing.
// - FILE is opened by the rule of every user-named output (base/output_file.hpp, kInPlace): a
//   regular file is created or truncated and grows in place (a reader may follow it), a device
//   or FIFO is written through, a link is followed and stays a link, a folder is refused. The
//   header is written at once, so a full device or a missing FIFO reader fails at start-up.
// - Later write errors are reported once through the log sink; the server keeps serving.

#include <functional>
#include <optional>
#include <string>

#include "base/output_file.hpp"
#include "moos/message.hpp"

namespace moosdb_lite {

class AlogWriter {
 public:
  using LogSink = std::function<void(const std::string&)>;

  AlogWriter() = default;
  ~AlogWriter();
  AlogWriter(const AlogWriter&) = delete;
  AlogWriter& operator=(const AlogWriter&) = delete;

  /// Creates (truncates) `path` and writes the header. False, with `error` filled, if the
  /// file cannot be opened or the header cannot be written.
  bool open(const std::string& path, double logstart_moos_s, LogSink log, std::string* error);
  void write(const moos::Message& msg);
  void flush();
  void close();
  bool is_open() const { return file_.has_value(); }

 private:
  void report(const std::string& problem);

  std::optional<base::OutputFile> file_;
  double logstart_moos_s_ = 0.0;
  bool dirty_ = false;
  bool failed_ = false;
  LogSink log_;
};

}  // namespace moosdb_lite
