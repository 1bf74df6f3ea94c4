// Fuzz target: .alog reading, line by line as hazard_replay and the tools read it: each line is
// classified and parsed, header lines give their LOGSTART, and every entry is formatted and must
// parse back as an entry whose variable and source are the originals escaped for a log
// (base::escape_for_log: a column read from a line holds no blank, so nothing else changes).
// An entry's time is finite and within kMaxAlogTimeS (a replay of it ends); any other number is
// kUnusableTime, which readers skip and count. The same bytes read from a file by
// base::LineStream (the streamed readers' splitter, with a 64-byte bound) give the same lines,
// less those over the bound, which it counts.
// A gap marker's count reads back from the marker written for it, a comment line.

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

#include "base/line_stream.hpp"
#include "base/text.hpp"
#include "fuzz_input.hpp"
#include "moos/alog.hpp"
#include "moos/alog_file.hpp"

namespace {

constexpr std::size_t kLineBound = 64;

// The input as a file (one per fuzzing process, removed when it exits) read by LineStream.
void check_line_stream(std::string_view text) {
  static const std::string path = "/tmp/hazard-fuzz-alog-" + std::to_string(::getpid());
  static const struct Remove {
    ~Remove() { std::remove(path.c_str()); }
  } remover;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(text.data(), static_cast<std::streamsize>(text.size()));
  base::Result<base::LineStream> opened = base::LineStream::open(path, kLineBound);
  if (!opened) std::abort();
  base::LineStream& stream = *opened.value;
  std::size_t number = 0;
  std::size_t long_lines = 0;
  for (const std::string_view line : fuzz::lines_of(text)) {
    ++number;
    if (line.size() > kLineBound) {
      ++long_lines;
      continue;
    }
    const std::optional<std::string_view> read = stream.next();
    if (!read || *read != line || stream.line_number() != number) std::abort();
  }
  if (stream.next() || stream.long_lines() != long_lines) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  check_line_stream(fuzz::as_text(data, size));
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
    if (parsed.kind == moos::AlogLineKind::kUnusableTime && parsed.error.empty()) std::abort();
    if (parsed.kind != moos::AlogLineKind::kEntry) continue;
    if (!(std::fabs(parsed.entry.time_s) <= moos::kMaxAlogTimeS)) std::abort();
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
