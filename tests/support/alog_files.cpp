#include "alog_files.hpp"

#include <sstream>

namespace test_support {

namespace {

Alog parse_alog(const std::string& text) {
  Alog log;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (const auto start = moos::alog_logstart(line)) log.logstart_s = *start;
    const auto parsed = moos::parse_alog_line(line);
    if (parsed.kind == moos::AlogLineKind::kEntry) log.entries.push_back(parsed.entry);
  }
  return log;
}

}  // namespace

std::vector<moos::AlogEntry> alog_entries(const std::string& text) { return parse_alog(text).entries; }

Alog read_alog(const fs::path& path) { return parse_alog(read_file(path)); }

}  // namespace test_support
