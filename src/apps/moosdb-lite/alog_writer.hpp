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
// - Write errors are reported once through the log sink; the server keeps serving.

#include <cstdio>
#include <functional>
#include <string>

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
  /// file cannot be opened.
  bool open(const std::string& path, double logstart_moos_s, LogSink log, std::string* error);
  void write(const moos::Message& msg);
  void flush();
  void close();
  bool is_open() const { return file_ != nullptr; }

 private:
  std::FILE* file_ = nullptr;
  std::string path_;
  double logstart_moos_s_ = 0.0;
  bool dirty_ = false;
  bool failed_ = false;
  LogSink log_;
};

}  // namespace moosdb_lite
