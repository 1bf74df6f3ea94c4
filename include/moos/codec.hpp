#pragma once
// Message encoding and packet framing of the MOOS v10 protocol (core-moos CMOOSMsg and
// CMOOSCommPkt), written from docs/protocol.md sections 1.2-3.4.
//
// Contract:
// - Everything is little-endian whatever the host (protocol.md 1.2).
// - The encoder writes the exact length fields; the packet header's compression byte is 0.
// - The decoder is strict where libMOOS is lenient (protocol.md 2.7): a length below 54, a length
//   past the bytes remaining, a negative or overlong string, or consumed != length is an error
//   that names the message index and the byte offset. It never reads out of bounds and never
//   allocates more than the bytes it was given.
// - PacketReader reassembles packets from arbitrary TCP segment boundaries and refuses a
//   header that announces fewer than 9 bytes or more than its configured limit before
//   allocating anything.

#include <cstddef>
#include <climits>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "moos/message.hpp"

namespace moos {

/// The 32-byte client banner: "ELKS CAN'T DANCE 2/8/10" padded with NULs (protocol.md 1.4).
inline constexpr std::string_view kBannerText = "ELKS CAN'T DANCE 2/8/10";
inline constexpr std::size_t kBannerSize = 32;
std::string protocol_banner();
/// True if a received 32-byte banner matches, compared as the DB does: up to the first NUL,
/// case-insensitively.
bool banner_matches(std::string_view received);

/// Packet header: int32 total length (including the header), int32 message count, one
/// compression byte that is always 0 (protocol.md 3.1).
inline constexpr std::size_t kPacketHeaderSize = 9;
/// The wire's size limits, one set for every sender and receiver here (docs/moos.md, "Limits"):
/// - kDefaultMaxPacketBytes: the largest packet a client accepts (protocol.md 3.4), so the
///   largest packet a client sends and the server sends to a client;
/// - kMaxMessageBytes: the largest message, encoded, that a client posts and the server stores
///   and relays: one that fits in a packet a client accepts behind the NULL that leads a
///   synchronous reply. A larger one is refused where it enters (the posting client, or the
///   server for other clients), naming the variable;
/// - kServerMaxPacketBytes: the largest packet moosdb-lite accepts. libMOOS sends its whole
///   backlog (up to 2,048 messages, OUTBOX_PENDING_LIMIT) as one packet; core-moos's app_test
///   posts 100 kB messages, so its packets reach ~205 MB: 2,048 messages of 128 KiB fit.
/// - Every length field is 32 bits: all three stay below INT32_MAX, and the encoder refuses
///   (std::length_error) a size it cannot write rather than narrowing it.
inline constexpr std::size_t kDefaultMaxPacketBytes = 128u * 1024u * 1024u;
inline constexpr std::size_t kMaxMessageBytes =
    kDefaultMaxPacketBytes - kPacketHeaderSize - Message::kFixedEncodedSize;
inline constexpr std::size_t kServerMaxPacketBytes = 256u * 1024u * 1024u;
static_assert(kServerMaxPacketBytes >= kDefaultMaxPacketBytes &&
                  kServerMaxPacketBytes <= std::size_t{INT32_MAX},
              "the server takes every packet a client may send, and lengths fit 32 bits");

/// Appends one encoded message. Throws std::length_error if a length does not fit the wire's
/// 32 bits (callers bound messages by kMaxMessageBytes first).
void append_message(std::string& out, const Message& msg);
std::string encode_message(const Message& msg);
/// One packet holding the messages in order (std::length_error if it would exceed INT32_MAX
/// bytes; callers bound packets by their peer's limit first). Never call with an empty list for a peer that
/// expects mail (protocol.md 3.4); the function itself allows it for tests.
std::string encode_packet(const std::vector<Message>& messages);
/// One packet holding the messages [first, last) in order (a slice of a list, uncopied).
std::string encode_packet(const Message* first, const Message* last);
/// The same packet with `lead` (when not null) before [first, last), written over `out`: a sender
/// that keeps its buffer reuses its capacity (up to 1 MiB, or four times the packet).
void write_packet(std::string& out, const Message* lead, const Message* first,
                  const Message* last);

struct DecodeError {
  std::string reason;       ///< human-readable, names the field that failed
  std::size_t offset = 0;   ///< byte offset within the buffer given to the decoder
};

/// Decodes exactly one message that must occupy all of `bytes`.
std::optional<Message> decode_message(std::string_view bytes, DecodeError* error = nullptr);

/// Decodes a whole packet (header included). Returns the messages in order.
std::optional<std::vector<Message>> decode_packet(std::string_view packet,
                                                  DecodeError* error = nullptr);

/// Incremental packet reassembly for a byte stream.
class PacketReader {
 public:
  explicit PacketReader(std::size_t max_packet_bytes = kDefaultMaxPacketBytes)
      : max_packet_bytes_(max_packet_bytes) {}

  enum class Status { kNeedMore, kPacket, kError };

  /// Appends received bytes.
  void feed(std::string_view bytes);
  /// Extracts the next complete packet into `out` (kPacket), reports that more bytes are
  /// needed (kNeedMore), or reports a framing/decoding error (kError, `error` filled, `out`
  /// unspecified). After an error the stream is unusable: the caller should close the
  /// connection. `out`'s elements are overwritten in place: a caller that passes the same
  /// vector every time reuses its storage and its messages' strings.
  Status next(std::vector<Message>& out, DecodeError* error = nullptr);

  /// Bytes received but not yet consumed as packets.
  std::size_t buffered() const { return buffer_.size() - consumed_; }
  /// Takes the unconsumed bytes (used after the banner/handshake stage switches readers).
  std::string take_buffered();

 private:
  std::size_t max_packet_bytes_;
  std::string buffer_;
  std::size_t consumed_ = 0;
  bool failed_ = false;
};

}  // namespace moos
