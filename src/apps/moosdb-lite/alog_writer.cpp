// `--log=FILE` writer. See alog_writer.hpp.

#include "alog_writer.hpp"

#include "moos/alog.hpp"

namespace moosdb_lite {

namespace {

std::string file_name_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

AlogWriter::~AlogWriter() { close(); }

bool AlogWriter::open(const std::string& path, double logstart_moos_s, LogSink log,
                      std::string* error) {
  close();
  std::string problem;
  file_ = base::OutputFile::open(path, base::OutputMode::kInPlace, problem);
  const std::string header = moos::alog_header(file_name_of(path), logstart_moos_s);
  if (!file_ || !file_->write(header, problem) || !file_->flush(problem)) {
    if (error) *error = "--log: " + problem;
    file_.reset();
    return false;
  }
  logstart_moos_s_ = logstart_moos_s;
  log_ = std::move(log);
  failed_ = false;
  dirty_ = false;
  return true;
}

void AlogWriter::report(const std::string& problem) {
  if (failed_) return;
  failed_ = true;
  if (log_) log_("--log: " + problem + "; logging stopped");
}

void AlogWriter::write(const moos::Message& msg) {
  if (!file_ || failed_) return;
  const std::string line = moos::format_alog_line(moos::alog_entry(msg, logstart_moos_s_));
  std::string problem;
  if (!file_->write(line, problem)) report(problem);
  dirty_ = true;
}

void AlogWriter::flush() {
  if (!file_ || !dirty_ || failed_) return;
  std::string problem;
  if (!file_->flush(problem)) report(problem);
  dirty_ = false;
}

void AlogWriter::close() {
  if (!file_) return;
  std::string problem;
  if (!file_->commit(problem)) report(problem);
  file_.reset();
}

}  // namespace moosdb_lite
