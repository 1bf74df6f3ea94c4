// MOOS v10 message and packet codec. Layouts: docs/protocol.md 2.1 and 3.1.
// Integers and doubles are written byte by byte in little-endian order so the code is
// independent of host byte order and alignment.

#include "moos/codec.hpp"

#include <cstring>
#include <limits>
#include <stdexcept>

#include "base/text.hpp"

namespace moos {

namespace {

constexpr std::size_t kInt32Size = 4;
constexpr std::size_t kDoubleSize = 8;
/// write_packet keeps its buffer's capacity between packets up to this much.
constexpr std::size_t kKeptPacketCapacity = std::size_t{1} << 20;

// The encoder writes through a cursor into bytes the caller sized once (a posting is a dozen
// fields: one capacity check per field cost more than the bytes).
char* put_int32(char* p, std::int32_t value) {
  const auto u = static_cast<std::uint32_t>(value);
  for (int i = 0; i < 4; ++i) p[i] = static_cast<char>((u >> (8 * i)) & 0xffu);
  return p + kInt32Size;
}

/// A size written as a 32-bit length field: checked before it is narrowed.
void check_length(std::size_t size, const char* what) {
  if (size > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::length_error(std::string(what) + " of " + std::to_string(size) +
                            " bytes does not fit a 32-bit length field");
}

char* put_double(char* p, double value) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (int i = 0; i < 8; ++i) p[i] = static_cast<char>((bits >> (8 * i)) & 0xffu);
  return p + kDoubleSize;
}

// A string's length is below its message's, which check_length has passed.
char* put_string(char* p, const std::string& s) {
  p = put_int32(p, static_cast<std::int32_t>(s.size()));
  if (!s.empty()) std::memcpy(p, s.data(), s.size());
  return p + s.size();
}

// Writes one message of `size` (its encoded_size(), checked) from `p`.
char* put_message(char* p, const Message& msg, std::size_t size) {
  p = put_int32(p, static_cast<std::int32_t>(size));
  p = put_int32(p, msg.id);
  *p++ = msg.type;
  *p++ = msg.data_type;
  p = put_string(p, msg.source);
  p = put_string(p, msg.source_aux);
  p = put_string(p, msg.community);
  p = put_string(p, msg.key);
  p = put_double(p, msg.time);
  p = put_double(p, msg.dval);
  p = put_double(p, msg.dval2);
  return put_string(p, msg.sval);
}

std::uint32_t load_u32(const char* p) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(p[i]);
  return v;
}

std::int32_t load_int32(const char* p) {
  const std::uint32_t u = load_u32(p);
  std::int32_t v = 0;
  std::memcpy(&v, &u, sizeof v);
  return v;
}

double load_double(const char* p) {
  std::uint64_t bits = 0;
  for (int i = 7; i >= 0; --i) bits = (bits << 8) | static_cast<unsigned char>(p[i]);
  double v = 0;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

// Sequential reader over one message's bytes; every read is bounds-checked.
class FieldReader {
 public:
  FieldReader(std::string_view bytes, std::size_t base_offset)
      : bytes_(bytes), base_offset_(base_offset) {}

  bool int32(std::int32_t& v, const char* field, DecodeError* error) {
    if (!have(kInt32Size, field, error)) return false;
    v = load_int32(bytes_.data() + pos_);
    pos_ += kInt32Size;
    return true;
  }
  bool byte(char& v, const char* field, DecodeError* error) {
    if (!have(1, field, error)) return false;
    v = bytes_[pos_++];
    return true;
  }
  bool float64(double& v, const char* field, DecodeError* error) {
    if (!have(kDoubleSize, field, error)) return false;
    v = load_double(bytes_.data() + pos_);
    pos_ += kDoubleSize;
    return true;
  }
  bool string(std::string& v, const char* field, DecodeError* error) {
    std::int32_t n = 0;
    const std::size_t at = pos_;
    if (!int32(n, field, error)) return false;
    if (n < 0) return fail(at, std::string("negative length for ") + field, error);
    if (static_cast<std::size_t>(n) > bytes_.size() - pos_)
      return fail(at, std::string("string ") + field + " runs past the end of the message", error);
    v.assign(bytes_.data() + pos_, static_cast<std::size_t>(n));
    pos_ += static_cast<std::size_t>(n);
    return true;
  }
  std::size_t position() const { return pos_; }

 private:
  bool have(std::size_t n, const char* field, DecodeError* error) {
    if (bytes_.size() - pos_ >= n) return true;
    return fail(pos_, std::string("truncated field ") + field, error);
  }
  bool fail(std::size_t at, std::string reason, DecodeError* error) const {
    if (error) *error = DecodeError{std::move(reason), base_offset_ + at};
    return false;
  }

  std::string_view bytes_;
  std::size_t base_offset_;
  std::size_t pos_ = 0;
};

// Decodes into `m` in its final place (a packet's messages are not moved around); false and
// `error` set when the bytes are not one whole message.
bool decode_message_into(Message& m, std::string_view bytes, std::size_t base_offset,
                         DecodeError* error) {
  FieldReader r(bytes, base_offset);
  std::int32_t length = 0;
  const bool ok = r.int32(length, "length", error) && r.int32(m.id, "id", error) &&
                  r.byte(m.type, "message type", error) &&
                  r.byte(m.data_type, "data type", error) &&
                  r.string(m.source, "source", error) &&
                  r.string(m.source_aux, "source aux", error) &&
                  r.string(m.community, "community", error) && r.string(m.key, "key", error) &&
                  r.float64(m.time, "time", error) && r.float64(m.dval, "dval", error) &&
                  r.float64(m.dval2, "dval2", error) && r.string(m.sval, "string value", error);
  if (!ok) return false;
  if (static_cast<std::size_t>(length) != r.position() || r.position() != bytes.size()) {
    if (error)
      *error = DecodeError{"length field " + std::to_string(length) + " but message holds " +
                               std::to_string(r.position()) + " bytes",
                           base_offset};
    return false;
  }
  return true;
}

// Decodes a packet into `out`: its elements are overwritten in place, so a vector reused from
// packet to packet is not reallocated, nor are the strings its messages still hold.
bool decode_packet_into(std::string_view packet, std::vector<Message>& out, DecodeError* error) {
  auto fail = [&](std::string reason, std::size_t offset) {
    if (error) *error = DecodeError{std::move(reason), offset};
    return false;
  };
  if (packet.size() < kPacketHeaderSize) return fail("packet shorter than its 9-byte header", 0);
  const std::uint32_t total = load_u32(packet.data());
  if (total != packet.size())
    return fail("packet length field " + std::to_string(total) + " but packet holds " +
                    std::to_string(packet.size()) + " bytes",
                0);
  const std::int32_t count = load_int32(packet.data() + 4);
  if (count < 0) return fail("negative message count " + std::to_string(count), 4);
  // A message is at least 54 bytes, which bounds the count before anything is reserved.
  const std::size_t body = packet.size() - kPacketHeaderSize;
  if (static_cast<std::size_t>(count) > body / Message::kFixedEncodedSize)
    return fail("message count " + std::to_string(count) + " cannot fit in " +
                    std::to_string(body) + " bytes",
                4);

  out.resize(static_cast<std::size_t>(count));
  std::size_t pos = kPacketHeaderSize;
  for (std::int32_t i = 0; i < count; ++i) {
    if (packet.size() - pos < kInt32Size)
      return fail("message " + std::to_string(i) + ": truncated length field", pos);
    const std::int32_t length = load_int32(packet.data() + pos);
    if (length < static_cast<std::int32_t>(Message::kFixedEncodedSize))
      return fail("message " + std::to_string(i) + ": length " + std::to_string(length) +
                      " below the minimum of 54",
                  pos);
    if (static_cast<std::size_t>(length) > packet.size() - pos)
      return fail("message " + std::to_string(i) + ": length " + std::to_string(length) +
                      " runs past the end of the packet",
                  pos);
    DecodeError inner;
    if (!decode_message_into(out[static_cast<std::size_t>(i)],
                             packet.substr(pos, static_cast<std::size_t>(length)), pos, &inner))
      return fail("message " + std::to_string(i) + ": " + inner.reason, inner.offset);
    pos += static_cast<std::size_t>(length);
  }
  if (pos != packet.size())
    return fail(std::to_string(packet.size() - pos) + " bytes left after the last message", pos);
  return true;
}

}  // namespace

std::string protocol_banner() {
  std::string banner(kBannerText);
  banner.resize(kBannerSize, '\0');
  return banner;
}

bool banner_matches(std::string_view received) {
  const auto nul = received.find('\0');
  return base::iequals(received.substr(0, nul), kBannerText);
}

void append_message(std::string& out, const Message& msg) {
  const std::size_t size = msg.encoded_size();
  check_length(size, "a message");
  const std::size_t at = out.size();
  out.resize(at + size);
  put_message(out.data() + at, msg, size);
}

std::string encode_message(const Message& msg) {
  std::string out;
  append_message(out, msg);
  return out;
}

std::string encode_packet(const std::vector<Message>& messages) {
  return encode_packet(messages.data(), messages.data() + messages.size());
}

std::string encode_packet(const Message* first, const Message* last) {
  std::string out;
  write_packet(out, nullptr, first, last);
  return out;
}

void write_packet(std::string& out, const Message* lead, const Message* first,
                  const Message* last) {
  std::size_t total = kPacketHeaderSize + (lead ? lead->encoded_size() : 0);
  for (const Message* m = first; m != last; ++m) total += m->encoded_size();
  check_length(total, "a packet");  // before the allocation it would size
  const std::size_t count = static_cast<std::size_t>(last - first) + (lead ? 1 : 0);
  check_length(count, "a message count");
  // A buffer kept from a burst is let go once packets are far smaller again.
  if (out.capacity() > kKeptPacketCapacity && out.capacity() / 4 > total) std::string().swap(out);
  out.resize(total);
  char* p = put_int32(out.data(), static_cast<std::int32_t>(total));
  p = put_int32(p, static_cast<std::int32_t>(count));
  *p++ = '\0';  // compression flag: v10 has no compression (protocol.md 3.2)
  if (lead) p = put_message(p, *lead, lead->encoded_size());
  for (const Message* m = first; m != last; ++m) p = put_message(p, *m, m->encoded_size());
}

std::optional<Message> decode_message(std::string_view bytes, DecodeError* error) {
  if (bytes.size() < Message::kFixedEncodedSize) {
    if (error) *error = DecodeError{"message shorter than the minimum of 54 bytes", 0};
    return std::nullopt;
  }
  Message m;
  if (!decode_message_into(m, bytes, 0, error)) return std::nullopt;
  return m;
}

std::optional<std::vector<Message>> decode_packet(std::string_view packet, DecodeError* error) {
  std::vector<Message> out;
  if (!decode_packet_into(packet, out, error)) return std::nullopt;
  return out;
}

void PacketReader::feed(std::string_view bytes) {
  // Compact lazily so that a long stream of small packets does not move memory each time.
  if (consumed_ > 0 && consumed_ >= buffer_.size() / 2) {
    buffer_.erase(0, consumed_);
    consumed_ = 0;
  }
  buffer_.append(bytes.data(), bytes.size());
}

PacketReader::Status PacketReader::next(std::vector<Message>& out, DecodeError* error) {
  if (failed_) {
    if (error) *error = DecodeError{"stream already failed", 0};
    return Status::kError;
  }
  const std::size_t available = buffer_.size() - consumed_;
  if (available < kInt32Size) return Status::kNeedMore;
  const std::uint32_t total = load_u32(buffer_.data() + consumed_);
  if (total < kPacketHeaderSize || total > max_packet_bytes_) {
    failed_ = true;
    if (error)
      *error = DecodeError{"packet header announces " + std::to_string(total) +
                               " bytes (allowed 9 to " + std::to_string(max_packet_bytes_) + ")",
                           0};
    return Status::kError;
  }
  if (available < total) return Status::kNeedMore;
  const bool decoded =
      decode_packet_into(std::string_view(buffer_.data() + consumed_, total), out, error);
  consumed_ += total;
  if (!decoded) {
    failed_ = true;
    return Status::kError;
  }
  if (consumed_ == buffer_.size()) {
    buffer_.clear();
    consumed_ = 0;
  }
  return Status::kPacket;
}

std::string PacketReader::take_buffered() {
  std::string rest = buffer_.substr(consumed_);
  buffer_.clear();
  consumed_ = 0;
  return rest;
}

}  // namespace moos
