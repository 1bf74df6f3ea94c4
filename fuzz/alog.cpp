// Fuzz target: .alog reading, line by line as hazard_replay and the tools read it: each line is
// classified and parsed, header lines give their LOGSTART, and every entry is formatted and must
// parse back as an entry whose variable and source are the originals escaped for a log
// (base::escape_for_log: a column read from a line holds no blank, so nothing else changes).
// A gap marker's count reads back from the marker written for it, a comment line.

#include <cstdlib>

#include "base/text.hpp"
#include "fuzz_input.hpp"
#include "moos/alog.hpp"
#include "moos/alog_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  for (const std::string_view line : fuzz::lines_of(fuzz::as_text(data, size))) {
    (void)moos::alog_logstart(line);
    if (const auto lost = moos::alog_gap_count(line)) {
      const std::string marker = moos::format_alog_gap(*lost, line);
      if (moos::alog_gap_count(marker) != lost ||
          moos::parse_alog_line(std::string_view(marker).substr(0, marker.size() - 1)).kind !=
              moos::AlogLineKind::kHeader)
        std::abort();
    }
    const moos::AlogParse parsed = moos::parse_alog_line(line);
    if (parsed.kind != moos::AlogLineKind::kEntry) continue;
    std::string again = moos::format_alog_line(parsed.entry);
    if (!again.empty() && again.back() == '\n') again.pop_back();
    const moos::AlogParse reread = moos::parse_alog_line(again);
    const bool same = reread.kind == moos::AlogLineKind::kEntry &&
                      reread.entry.variable == base::escape_for_log(parsed.entry.variable) &&
                      reread.entry.source == base::escape_for_log(parsed.entry.source);
    if (!same)
      std::abort();
  }
  return 0;
}
