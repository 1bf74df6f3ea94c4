// `--log=FILE` writer. See alog_writer.hpp.

#include "alog_writer.hpp"

#include <cerrno>
#include <cstring>

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
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr) {
    if (error) *error = "cannot write log file " + path + ": " + std::strerror(errno);
    return false;
  }
  path_ = path;
  logstart_moos_s_ = logstart_moos_s;
  log_ = std::move(log);
  failed_ = false;
  const std::string header = moos::alog_header(file_name_of(path), logstart_moos_s);
  std::fwrite(header.data(), 1, header.size(), file_);
  dirty_ = true;
  return true;
}

void AlogWriter::write(const moos::Message& msg) {
  if (file_ == nullptr || failed_) return;
  const std::string line = moos::format_alog_line(
      moos::alog_entry(msg, logstart_moos_s_));
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size()) {
    failed_ = true;
    if (log_) log_("log file " + path_ + ": write failed (" + std::strerror(errno) +
                   "); logging stopped");
  }
  dirty_ = true;
}

void AlogWriter::flush() {
  if (file_ == nullptr || !dirty_) return;
  std::fflush(file_);
  dirty_ = false;
}

void AlogWriter::close() {
  if (file_ == nullptr) return;
  std::fclose(file_);
  file_ = nullptr;
}

}  // namespace moosdb_lite
