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

void put_int32(std::string& out, std::int32_t value) {
  const auto u = static_cast<std::uint32_t>(value);
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<char>((u >> shift) & 0xffu));
}

/// A size written as a 32-bit length field: checked before it is narrowed.
void put_length(std::string& out, std::size_t size, const char* what) {
  if (size > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::length_error(std::string(what) + " of " + std::to_string(size) +
                            " bytes does not fit a 32-bit length field");
  put_int32(out, static_cast<std::int32_t>(size));
}

void put_double(std::string& out, double value) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (int shift = 0; shift < 64; shift += 8) out.push_back(static_cast<char>((bits >> shift) & 0xffu));
}

void put_string(std::string& out, const std::string& s) {
  put_length(out, s.size(), "a string");
  out.append(s);
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

std::optional<std::vector<Message>> decode_packet_at(std::string_view packet, DecodeError* error) {
  auto fail = [&](std::string reason, std::size_t offset) -> std::optional<std::vector<Message>> {
    if (error) *error = DecodeError{std::move(reason), offset};
    return std::nullopt;
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

  std::vector<Message> out;
  out.reserve(static_cast<std::size_t>(count));
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
    if (!decode_message_into(out.emplace_back(),
                             packet.substr(pos, static_cast<std::size_t>(length)), pos, &inner))
      return fail("message " + std::to_string(i) + ": " + inner.reason, inner.offset);
    pos += static_cast<std::size_t>(length);
  }
  if (pos != packet.size())
    return fail(std::to_string(packet.size() - pos) + " bytes left after the last message", pos);
  return out;
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
  put_length(out, size, "a message");
  out.reserve(out.size() + size);
  put_int32(out, msg.id);
  out.push_back(msg.type);
  out.push_back(msg.data_type);
  put_string(out, msg.source);
  put_string(out, msg.source_aux);
  put_string(out, msg.community);
  put_string(out, msg.key);
  put_double(out, msg.time);
  put_double(out, msg.dval);
  put_double(out, msg.dval2);
  put_string(out, msg.sval);
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
  std::size_t total = kPacketHeaderSize;
  for (const Message* m = first; m != last; ++m) total += m->encoded_size();
  std::string out;
  put_length(out, total, "a packet");  // before the allocation it would size
  out.reserve(total);
  put_length(out, static_cast<std::size_t>(last - first), "a message count");
  out.push_back('\0');  // compression flag: v10 has no compression (protocol.md 3.2)
  for (const Message* m = first; m != last; ++m) append_message(out, *m);
  return out;
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
  return decode_packet_at(packet, error);
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
  auto messages = decode_packet_at(std::string_view(buffer_.data() + consumed_, total), error);
  consumed_ += total;
  if (!messages) {
    failed_ = true;
    return Status::kError;
  }
  out = std::move(*messages);
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
