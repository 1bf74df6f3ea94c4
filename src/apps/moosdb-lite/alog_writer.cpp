// `--log=FILE` writer. See alog_writer.hpp.

#include "alog_writer.hpp"

#include <cerrno>
#include <charconv>
#include <cstring>

#include "moos/alog.hpp"

namespace moosdb_lite {

namespace {

constexpr char kHexDigits[] = "0123456789abcdef";
/// Enough for the longest shortest-form double ("-2.2250738585072014e-308").
constexpr std::size_t kDoubleTextBytes = 32;

std::string file_name_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

std::string alog_value(const moos::Message& msg) {
  switch (msg.data_type) {
    case moos::data_type::kDouble: {
      char text[kDoubleTextBytes];
      const auto [end, error] = std::to_chars(text, text + sizeof text, msg.dval);
      return error == std::errc() ? std::string(text, end) : std::string("nan");
    }
    case moos::data_type::kBinary: {
      std::string out = "<binary:" + std::to_string(msg.sval.size()) + ":";
      for (const unsigned char c : msg.sval) {
        out.push_back(kHexDigits[c >> 4]);
        out.push_back(kHexDigits[c & 0x0f]);
      }
      return out + ">";
    }
    default:
      return msg.sval;
  }
}

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
      moos::AlogEntry{msg.time - logstart_moos_s_, msg.key, msg.source, alog_value(msg)});
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
