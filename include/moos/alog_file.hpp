#pragma once
// A .alog written while a program runs (pLogLite, moosdb-lite --log): whole records, never a
// wait, and a log that says what it is missing.
//
// Contract:
// - open() opens `path` by the rule of every user-named output (base/output_file.hpp,
//   kInPlace) and writes the header (alog_header) at once, so a file that cannot take it is an
//   error at start-up. From then on the file is written without waiting (O_NONBLOCK).
// - add() turns a message into one line (alog_entry, times relative to LOGSTART) and queues
//   it; nothing is written there. A message time that is not finite or lies more than
//   kAlogMaxClockSkew_s from the writer's own clock is logged at the writer's clock instead,
//   counted in times_clamped(), with a notice the first time.
// - pump() writes what the file takes now and never waits: while a FIFO's reader stalls the
//   records wait in the queue, up to max_queued_bytes (one record is always taken); records
//   that do not fit are dropped and counted.
// - Records reach the file whole or not at all: the part of a record a failed write left is
//   cut off again (a regular file is truncated back to the record's start); where that cannot
//   be done (a device) the next line starts with a newline, so the fragment stands alone. A
//   FIFO is written in pieces of whole lines of at most PIPE_BUF bytes, which a pipe takes
//   whole or not at all, so a reader that stalls holds whole lines (but for a longer line).
// - After a write error (a full disk, a file size limit, a reader gone) the queued records are
//   lost and counted, and so is every record added until writing is tried again,
//   retry_interval_s later. What the file holds next is a gap marker, a comment line every
//   reader skips (alog.hpp): `%% GAP: N records lost (REASON)`; then writing goes on.
// - A regular file deleted while it is written (its folder too) is seen at the next pump()
//   with something to write (fstat finds no link left): folder and file are created again, with
//   the same header (the same LOGSTART) and a gap marker counting the records that went with
//   the deleted file (they count as lost). If that fails, records are lost and counted, and it
//   is tried again retry_interval_s later.
// - close() writes what is queued, waiting at most close_wait_s for a FIFO's reader, counts
//   what is left as lost, ends the file with a gap marker when it can, then syncs and closes
//   it. False when a record was lost (records_lost() > 0) or closing failed.
// - Each new problem (a failure, a full queue, a deletion, the first clamped time) and each
//   recovery goes once to the `notice` sink, as one line naming the file.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "moos/alog.hpp"
#include "moos/message.hpp"

namespace moos {

/// How far (MOOS seconds) a message time may lie from the writer's own clock: as far as a reader
/// places a line (kMaxAlogTimeS). A time some clock could have written is logged as it is, even
/// years off (a client whose clock is set otherwise, old stamps replayed): only a time no reader
/// could place is not.
inline constexpr double kAlogMaxClockSkew_s = kMaxAlogTimeS;

/// Whether a writer whose clock reads `now_s` logs `message_time_s` as it is (see the contract).
bool alog_time_is_sane(double message_time_s, double now_s);

/// A gap marker line, newline-terminated: `%% GAP: N records lost (REASON)`.
std::string format_alog_gap(std::uint64_t lost, std::string_view reason);
/// The N of a gap marker line, if the line is one.
std::optional<std::uint64_t> alog_gap_count(std::string_view line);

struct AlogFileOptions {
  /// Memory for records held while the file does not take them (a FIFO whose reader stalls):
  /// their bytes and their place in the queue.
  std::size_t max_queued_bytes = std::size_t{16} << 20;
  /// Real seconds between attempts after a write error or a failed re-creation.
  double retry_interval_s = 1.0;
  /// Real seconds close() waits for a FIFO's reader to take what is queued.
  double close_wait_s = 1.0;
  /// Where notices go (see the contract); none: nowhere.
  std::function<void(const std::string&)> notice;
};

class AlogFile {
 public:
  /// The file at `path` with its header written, or nullopt with `problem` set.
  static std::optional<AlogFile> open(const std::string& path, double logstart_s,
                                      AlogFileOptions options, std::string& problem);
  AlogFile(AlogFile&&) noexcept;
  /// Closes this file first (close()), then takes the other.
  AlogFile& operator=(AlogFile&&) noexcept;
  AlogFile(const AlogFile&) = delete;
  AlogFile& operator=(const AlogFile&) = delete;
  /// close(), if it was not called.
  ~AlogFile();

  /// Queues the line of `msg`; `now_s` is the writer's clock (MOOS seconds).
  void add(const Message& msg, double now_s);
  /// Queues one line (newline-terminated) as it is.
  void add_line(std::string line);
  /// Writes what the file takes now (see the contract).
  void pump();
  /// See the contract. `problem` names the last problem when it returns false.
  bool close(std::string& problem);

  const std::string& path() const;
  std::uint64_t records_written() const;
  std::uint64_t records_lost() const;
  std::uint64_t times_clamped() const;
  /// How often the file was created again after it was deleted.
  std::uint64_t reopened() const;
  /// The memory the queued records hold (see max_queued_bytes).
  std::size_t queued_bytes() const;
  /// The last problem met ("" when none).
  const std::string& last_problem() const;

 private:
  class Impl;
  explicit AlogFile(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace moos
