#pragma once
// Reading a whole input file, bounded and without surprises ("Special files").
//
// Contract (read_file_text; WholeFile below also reads a pipe, for hazard_replay's logs):
// - Only a regular file is read. A directory, FIFO, socket or device (/dev/zero) is refused with
//   a reason, never read: the file is opened non-blocking, so a FIFO with no writer cannot hang
//   the caller, and its type is checked on the open descriptor before any byte is read.
// - At most `max_bytes` are read: a larger file (or one that grows past the bound while it is
//   read) is refused with its size in the reason, so memory stays bounded.
// - Failures are a base::Result's error (docs/architecture.md "Error convention"): a short
//   lower-case phrase to follow the path the caller names, e.g. "is a directory".

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"

namespace base {

/// The largest input file the programs read whole, in bytes (mission files, hazard files): a
/// field of 1,000,000 objects is about 80 MB. docs/robustness.md lists it.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{512} * 1024 * 1024;

/// The file's bytes, or why not (the contract above).
Result<std::string> read_file_text(const std::string& path,
                                   std::size_t max_bytes = kMaxInputFileBytes);

/// The whole of a file for a reader that takes every byte at once and may be given large ones
/// (hazard_replay's logs, hundreds of MB). A regular file is mapped read-only: no copy and no
/// memory of our own beyond the page cache's. A FIFO (a pipe, e.g. `<(zcat run.alog.gz)`), or
/// a regular file that cannot be mapped (those of /proc, which say they are empty), is read to
/// its end. A directory, socket or device is refused with a reason, as is more than
/// `max_bytes`. A mapped file cut short by another process while it is read faults (SIGBUS),
/// as in any program that maps its input: read a copy of a file that is still being written.
class WholeFile {
 public:
  /// The file's bytes, or why not (as read_file_text's reasons).
  static Result<WholeFile> open(const std::string& path, std::size_t max_bytes);
  WholeFile(WholeFile&& other) noexcept;
  WholeFile& operator=(WholeFile&& other) noexcept;
  WholeFile(const WholeFile&) = delete;
  WholeFile& operator=(const WholeFile&) = delete;
  ~WholeFile();

  /// Valid while this object lives, and across moves (the bytes never move).
  std::string_view text() const {
    return mapped_ ? std::string_view(static_cast<const char*>(mapped_), mapped_bytes_)
                   : std::string_view(read_.data(), read_.size());
  }
  bool mapped() const { return mapped_ != nullptr; }

 private:
  WholeFile() = default;
  void unmap();

  void* mapped_ = nullptr;
  std::size_t mapped_bytes_ = 0;
  std::vector<char> read_;  // when not mapped (a vector's bytes stay put when it is moved)
};

}  // namespace base
