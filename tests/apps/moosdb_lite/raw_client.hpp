#pragma once
// A test client that speaks raw MOOS protocol through the project's codec over a real
// socket, so the tests see exactly the bytes moosdb-lite sends. Every wait is bounded.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "moos/codec.hpp"
#include "moos/message.hpp"

namespace moosdb_lite::test {

/// How long a test waits for something that must arrive.
inline constexpr double kArrivalTimeout_s = 5.0;
/// How long a test waits to be confident that something does NOT arrive.
inline constexpr double kSilence_s = 0.3;

class RawClient {
 public:
  RawClient() = default;
  ~RawClient();
  RawClient(const RawClient&) = delete;
  RawClient& operator=(const RawClient&) = delete;

  /// Connects to 127.0.0.1:port; `receive_buffer_bytes` > 0 shrinks SO_RCVBUF first.
  bool connect(int port, int receive_buffer_bytes = 0);
  bool send_bytes(std::string_view bytes);
  bool send(const std::vector<moos::Message>& packet) { return send_bytes(moos::encode_packet(packet)); }

  /// Banner + identification; returns the first reply packet (WELCOME or POISON).
  std::optional<std::vector<moos::Message>> handshake(const std::string& name, bool async,
                                                      double ident_time);
  /// Connect + handshake that must succeed (test fails otherwise).
  bool join(int port, const std::string& name, bool async);

  /// The next packet, or nullopt after `timeout_s` or at end of stream (see eof()).
  std::optional<std::vector<moos::Message>> read_packet(double timeout_s = kArrivalTimeout_s);
  /// Reads packets until `count` NOTIFY messages (TIMING/NULL skipped) have arrived or the
  /// time is up; returns what arrived.
  std::vector<moos::Message> read_notifies(std::size_t count, double timeout_s = kArrivalTimeout_s);
  /// True if the server closes the connection within `timeout_s` (bytes before are discarded
  /// into `discarded_bytes`).
  bool wait_closed(double timeout_s, std::size_t* discarded_bytes = nullptr);
  bool eof() const { return eof_; }

  void close();
  /// Stops sending but keeps reading (TCP half close).
  void shutdown_write();

  /// Sync round trip: send `packet`, read exactly one reply.
  std::optional<std::vector<moos::Message>> exchange(const std::vector<moos::Message>& packet);

  const std::string& name() const { return name_; }

 private:
  int fd_ = -1;
  bool eof_ = false;
  std::string name_;
  moos::PacketReader reader_;
};

/// The current MOOS time of an unwarped process (seconds since the epoch).
double moos_now();

}  // namespace moosdb_lite::test
