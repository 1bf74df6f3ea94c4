// `--log=FILE` writer. See alog_writer.hpp.

#include "alog_writer.hpp"

#include "moos/clock.hpp"

namespace moosdb_lite {

AlogWriter::~AlogWriter() { close(); }

bool AlogWriter::open(const std::string& path, double logstart_moos_s, LogSink log,
                      std::string* error, MoosClock now, moos::AlogFileOptions options) {
  close();
  log_ = std::move(log);
  now_ = now ? std::move(now) : MoosClock([] { return moos::system_clock().unix_now_s(); });
  options.notice = [this](const std::string& text) { report(text); };
  std::string problem;
  file_ = moos::AlogFile::open(path, logstart_moos_s, std::move(options), problem);
  if (!file_) {
    if (error) *error = "--log: " + problem;
    return false;
  }
  lost_ = 0;
  return true;
}

void AlogWriter::report(const std::string& problem) {
  if (log_) log_("warning: --log " + problem);
}

void AlogWriter::write(const moos::Message& msg) {
  if (file_) file_->add(msg, now_());
}

void AlogWriter::flush() {
  if (file_) file_->pump();
}

bool AlogWriter::close() {
  if (!file_) return lost_ == 0;
  std::string problem;
  const bool whole = file_->close(problem);
  lost_ = file_->records_lost();
  if (!whole && log_) log_("error: --log '" + file_->path() + "' is not whole: " + problem);
  file_.reset();
  return whole;
}

}  // namespace moosdb_lite
