#pragma once
// .alog text as the tests read it back: what a program logged (moosdb-lite's --log, pLogLite,
// hazard_replay's output, a mission's log), parsed with libmoos's own line parser.

#include <string>
#include <vector>

#include "moos/alog.hpp"
#include "scratch_files.hpp"

namespace test_support {

struct Alog {
  double logstart_s = 0.0;               ///< the header's LOGSTART (0 when there is none)
  std::vector<moos::AlogEntry> entries;  ///< in file order; header and other lines skipped
};

/// The entries of .alog text.
std::vector<moos::AlogEntry> alog_entries(const std::string& text);
/// An .alog file ("" when it cannot be read: no entries).
Alog read_alog(const fs::path& path);

}  // namespace test_support
