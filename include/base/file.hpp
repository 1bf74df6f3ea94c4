#pragma once
// Reading a whole input file, bounded and without surprises (issue 12, "Special files").
//
// Contract:
// - Only a regular file is read. A directory, FIFO, socket or device (/dev/zero) is refused with
//   a reason, never read: the file is opened non-blocking, so a FIFO with no writer cannot hang
//   the caller, and its type is checked on the open descriptor before any byte is read.
// - At most `max_bytes` are read: a larger file (or one that grows past the bound while it is
//   read) is refused with its size in the reason, so memory stays bounded.
// - The reason is a short lower-case phrase to follow the path, e.g. "is a directory".

#include <cstddef>
#include <optional>
#include <string>

namespace base {

/// The largest input file the programs read whole, in bytes (mission files, hazard files): a
/// field of 1,000,000 objects is about 80 MB. docs/robustness.md lists it.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{512} * 1024 * 1024;

struct FileText {
  std::optional<std::string> text;  ///< the bytes, when the file was read
  std::string problem;              ///< why not, when text is empty
};

FileText read_regular_file(const std::string& path, std::size_t max_bytes = kMaxInputFileBytes);

}  // namespace base
