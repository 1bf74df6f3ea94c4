#pragma once
// Diagnostics that never block: what a program writes to standard error (and a MOOS app's
// terminal report on standard output) must not stop it when nobody reads the other end, a
// stalled pipe, a terminal paused with Ctrl-S, or a full disk.
//
// Contract:
// - DiagnosticWriter::write(text) writes `text` to its descriptor without ever waiting: in
//   pieces of at most PIPE_BUF bytes, each only when the descriptor can take it at once (a
//   socket is written with MSG_DONTWAIT; anything else after a zero-timeout poll). What cannot
//   be written now is dropped whole and its lines are counted; the next write that gets through
//   starts with one line saying how many lines were lost. Safe from several threads.
// - install_nonblocking_diagnostics() routes std::cerr and C's stderr (and, when asked, std::cout
//   and stdout) through standard_writer(2) (and (1)), line by line, for the rest of the
//   process. It first makes sure descriptors 0, 1 and 2 are open (base/descriptors.hpp), so
//   that no pipe, socket or log file the program opens later can land on them and receive its
//   diagnostics.
// - Standard output as a program's data (gen_hazards, hazard_replay) is never routed here: data
//   is not to be dropped.
#include <cstdint>
#include <mutex>
#include <string>
#include <string_view>

namespace base {

/// Writes one descriptor's diagnostics without waiting (see the contract).
class DiagnosticWriter {
 public:
  /// `stream_name` names the descriptor in the line about dropped lines ("standard error").
  DiagnosticWriter(int fd, std::string stream_name);

  /// False when any of `text` was dropped. Safe from several threads.
  bool write(std::string_view text);
  /// Lines dropped so far, those already reported included.
  std::uint64_t dropped_lines() const;

 private:
  std::string_view write_now(std::string_view text, bool& line_open);
  bool drop(std::string_view text);  ///< counts its lines as dropped; false

  const int fd_;
  const std::string stream_name_;
  mutable std::mutex mutex_;
  std::uint64_t dropped_lines_ = 0;     ///< in all
  std::uint64_t unreported_lines_ = 0;  ///< since the last line that said so
  bool line_open_ = false;              ///< the last byte written was not a newline
};

/// Which standard streams install_nonblocking_diagnostics routes.
enum class DiagnosticStreams { kStderr, kStdoutAndStderr };

/// The writer of descriptor 1 (standard output) or 2 (standard error).
DiagnosticWriter& standard_writer(int fd);

/// Routes the streams named (see the contract). Call once, early in main.
void install_nonblocking_diagnostics(DiagnosticStreams streams = DiagnosticStreams::kStderr);

}  // namespace base
