#pragma once
// The socket side of moosdb-lite: one thread, poll(), non-blocking sockets. All protocol
// decisions are the Hub's; this file only moves bytes and enforces transport limits.
//
// Contract:
// - listen() binds an IPv4 TCP listener (SO_REUSEADDR, backlog 50 as the reference DB),
//   and writes the bound port to the port file by the rule of every user-named output
//   (base/output_file.hpp: a regular file is written to a temporary name, then renamed, so a
//   reader never sees a partial number; a device or FIFO is written through).
// - run() serves until `stop_requested` becomes non-zero (the signal handler also writes a
//   byte to `wake_fd` so poll() returns at once). Every accepted socket gets TCP_NODELAY
//   (protocol.md 1.1). Reads are bounded per connection per round, so one flooding client cannot
//   starve the others.
// - Each connection has an output buffer of kWriteBufferBytes fed from per-source queues
//   (the Hub names each packet's source) in round-robin turns of one packet each: the mail of
//   one source keeps its order, and a flood from one source does not delay the others' mail
//   by more than a turn. Nothing else changes while the client keeps up (the queues are empty
//   and packets go straight to the buffer). "Unsent bytes" below counts buffer and queues.
//   Back-pressure first: while its unsent bytes exceed
//   kPauseReadingOutputBytes (or half of `max_output_bytes` if less) the connection is not
//   read (it cannot make more replies, the client is slowed down, a warning says its
//   messages are delayed); reading resumes below half of that. Only if its unsent bytes
//   exceed `max_output_bytes`, or nothing could be written for kSendStall_s while bytes were
//   waiting (the reference DB's 6 s send timeout, protocol.md 1.1), is the connection dropped with
//   a logged reason.
// - Global memory budget: the unsent output of all connections, their incomplete packets and
//   the mail the database keeps for them stay within `memory_budget_bytes`. Above it, the
//   connection holding the most is dropped with a logged warning, and the drops are counted
//   (never a crash).
// - Descriptor exhaustion (accept fails with EMFILE/ENFILE): a reserve descriptor is released
//   to accept the waiting connection and close it at once, so the listener does not spin;
//   without a reserve the listener is not polled for kAcceptBackoff_s. The failures are
//   logged at most once per kDescriptorLogInterval_s, with their count.
// - Liveness: the Hub's timers run with the time poll() returned (the last time the server
//   looked at the sockets), not the time after processing, and a connection whose input was
//   read is heard() when its processing ends (hub.hpp).
// - A connection closed "after send" gets at most kCloseGrace_s to take its last bytes.

#include <csignal>
#include <cstddef>
#include <functional>
#include <deque>
#include <map>
#include <optional>
#include <string>

#include "hub.hpp"

namespace moosdb_lite {

/// The reference DB sets a 6 s SO_SNDTIMEO; a stuck write ends the connection (protocol.md 1.1).
inline constexpr double kSendStall_s = 6.0;
/// Time given to a closing connection to take a POISON or its last reply.
inline constexpr double kCloseGrace_s = 2.0;
/// Bytes of a connection's output handed to send() at a time; the rest waits in per-source
/// queues and is taken in turns (one packet of each source per turn), so mail from a flooding
/// source waits behind the flood's earlier mail, but another source's mail does not.
inline constexpr std::size_t kWriteBufferBytes = 64u * 1024u;
/// Unsent bytes above which a connection is no longer read (back-pressure), in bytes.
inline constexpr std::size_t kPauseReadingOutputBytes = 64u * 1024u * 1024u;
/// Default global budget, in bytes: unsent output, incomplete packets and kept mail of all
/// connections.
/// Holds two libMOOS clients each echoing a maximal packet (hub.hpp) with room to spare.
inline constexpr std::size_t kDefaultMemoryBudgetBytes = 1024u * 1024u * 1024u;
/// How long the listener rests when a connection cannot be accepted for lack of descriptors.
inline constexpr double kAcceptBackoff_s = 0.1;
/// Descriptor-exhaustion warnings are logged at most this often (the rest are counted).
inline constexpr double kDescriptorLogInterval_s = 10.0;

struct EventLoopConfig {
  std::string bind_address;
  int port = 0;  ///< 0: the OS picks
  std::optional<std::string> port_file;
  std::size_t max_output_bytes = 0;
  std::size_t memory_budget_bytes = kDefaultMemoryBudgetBytes;
};

class EventLoop {
 public:
  using LogSink = std::function<void(const std::string&)>;
  EventLoop(EventLoopConfig config, Hub& hub, LogSink log);
  ~EventLoop();
  EventLoop(const EventLoop&) = delete;
  EventLoop& operator=(const EventLoop&) = delete;

  /// Binds and listens; false with `error` filled on failure.
  bool listen(std::string* error);
  int bound_port() const { return bound_port_; }

  /// Serves until `stop_requested` is set. `after_round` runs after every poll round
  /// (the caller flushes its log file there).
  void run(int wake_fd, const volatile std::sig_atomic_t& stop_requested,
           const std::function<void()>& after_round);

 private:
  struct Socket {
    int fd = -1;
    std::string out;             ///< bytes handed to send(), from out_offset on
    std::size_t out_offset = 0;
    /// Packets not yet in `out`, per source (Action::source), each queue in arrival order.
    std::map<ConnectionId, std::deque<std::string>> queued;
    std::size_t queued_bytes = 0;
    ConnectionId next_source = 0;  ///< the round-robin turn starts at the first source >= it
    bool closing = false;        ///< no more reads; close once `out` is written
    double close_deadline_real_s = 0;
    double last_progress_real_s = 0;
    bool broken = false;         ///< a write failed: close without further writes
    bool reading_paused = false; ///< back-pressure: too much unsent output
    std::size_t in_buffer() const { return out.size() - out_offset; }
    /// Every byte waiting for this connection: the buffer and the per-source queues.
    std::size_t pending() const { return in_buffer() + queued_bytes; }
  };

  /// Appends a packet for `socket` from `source`: straight to the buffer while nothing is
  /// queued and the buffer is below kWriteBufferBytes, else to the source's queue.
  static void enqueue(Socket& socket, ConnectionId source, std::string bytes);
  /// Tops the buffer up to kWriteBufferBytes from the queues, one packet per source per turn.
  static void fill_buffer(Socket& socket);

  void accept_new(double now);
  /// accept() failed for lack of descriptors: shed the connection, back off, log rarely.
  void shed_connection(double now, int error);
  void apply_back_pressure(double now);
  void enforce_memory_budget(double now);
  void read_from(ConnectionId id, double now);
  void read_chunks(ConnectionId id, double now);
  void write_to(ConnectionId id, double now);
  void apply_actions(double now);
  void enforce_output_limits(double now);
  void reap_closed(double now);
  void close_socket(ConnectionId id);

  EventLoopConfig config_;
  Hub& hub_;
  LogSink log_;
  int listen_fd_ = -1;
  int reserve_fd_ = -1;  ///< released to accept-and-close when descriptors run out
  double listen_paused_until_s_ = 0;
  std::size_t shed_count_ = 0;         ///< connections refused for lack of descriptors
  std::size_t shed_logged_count_ = 0;  ///< ... of which the log already told
  double shed_logged_s_ = -1e300;
  std::size_t budget_drops_ = 0;       ///< connections dropped by the memory budget
  int bound_port_ = 0;
  std::map<ConnectionId, Socket> sockets_;
};

}  // namespace moosdb_lite
