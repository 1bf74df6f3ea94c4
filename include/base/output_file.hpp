#pragma once
// Writing a file the user names (--output, --log, --port-file, a logger's .alog): one rule for
// every program, so that no program replaces a device, a FIFO or a link with a regular file.
//
// Contract (OutputFile::open, by what the path names when it is opened):
// - A regular file, or nothing yet: with OutputMode::kReplace the bytes go to a new temporary
//   file in the same folder (`<FILE>.tmp.<pid>.<n>`), which commit() flushes to disk (fsync)
//   and renames over FILE, so a reader sees the old file or the whole new one, never half of
//   it; until commit() nothing at FILE changes, and an OutputFile dropped without commit()
//   removes its temporary. A file that existed keeps its permission bits (not its owner, nor
//   its other hard links, which keep the old content); a new one gets 0666 minus the umask, as
//   from a shell's redirection. With OutputMode::kInPlace (a log that grows
//   while it runs, which a reader may follow) FILE itself is created or truncated at open.
// - A symbolic link: the link is followed (a chain of them too, and a relative target is taken
//   from the link's folder) and the rule is applied to the path it leads to, so the link stays
//   a link and the file it names gets the bytes; a link to nothing yet creates that file.
// - A character device (/dev/null, /dev/full, a terminal) or a FIFO: written through, as a
//   shell's `>` would: opened for writing without O_CREAT or O_TRUNC, never renamed over,
//   never removed. A FIFO is opened non-blocking so that a FIFO nobody reads cannot hang the
//   program: it waits up to kFifoReaderWait_s for a reader (one started beside the program may
//   come a moment late), then fails with "no process is reading the FIFO". Once open, writes
//   block as in any pipe. A reader that goes away raises SIGPIPE, as for any pipe, unless the
//   program ignores it (every MOOS app does: moos::run_app), when the write fails with EPIPE.
// - A directory, a block device, a socket: refused at open, naming the path and the kind.
// Every problem is one message naming the path the user gave (and the file a link leads to):
// "cannot write '/dev/full': No space left on device". Writes are buffered (kBufferBytes), so a
// write error may surface at the next write, at flush() or at commit(): the caller must check
// commit(), which reports the first error; a program then exits non-zero.

#include <cstddef>
#include <streambuf>
#include <string>
#include <string_view>

#include "base/result.hpp"

namespace base {

/// How an OutputFile writes a regular file (devices and FIFOs are always written through).
enum class OutputMode {
  kReplace,  ///< a temporary file renamed over the target by commit(): all or nothing
  kInPlace,  ///< the target itself, truncated at open: a log that grows while it is written
};

/// How long OutputFile::open waits for a process to open a FIFO for reading.
inline constexpr double kFifoReaderWait_s = 5.0;

class OutputFile {
 public:
  /// Bytes gathered before they are written (a log writes a line at a time).
  static constexpr std::size_t kBufferBytes = std::size_t{64} * 1024;

  /// The file to write at `path` by the rule above, or why it cannot be written.
  static Result<OutputFile> open(const std::string& path, OutputMode mode);
  OutputFile(OutputFile&& other) noexcept;
  OutputFile& operator=(OutputFile&& other) noexcept;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  /// Without commit(): closes, and removes a temporary file (the target stays as it was).
  ~OutputFile();

  /// Buffers `bytes`; fails once a write has failed (and on every later call, the same way).
  Result<void> write(std::string_view bytes);
  /// Hands the buffered bytes to the file (a log's periodic flush).
  Result<void> flush();
  /// Flushes, syncs a regular file to disk, closes and (kReplace) renames the temporary over
  /// the target. After it, nothing more can be written. Fails on any error, the first one a
  /// write met included; a failed kReplace leaves the target as it was.
  Result<void> commit();

  /// The path as the user gave it.
  const std::string& path() const { return path_; }
  /// Whether the file is written through (a device or a FIFO) rather than a regular file.
  bool written_through() const { return through_; }
  /// The open descriptor (-1 once closed), for a writer that does its own writing
  /// (moos::AlogFile: non-blocking writes of whole records). Such a writer never calls write()
  /// or flush(); commit() still syncs and closes the file.
  int descriptor() const { return fd_; }

 private:
  OutputFile() = default;
  /// Opens target_ by the rule, or says why not.
  Result<void> open_target(OutputMode mode);
  Result<void> check_opened(OutputMode mode);
  Result<void> fail(const std::string& reason);
  void discard();

  int fd_ = -1;
  std::string path_;        // as given
  std::string target_;      // after following links
  std::string temporary_;   // kReplace of a regular file: renamed over target_ by commit()
  std::string buffer_;
  std::string error_;       // the first failure, repeated by every later call
  bool through_ = false;
};

/// An OutputFile as a std::ostream's buffer, for a writer that takes a stream (hazard_replay's
/// postings). A failed write sets the stream's badbit; the file's commit() says why.
class OutputFileBuffer : public std::streambuf {
 public:
  explicit OutputFileBuffer(OutputFile& file) : file_(file) {}

 protected:
  int_type overflow(int_type c) override;
  std::streamsize xsputn(const char* bytes, std::streamsize count) override;
  int sync() override;

 private:
  OutputFile& file_;
};

/// The whole of `text` written to `path` by the rule above (kReplace), or why not. For programs
/// that write their output at once (gen_hazards, --port-file).
Result<void> write_output_file(const std::string& path, std::string_view text);

}  // namespace base
