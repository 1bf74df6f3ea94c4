#pragma once
// A MOOS client over TCP in asynchronous mode (docs/protocol.md sections 1, 4.1, 4.3, 4.4 and 4.6),
// compatible with the reference MOOSDB and with moosdb-lite.
//
// Contract:
// - start() launches one comms thread that connects, performs the handshake (32-byte banner,
//   identification with key "asynchronous" and the client name, protocol.md 1.4-1.5) and then both
//   writes and reads the socket. Every public function is thread-safe.
// - POISON (duplicate name) stops the client for good (state kPoisoned, last_error() holds the
//   server's reason), as libMOOS does. Any other failure (refused connection, lost connection,
//   a handshake that closes or stays silent longer than handshake_timeout_real_s) is retried
//   once per MOOS second (1/warp real seconds, protocol.md 1.9).
// - After each handshake the client (1) adopts the WELCOME skew per SkewPolicy (1.8), (2) queues
//   every remembered subscription, (3) runs the on-connect callback, then normal traffic starts.
// - Sending: whatever was posted is sent as one packet (several, when it exceeds
//   kDefaultMaxPacketBytes, codec.hpp) as soon as possible, after
//   max(server delay from the last TIMING echo, warp x tw_delay_factor ms) since the previous
//   send (4.3 step 4). A TIMING message (own local time, protocol.md 2.6) leads the next packet
//   when kTimingInterval_real_s has passed since the last one, and is sent alone while idle, so an
//   idle client sends one at least once per second (4.6); while the app's thread sends packets
//   itself, the comms thread waits kAppTimingSlack_real_s longer, so the TIMING rides in the
//   app's next packet. Packets are never empty.
// - Receiving: a TIMING at the head of a packet is consumed and refines the skew (4.4); TIMING
//   messages elsewhere and NULL messages anywhere are dropped; everything else, `~` data types
//   included, goes to the inbox in arrival order. A framing or decoding error closes the
//   connection (then it is retried).
// - The app's own thread does the I/O when it can: release_sends() writes the held
//   batch itself when the send slot is open. After expect_fetch_within(), fetch() first reads
//   what the socket holds, and the comms thread leaves reading to fetch() for that long plus
//   kAppReadGrace_real_s (except while a TIMING echo is awaited, so the skew stays exact), so an
//   app cycling with steady mail wakes one thread per cycle, not two per packet; a fetch() that
//   cannot read it all hands the reading back for one round (the promise, comms.hpp). The comms
//   thread still does everything when the app does not cycle, and is the only one that drops a
//   connection: a failure the app's thread meets is handed to it. Mail left unread when the
//   app stops makes the close a reset, which the server may log as one.
// - Deviations from libMOOS, deliberate: postings wait in the bounded outbox while disconnected
//   and leave after the next handshake (comms.hpp; libMOOS refuses them); the inbox is kept
//   across a reconnect (libMOOS clears it, losing mail that had arrived); the inbox is bounded by max_inbox_messages and
//   max_inbox_bytes and, when either is reached, the OLDEST unread mail is dropped and counted
//   (mail_dropped()) so the app still sees the newest state (libMOOS discards the whole inbox
//   beyond 2048 unread messages); the handshake has a timeout (libMOOS waits forever); a connection closed
//   during the handshake is retried (libMOOS gives up).
// - close() (and the destructor) stops the thread, closes the socket and joins; nothing is left.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "moos/codec.hpp"
#include "moos/comms.hpp"
#include "moos/inbox.hpp"

namespace moos {

enum class ConnectionState {
  kNotStarted,
  kConnecting,  ///< trying to connect or reconnect
  kConnected,
  kPoisoned,    ///< the server refused the name; the client has stopped
  kClosed,      ///< close() was called
};

/// When to adopt the skew a server announces in WELCOME (protocol.md 1.8).
enum class SkewPolicy {
  kLibMoos,  ///< libMOOS non-quiet: ignore it when the DB runs on this host (same hostname)
  kAlways,   ///< libMOOS quiet mode and pymoos2
  kNever,
};

/// Unread mail a client keeps before it drops the oldest: far above what a
/// 100-vehicle mission delivers between two iterations (about 1,000 messages a second), so only
/// an app that has stopped fetching, or a flood, reaches it.
inline constexpr std::size_t kDefaultMaxInboxMessages = 65536;
inline constexpr std::size_t kDefaultMaxInboxBytes = std::size_t{64} * 1024 * 1024;

struct TcpClientOptions {
  std::string host = "localhost";  ///< a name or dotted IPv4 address (IPv4 only, protocol.md 1.1)
  int port = 9000;                 ///< 1..65535
  std::string name;                ///< the client name: unique in the community, not empty
  double time_warp = 1.0;          ///< 0 < W <= 400 (protocol.md 1.10)
  Clock* clock = nullptr;          ///< time stamps; nullptr = system_clock()
  SkewPolicy skew_policy = SkewPolicy::kLibMoos;
  /// This host's name for the kLibMoos comparison; "" = gethostname().
  std::string own_hostname;
  double connect_timeout_real_s = 2.0;
  double handshake_timeout_real_s = 5.0;  ///< the DB itself allows 5 s for the identification
  std::size_t max_packet_bytes = kDefaultMaxPacketBytes;
  std::size_t max_inbox_messages = kDefaultMaxInboxMessages;  ///< >= 1
  std::size_t max_inbox_bytes = kDefaultMaxInboxBytes;        ///< >= 1; approximate message sizes
  std::size_t max_outbox_messages = kDefaultMaxOutboxMessages;  ///< >= 1 (comms.hpp)
  std::size_t max_outbox_bytes = kDefaultMaxOutboxBytes;        ///< >= 1; encoded sizes
  /// libMOOS --moos_tw_delay_factor: ms of pause after each send per unit of warp above 1.
  double tw_delay_factor_ms = 0.2;
};

class TcpClient final : public Comms {
 public:
  /// Under 1 s with a 250 ms margin for scheduling delays on a loaded machine, so an idle
  /// client sends at least one TIMING per second (4.6; libMOOS waits 1.0-1.33 s).
  static constexpr double kTimingInterval_real_s = 0.75;

  explicit TcpClient(TcpClientOptions options);
  ~TcpClient() override;

  /// Launches the comms thread. False (with last_error()) if the options are invalid or the
  /// client was already started.
  bool start();
  /// Stops the comms thread and closes the socket. Idempotent; the client cannot be restarted.
  void close();

  /// Blocks until connected, poisoned, closed, or `timeout_real_s` passes. True if connected.
  bool wait_until_connected(double timeout_real_s) const;
  /// Blocks until everything posted so far has been written to the socket (true), or the
  /// connection is lost or `timeout_real_s` passes (false).
  bool flush(double timeout_real_s);

  ConnectionState state() const;
  /// The most recent problem (connection refused, POISON reason, decode error, ...).
  std::string last_error() const;
  /// `hostname` of the server from WELCOME ("" if it sent none).
  std::string server_hostname() const;
  /// True if WELCOME advertised asynchronous support.
  bool server_is_asynchronous() const;
  /// Packets sent since start (TIMING-only ones included); for tests and diagnostics.
  std::uint64_t packets_sent() const;

  // Comms
  bool is_connected() const override;
  std::uint64_t connection_count() const override;
  std::string community() const override;
  Clock& clock() const override { return clock_; }
  double time_warp() const override { return options_.time_warp; }
  double skew_s() const override { return skew_s_.load(); }
  void fetch_into(std::vector<Message>& mail) override;
  void hold_sends() override;
  void release_sends() override;
  void expect_fetch_within(double real_s) override;

  /// How long past its promise the comms thread leaves reading to fetch(): a cycling app's late
  /// iterations never make it read, and a stalled app's mail waits at most this much longer to
  /// be counted against the inbox bounds (it could not be handled sooner anyway).
  static constexpr double kAppReadGrace_real_s = 0.5;
  /// While the app's thread sends packets itself, the comms thread waits this much longer for a
  /// due TIMING, which then rides in the app's next packet (one wake-up saved per TIMING); the
  /// longest gap between two TIMINGs, 0.95 s, stays within libMOOS's 1.0 s.
  static constexpr double kAppTimingSlack_real_s = 0.2;

 protected:
  bool transmit(Message&& msg) override;

 private:
  /// Bytes read per recv call, and recv calls per read (1 MiB) before sending gets a turn.
  static constexpr std::size_t kReadChunkBytes = 64 * 1024;
  static constexpr int kMaxReadChunksPerWake = 16;
  /// How long after a TIMING its echo is read by the comms thread at once (when the skew is
  /// corrected): beyond that the echo is late anyway, and fetch() may read it.
  static constexpr double kTimingEchoWindow_real_s = 0.25;

  static double steady_now_s();
  static std::string errno_text(const char* what);  ///< "what: strerror(errno)"
  bool on_comms_thread() const;
  void run();
  bool connect_socket();
  bool handshake();
  void serve();
  /// The comms thread's next poll (io_mutex_ held): what to wait for, and how long.
  struct PollPlan {
    short socket_events = 0;
    double wait_real_s = 0;
  };
  PollPlan plan_poll(double now);
  /// True while the input is left to the promised fetch (io_mutex_ held); false for one poll
  /// after fetch() handed the reading back.
  bool app_reads(double now);
  void drop_connection(const std::string& why);
  /// Drops the registrations from the outbox (mutex_ held): the next handshake replays them.
  void forget_registrations_in_outbox();
  /// A socket failure: dropped at once on the comms thread; from the app's thread handed to the
  /// comms thread (it owns the socket's life), and no more I/O happens here until then.
  void fail_io(const std::string& why);
  /// Encodes the next packet (io_mutex_ held) when the write buffer is free, the send slot open
  /// and something is due: a TIMING, or posted messages not held. True if a packet was started.
  bool start_packet_if_due(double now);
  bool write_pending();
  bool read_available();
  /// The app's thread reads / sends for itself when the comms thread is not busy doing it.
  void read_for_app();
  bool send_for_app();
  /// io_mutex_ for the app's thread: owned only when it was free and the connection is usable
  /// (connected, no failure handed over yet).
  std::unique_lock<std::mutex> lock_io_for_app();
  /// The comms thread's reading: `read` (process_buffered or read_available) under io_mutex_,
  /// then, with the lock released, the on-mail callback if the inbox grew. `read`'s result.
  bool read_and_announce(bool (TcpClient::*read)());
  /// Drops the oldest unread mail until the inbox is within 3/4 of its bounds (mutex held); a
  /// bulk drop keeps the cost of a flood linear.
  void enforce_inbox_bounds();
  bool process_buffered();
  /// Moves a decoded packet's mail into the inbox; `messages` gets the inbox's kept messages in
  /// its place, for the next decode to overwrite.
  void handle_packet(std::vector<Message>& messages);
  void refine_skew(const Message& timing_echo);
  Message timing_message() const;
  /// Moves the outbox's head that fits one packet (after a lead of `lead_bytes`) into batch_
  /// (mutex_ held).
  void take_batch(std::size_t lead_bytes);
  void wake();
  void wait_for_wake(double timeout_real_s);
  void set_error(const std::string& error);
  double retry_delay_real_s() const;

  const TcpClientOptions options_;
  Clock& clock_;

  std::thread thread_;
  /// Set by the comms thread itself when it starts: `thread_` is assigned only after the thread
  /// runs, so the thread must not read it.
  std::atomic<std::thread::id> comms_thread_id_{};
  std::atomic<bool> stopping_{false};
  int wake_read_ = -1;    // self-pipe: transmit()/close() wake the comms thread
  int wake_write_ = -1;

  // The socket's I/O state. Lock order: io_mutex_ before mutex_. The comms thread holds io_mutex_
  // for all I/O but its poll; the app's thread only try-locks it, and does I/O only while
  // connected, so connect and handshake (not connected yet) and drop_connection (under the lock)
  // never meet it.
  std::mutex io_mutex_;
  int socket_ = -1;
  PacketReader reader_;
  // The last packet decoded and the last batch sent: kept, so a packet costs no vector of its own
  // (up to kKeptMessages; a burst's larger vector is let go: release_if_large).
  static constexpr std::size_t kKeptMessages = 4096;
  static void release_if_large(std::vector<Message>& kept) {
    if (kept.capacity() > kKeptMessages) std::vector<Message>().swap(kept);
  }
  std::vector<Message> decoded_;
  std::vector<Message> batch_;
  std::string write_buffer_;  // bytes of the packet being written (its capacity kept)
  std::size_t write_offset_ = 0;
  double next_send_allowed_ = 0;   // steady seconds
  std::optional<double> last_timing_sent_;  // steady seconds; nullopt: never
  std::optional<double> last_app_send_;     // steady seconds of the app thread's last packet
  bool awaiting_timing_echo_ = false;  // a TIMING went out and its echo has not come back
  bool time_correction_ = true;
  // A failure met on the app's thread, for the comms thread to drop. The app's thread reads it
  // only once it saw the client connected (lock_io_for_app): a failed handshake clears it
  // without io_mutex_.
  std::string app_io_failure_;
  bool new_mail_ = false;  // the inbox grew under this hold of io_mutex_: announce it after
  std::atomic<double> app_reads_until_{0};  // steady s: reading left to fetch() until then
  std::atomic<bool> comms_reads_once_{false};  // fetch() could not read it all: the comms thread does
  bool input_left_ = false;  // the last read_available() stopped at its bound (io_mutex_ held)

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  ConnectionState state_ = ConnectionState::kNotStarted;
  std::vector<Message> outbox_;
  OutboxBound outbox_bound_;
  bool holding_sends_ = false;  ///< hold_sends(): the outbox waits for release_sends()
  Inbox inbox_;
  std::size_t inbox_bytes_ = 0;  ///< approximate, see inbox_cost()
  std::int32_t next_id_ = 0;
  std::uint64_t connections_ = 0;
  std::uint64_t packets_sent_ = 0;
  std::uint64_t packets_in_flight_ = 0;  // encoded but not completely written yet
  std::string community_;
  std::string server_hostname_;
  bool server_async_ = false;
  std::string last_error_;
  std::atomic<double> skew_s_{0.0};
  std::atomic<double> server_delay_s_{0.0};
};

}  // namespace moos
