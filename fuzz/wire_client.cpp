// Fuzz target: the client side of the MOOS wire protocol: the bytes a server sends, cut into
// TCP segments of fuzzer-chosen sizes, reassembled by PacketReader and decoded; the same bytes
// are also decoded whole as one packet and as one message. A decoded packet is encoded again and
// must decode to the same messages.

#include <cstdlib>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>

#include "moos/codec.hpp"

namespace {

/// A small limit, so the fuzzer reaches the "packet too large" refusal too.
constexpr std::size_t kMaxPacketBytes = 1u << 16;

void check_round_trip(const std::vector<moos::Message>& messages) {
  const auto again = moos::decode_packet(moos::encode_packet(messages));
  if (!again || *again != messages) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider input(data, size);
  const std::size_t segment_seed = input.ConsumeIntegral<std::uint8_t>();
  const std::string stream = input.ConsumeRemainingBytesAsString();

  (void)moos::decode_message(stream);
  if (const auto whole = moos::decode_packet(stream)) check_round_trip(*whole);

  moos::PacketReader reader(kMaxPacketBytes);
  std::size_t at = 0;
  const std::size_t segment = 1 + segment_seed % 64;
  while (at < stream.size()) {
    reader.feed(std::string_view(stream).substr(at, segment));
    at += segment;
    std::vector<moos::Message> packet;
    moos::DecodeError error;
    moos::PacketReader::Status status;
    while ((status = reader.next(packet, &error)) == moos::PacketReader::Status::kPacket)
      check_round_trip(packet);
    if (status == moos::PacketReader::Status::kError) break;
  }
  return 0;
}
