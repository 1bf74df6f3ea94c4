#pragma once
// Descriptors a program owns: the three standard ones are always open, and its internal pipes
// never land on them.
//
// Contract:
// - ensure_standard_descriptors() opens /dev/null on each of descriptors 0, 1 and 2 that is
//   closed (a program started with them closed would otherwise hand them to the next pipe,
//   socket or log file it opens, and write its diagnostics into it).
// - open_internal_pipe() makes a pipe whose two ends are non-blocking, close-on-exec and above
//   descriptor 2, whatever was closed when it was called.

namespace base {

/// Opens /dev/null on each of descriptors 0, 1 and 2 that is closed.
void ensure_standard_descriptors();

/// A pipe for a program's own use (see the contract): fds[0] reads, fds[1] writes. False (with
/// errno set) when it cannot be made.
bool open_internal_pipe(int fds[2]);

}  // namespace base
