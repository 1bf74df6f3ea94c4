#pragma once
// The connection state machine of moosdb-lite (docs/protocol.md 5.1a),
// between raw bytes and moos::Database (include/moos/database.hpp), without sockets.
//
// Contract:
// - The transport opens a connection (open), hands over received bytes in any segmentation
//   (receive), reports end of stream (end_of_stream), drops connections for its own reasons
//   (drop), and calls tick() regularly (at least every 100 ms) with the current time.
// - Time comes in as real unix seconds; the server's MOOS time is that times the warp.
// - Every call appends Actions (send bytes / close) in the order they must be applied.
//   Bytes that follow the banner or the identification packet in the same segment belong to
//   the next state and are never discarded (5.1a). Every complete packet is processed even
//   if the peer closes right after it (5.6).
// - States: BANNER (32 bytes, banner_timeout_s) -> IDENT (one packet, handshake_timeout_s)
//   -> ACTIVE (inactivity limit client_timeout_s, none if unset) -> closed. Inactivity is
//   judged by what the client sent (any byte, so a large packet arriving over many reads
//   keeps its sender alive) at the time the transport last looked at its socket: tick()'s
//   `now_real_s` must be the time of that look (the poll's return), never a later time, so a
//   server busy for seconds does not count its own stall as the clients' silence.
//   heard() moves the start of a connection's silence to when its input was processed.
//   A connection whose reading the transport paused (set_reading_paused) is not judged; its
//   silence counts again from the resumption. A wrong banner
//   closes without a reply; a failed identification gets POISON (1.6) before the close;
//   a framing or decoding error, an oversized packet header, a truncated packet at end of
//   stream or inactivity closes the connection. Each close of a misbehaving peer is logged
//   with the peer, the client name once known, and the reason.
// - Every Send names its source (Action::source). Mail to an asynchronous client is cut
//   into packets of at most kFairPacketBytes (or one message, at most moos::kMaxMessageBytes),
//   in order; a synchronous client's reply is one packet, as protocol.md 5.6 requires, which
//   moos::Database keeps within moos::kDefaultMaxPacketBytes. No client is sent a packet larger
//   than moos::kDefaultMaxPacketBytes.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "moos/codec.hpp"
#include "moos/database.hpp"

namespace moosdb_lite {

using ConnectionId = moos::ClientId;
// The database defaults the command line shows (options.cpp).
using moos::kDefaultCommunity;
using moos::kDefaultMaxPendingBytes;
using moos::kDefaultMaxStoredBytes;

/// Largest packet a client may send, in bytes: moos::kServerMaxPacketBytes (its reasons and the
/// other limits of the wire are in include/moos/codec.hpp).
inline constexpr std::size_t kDefaultServerMaxPacketBytes = moos::kServerMaxPacketBytes;
static_assert(kDefaultMaxPendingBytes >= 2 * kDefaultServerMaxPacketBytes,
              "a client's output must hold the echo of one maximal packet plus one more");

/// Banner and identification limits (protocol.md 1.5: the DB reads the identification with a
/// 5-second timeout; the banner gets the same).
inline constexpr double kDefaultBannerTimeout_s = 5.0;
inline constexpr double kDefaultHandshakeTimeout_s = 5.0;
/// Inactivity limit of the reference DB (protocol.md 1.9, mission global ClientTimeout).
inline constexpr double kDefaultClientTimeout_s = 5.0;
/// DB_TIME, DB_UPTIME, DB_CLIENTS, DB_RWSUMMARY are rewritten this often (real seconds;
/// protocol.md 5.6 SHOULD asks for 1-2 s).
inline constexpr double kDbVariableRefreshInterval_s = 1.0;

struct HubConfig {
  moos::DatabaseConfig database;
  double time_warp = 1.0;  ///< MOOS time = unix time x warp (protocol.md 1.10), 0 < warp <= 400
  double banner_timeout_s = kDefaultBannerTimeout_s;
  double handshake_timeout_s = kDefaultHandshakeTimeout_s;
  std::optional<double> client_timeout_s = kDefaultClientTimeout_s;  ///< nullopt: never
  std::size_t max_packet_bytes = kDefaultServerMaxPacketBytes;
};

/// The source of output no client caused (connection ids start at 1).
inline constexpr ConnectionId kServerSource = 0;

struct Action {
  enum class Kind {
    kSend,          ///< append `bytes` to the connection's output
    kClose,         ///< close now; pending output is discarded
    kCloseAfterSend ///< stop reading, close once the pending output is written
  };
  Kind kind = Kind::kSend;
  ConnectionId id = 0;
  std::string bytes;
  /// kSend: the connection whose input caused the packet (its posts, or its own reply);
  /// kServerSource for what the server sends of its own accord (DB variables, disconnects).
  /// The transport queues each connection's output per source (event_loop.hpp).
  ConnectionId source = kServerSource;
};
/// Mail to an asynchronous client leaves in packets of at most this many encoded bytes (or
/// one message, if larger), so a packet of a flooding source is a short turn in the
/// transport's round-robin over sources. Synchronous clients get one reply per packet, whole.
inline constexpr std::size_t kFairPacketBytes = 64u * 1024u;

class Hub {
 public:
  using LogSink = std::function<void(const std::string&)>;

  /// `observer` sees every NOTIFY the Database accepts (see Database).
  Hub(HubConfig config, double start_real_s, LogSink log,
      moos::Database::NotifyObserver observer = {});

  /// A new connection from `peer` (e.g. "127.0.0.1:40312"); returns its id.
  ConnectionId open(std::string peer, double now_real_s);
  void receive(ConnectionId id, std::string_view bytes, double now_real_s);
  /// The peer closed its side (or the socket failed: `reason` says how).
  void end_of_stream(ConnectionId id, double now_real_s, std::string_view reason = {});
  /// The transport gives up on a connection (e.g. its output overflowed); logged.
  void drop(ConnectionId id, const std::string& reason, double now_real_s);
  /// Timeouts and the DB-variable timer; `now_real_s` is when the transport last looked at
  /// every socket (see the contract).
  void tick(double now_real_s);
  /// The transport finished handing over (and the Hub processing) what the connection sent,
  /// at `now_real_s`: its silence counts from then, so a client that waits for the reply to
  /// a packet that kept the server busy is not judged silent for that time.
  void heard(ConnectionId id, double now_real_s);
  /// The transport stopped (true) or resumed (false) reading from a connection
  /// (back-pressure); a paused connection is not judged silent.
  void set_reading_paused(ConnectionId id, bool paused, double now_real_s);
  /// Bytes held for a connection besides its socket output, for the memory budget: its
  /// incomplete packet and the mail the database keeps for it.
  std::size_t held_bytes(ConnectionId id) const;

  std::vector<Action> take_actions();

  moos::Database& database() { return db_; }
  /// "client "pFoo" (127.0.0.1:40312)" or "connection #3 (127.0.0.1:40312)".
  std::string describe(ConnectionId id) const;
  std::size_t connection_count() const { return connections_.size(); }

 private:
  enum class State { kBanner, kIdent, kActive };

  struct Connection {
    std::string peer;
    State state = State::kBanner;
    std::string banner;            ///< banner bytes received so far
    moos::PacketReader reader;
    double state_since_real_s = 0; ///< when the current state began
    double last_input_real_s = 0;  ///< last byte received (liveness in ACTIVE)
    bool reading_paused = false;   ///< the transport does not read it (back-pressure)
    explicit Connection(std::size_t max_packet_bytes) : reader(max_packet_bytes) {}
  };

  void process_banner(ConnectionId id, Connection& conn, std::string_view& bytes, double now);
  void process_packets(ConnectionId id, double now);
  void handle_identification(ConnectionId id, const std::vector<moos::Message>& packet,
                             double now);
  void close(ConnectionId id, const std::string& reason, double now, Action::Kind kind);
  void collect_database_output(double now);
  /// Send actions for `packet`, split by kFairPacketBytes for an asynchronous client.
  void queue_send(moos::OutPacket packet);
  double moos_time(double now_real_s) const { return now_real_s * config_.time_warp; }

  HubConfig config_;
  LogSink log_;
  moos::Database db_;
  std::map<ConnectionId, Connection> connections_;
  ConnectionId next_id_ = 1;
  double last_refresh_real_s_;
  std::vector<Action> actions_;
  ConnectionId source_ = kServerSource;  ///< whose input is being processed (Action::source)
};

}  // namespace moosdb_lite
