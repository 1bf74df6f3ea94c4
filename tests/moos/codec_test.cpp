// Codec and framing tests against the byte vectors of docs/protocol.md
// section 8, which were produced by libMOOS itself and by pymoos2.

#include <gtest/gtest.h>

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "moos/codec.hpp"

namespace moos {
namespace {

// Parses "40 00 00 00 ..." into bytes.
std::string hex(const std::string& text) {
  std::istringstream in(text);
  std::string out;
  std::string byte;
  while (in >> byte) out.push_back(static_cast<char>(std::stoi(byte, nullptr, 16)));
  return out;
}

constexpr double kT0 = 1700000000.0;
constexpr double kT025 = 1700000000.25;
constexpr double kT05 = 1700000000.5;
constexpr double kT0125 = 1700000000.125;

Message vector_a() {
  Message m = make_double_notify("DEPTH", 12.5, "pTest", kT025);
  m.id = 0;
  return m;
}
Message vector_b() {
  Message m = make_string_notify("MODE", "SURVEY", "pTest", kT05);
  m.id = 1;
  return m;
}

const char* kVectorA =
    "40 00 00 00 00 00 00 00 4e 44 05 00 00 00 70 54 65 73 74 00 00 00 00 00 00 00 00"
    " 05 00 00 00 44 45 50 54 48 00 00 10 40 fc 54 d9 41 00 00 00 00 00 00 29 40"
    " 00 00 00 00 00 00 f0 bf 00 00 00 00";
const char* kVectorB =
    "45 00 00 00 01 00 00 00 4e 53 05 00 00 00 70 54 65 73 74 00 00 00 00 00 00 00 00 04 00 00 00 4d"
    " 4f 44 45 00 00 20 40 fc 54 d9 41 00 00 00 00 00 00 f0 bf 00 00 00 00 00 00 f0 bf 06 00 00 00 53"
    " 55 52 56 45 59";

TEST(Codec, DoubleNotifyMatchesVectorA) {
  EXPECT_EQ(encode_message(vector_a()), hex(kVectorA));
  EXPECT_EQ(vector_a().encoded_size(), 64u);
  auto decoded = decode_message(hex(kVectorA));
  ASSERT_TRUE(decoded);
  EXPECT_EQ(*decoded, vector_a());
}

TEST(Codec, StringNotifyMatchesVectorBWithDvalMinusOne) {
  EXPECT_EQ(encode_message(vector_b()), hex(kVectorB));
  auto decoded = decode_message(hex(kVectorB));
  ASSERT_TRUE(decoded);
  EXPECT_EQ(*decoded, vector_b());
  EXPECT_EQ(decoded->dval, -1.0);
}

TEST(Codec, PacketOfTwoMatchesVectorC) {
  const std::string expected = hex(
      "8e 00 00 00 02 00 00 00 00") + hex(kVectorA) + hex(kVectorB);
  EXPECT_EQ(expected.size(), 142u);
  EXPECT_EQ(encode_packet({vector_a(), vector_b()}), expected);
  auto decoded = decode_packet(expected);
  ASSERT_TRUE(decoded);
  ASSERT_EQ(decoded->size(), 2u);
  EXPECT_EQ((*decoded)[0], vector_a());
  EXPECT_EQ((*decoded)[1], vector_b());
}

TEST(Codec, RegisterCarriesIntervalInDvalVectorD) {
  Message m;
  m.id = 2;
  m.type = msg_type::kRegister;
  m.data_type = data_type::kDouble;
  m.source = "pTest";
  m.key = "NAV_X";
  m.time = kT0;
  m.dval = 0.0;
  const std::string expected = hex(
      "40 00 00 00 02 00 00 00 52 44 05 00 00 00 70 54 65 73 74 00 00 00 00 00 00 00 00 05 00 00 00 4e"
      " 41 56 5f 58 00 00 00 40 fc 54 d9 41 00 00 00 00 00 00 00 00 00 00 00 00 00 00 f0 bf 00 00 00 00");
  EXPECT_EQ(encode_message(m), expected);
  auto decoded = decode_message(expected);
  ASSERT_TRUE(decoded);
  EXPECT_EQ(*decoded, m);
}

TEST(Codec, AsyncIdentificationPacketVectorE) {
  Message m;
  m.type = msg_type::kData;
  m.data_type = data_type::kString;
  m.key = "asynchronous";
  m.time = kT0;
  m.sval = "pTest";
  const std::string expected = hex(
      "50 00 00 00 01 00 00 00 00 47 00 00 00 ff ff ff ff 69 53 00 00 00 00 00 00 00 00 00 00 00 00 0c"
      " 00 00 00 61 73 79 6e 63 68 72 6f 6e 6f 75 73 00 00 00 40 fc 54 d9 41 00 00 00 00 00 00 f0 bf 00"
      " 00 00 00 00 00 f0 bf 05 00 00 00 70 54 65 73 74");
  EXPECT_EQ(encode_packet({m}), expected);
  auto decoded = decode_packet(expected);
  ASSERT_TRUE(decoded);
  ASSERT_EQ(decoded->size(), 1u);
  EXPECT_EQ((*decoded)[0], m);
}

TEST(Codec, WelcomePacketVectorF) {
  Message m;
  m.type = msg_type::kWelcome;
  m.data_type = data_type::kDouble;
  m.source_aux = "hostname=dbhost";
  m.community = "alpha";
  m.time = kT0;
  m.dval = 0.001;
  m.sval = "asynchronous";
  const std::string expected = hex(
      "5f 00 00 00 01 00 00 00 00 56 00 00 00 ff ff ff ff 57 44 00 00 00 00 0f 00 00 00 68 6f 73 74 6e"
      " 61 6d 65 3d 64 62 68 6f 73 74 05 00 00 00 61 6c 70 68 61 00 00 00 00 00 00 00 40 fc 54 d9 41 fc"
      " a9 f1 d2 4d 62 50 3f 00 00 00 00 00 00 f0 bf 0c 00 00 00 61 73 79 6e 63 68 72 6f 6e 6f 75 73");
  EXPECT_EQ(encode_packet({m}), expected);
  auto decoded = decode_packet(expected);
  ASSERT_TRUE(decoded);
  EXPECT_EQ((*decoded)[0], m);
}

TEST(Codec, NullKeepAliveVectorG) {
  Message m;
  m.type = msg_type::kNull;
  m.source = "pTest";
  const std::string expected = hex(
      "3b 00 00 00 ff ff ff ff 2e 44 05 00 00 00 70 54 65 73 74 00 00 00 00 00 00 00 00 00 00 00 00 00"
      " 00 00 00 00 00 f0 bf 00 00 00 00 00 00 f0 bf 00 00 00 00 00 00 f0 bf 00 00 00 00");
  EXPECT_EQ(encode_message(m), expected);
  auto decoded = decode_message(expected);
  ASSERT_TRUE(decoded);
  EXPECT_EQ(*decoded, m);
}

TEST(Codec, BinaryNotifyKeepsRawBytesVectorH) {
  Message m = make_binary_notify("BLOB", std::string("\x00\xff\x10\x7f", 4), "pTest", kT0);
  m.id = 3;
  const std::string expected = hex(
      "43 00 00 00 03 00 00 00 4e 42 05 00 00 00 70 54 65 73 74 00 00 00 00 00 00 00 00 04 00 00 00 42"
      " 4c 4f 42 00 00 00 40 fc 54 d9 41 00 00 00 00 00 00 f0 bf 00 00 00 00 00 00 f0 bf 04 00 00 00 00"
      " ff 10 7f");
  EXPECT_EQ(encode_message(m), expected);
  auto decoded = decode_message(expected);
  ASSERT_TRUE(decoded);
  EXPECT_EQ(*decoded, m);
  EXPECT_TRUE(decoded->is_binary());
}

Message timing(double time, double dval, double dval2) {
  Message m;
  m.type = msg_type::kTiming;
  m.data_type = data_type::kDouble;
  m.key = "_async_timing";
  m.time = time;
  m.dval = dval;
  m.dval2 = dval2;
  return m;
}

TEST(Codec, TimingAndEchoVectorsIJ) {
  const std::string i = hex(
      "4c 00 00 00 01 00 00 00 00 43 00 00 00 ff ff ff ff 54 44 00 00 00 00 00 00 00 00 00 00 00 00 0d"
      " 00 00 00 5f 61 73 79 6e 63 5f 74 69 6d 69 6e 67 00 00 00 40 fc 54 d9 41 00 00 00 00 00 00 00 00"
      " 00 00 00 00 00 00 f0 bf 00 00 00 00");
  const std::string j = hex(
      "4c 00 00 00 01 00 00 00 00 43 00 00 00 ff ff ff ff 54 44 00 00 00 00 00 00 00 00 00 00 00 00 0d"
      " 00 00 00 5f 61 73 79 6e 63 5f 74 69 6d 69 6e 67 00 00 00 40 fc 54 d9 41 00 00 08 40 fc 54 d9 41"
      " 00 00 00 00 00 00 00 00 00 00 00 00");
  EXPECT_EQ(encode_packet({timing(kT0, 0.0, -1.0)}), i);
  EXPECT_EQ(encode_packet({timing(kT0, kT0125, 0.0)}), j);
  auto decoded = decode_packet(j);
  ASSERT_TRUE(decoded);
  EXPECT_EQ((*decoded)[0], timing(kT0, kT0125, 0.0));
}

TEST(Codec, ServerNullReplyVectorK) {
  Message m;
  m.type = msg_type::kNull;
  m.time = -1;
  m.dval = kT0125;
  const std::string expected = hex(
      "3f 00 00 00 01 00 00 00 00 36 00 00 00 ff ff ff ff 2e 44 00 00 00 00 00 00 00 00 00 00 00 00 00"
      " 00 00 00 00 00 00 00 00 00 f0 bf 00 00 08 40 fc 54 d9 41 00 00 00 00 00 00 f0 bf 00 00 00 00");
  EXPECT_EQ(encode_packet({m}), expected);
}

TEST(Codec, WildcardRegisterVectorL) {
  Message m;
  m.id = 4;
  m.type = msg_type::kWildcardRegister;
  m.data_type = data_type::kString;
  m.source = "pTest";
  m.key = "pTest";
  m.time = kT0;
  m.sval = "AppPattern=*,VarPattern=NAV_*,Interval=0.5";
  const std::string expected = hex(
      "73 00 00 00 01 00 00 00 00 6a 00 00 00 04 00 00 00 2a 53 05 00 00 00 70 54 65 73 74 00 00 00 00"
      " 00 00 00 00 05 00 00 00 70 54 65 73 74 00 00 00 40 fc 54 d9 41 00 00 00 00 00 00 f0 bf 00 00 00"
      " 00 00 00 f0 bf 2a 00 00 00 41 70 70 50 61 74 74 65 72 6e 3d 2a 2c 56 61 72 50 61 74 74 65 72 6e"
      " 3d 4e 41 56 5f 2a 2c 49 6e 74 65 72 76 61 6c 3d 30 2e 35");
  EXPECT_EQ(encode_packet({m}), expected);
}

TEST(Codec, ServerRequestVectorM) {
  Message m;
  m.id = kServerRequestId;
  m.type = msg_type::kServerRequest;
  m.data_type = data_type::kString;
  m.source = "pTest";
  m.key = "VAR_SUMMARY";
  m.time = kT0;
  const std::string expected = hex(
      "4f 00 00 00 01 00 00 00 00 46 00 00 00 fe ff ff ff 51 53 05 00 00 00 70 54 65 73 74 00 00 00 00"
      " 00 00 00 00 0b 00 00 00 56 41 52 5f 53 55 4d 4d 41 52 59 00 00 00 40 fc 54 d9 41 00 00 00 00 00"
      " 00 f0 bf 00 00 00 00 00 00 f0 bf 00 00 00 00");
  EXPECT_EQ(encode_packet({m}), expected);
}

TEST(Codec, PoisonVectorN) {
  Message m;
  m.type = msg_type::kPoison;
  m.data_type = data_type::kString;
  m.time = kT0;
  m.sval = "A client of this name (\"pTest\") already exists";
  const std::string expected = hex(
      "6d 00 00 00 01 00 00 00 00 64 00 00 00 ff ff ff ff 4b 53 00 00 00 00 00 00 00 00 00 00 00 00 00"
      " 00 00 00 00 00 00 40 fc 54 d9 41 00 00 00 00 00 00 f0 bf 00 00 00 00 00 00 f0 bf 2e 00 00 00 41"
      " 20 63 6c 69 65 6e 74 20 6f 66 20 74 68 69 73 20 6e 61 6d 65 20 28 22 70 54 65 73 74 22 29 20 61"
      " 6c 72 65 61 64 79 20 65 78 69 73 74 73");
  EXPECT_EQ(encode_packet({m}), expected);
  auto decoded = decode_packet(expected);
  ASSERT_TRUE(decoded);
  EXPECT_EQ((*decoded)[0], m);
}

TEST(Banner, IsThirtyTwoBytesAndMatchesCaseInsensitively) {
  const std::string banner = protocol_banner();
  ASSERT_EQ(banner.size(), 32u);
  EXPECT_EQ(banner.substr(0, 16), "ELKS CAN'T DANCE");
  EXPECT_EQ(banner.substr(23), std::string(9, '\0'));
  EXPECT_TRUE(banner_matches(banner));
  std::string lower = "elks can't dance 2/8/10";
  lower.resize(32, '\0');
  EXPECT_TRUE(banner_matches(lower));
  std::string old = "ELKS CAN'T DANCE 30/7/10";
  old.resize(32, '\0');
  EXPECT_FALSE(banner_matches(old));
  EXPECT_FALSE(banner_matches(std::string(32, '\0')));
}

TEST(DecodeErrors, RejectLengthBelowMinimum) {
  std::string bytes = hex(kVectorA);
  bytes[0] = 53;  // one less than the 54-byte minimum
  std::string packet = hex("00 00 00 00 01 00 00 00 00") + bytes;
  packet[0] = static_cast<char>(packet.size());
  DecodeError error;
  EXPECT_FALSE(decode_packet(packet, &error));
  EXPECT_NE(error.reason.find("below the minimum"), std::string::npos) << error.reason;
}

TEST(DecodeErrors, RejectNegativeStringLength) {
  std::string bytes = hex(kVectorA);
  bytes[10] = '\xff';  // source length -> 0xffffff05 (negative)
  bytes[11] = '\xff';
  bytes[12] = '\xff';
  bytes[13] = '\xff';
  DecodeError error;
  EXPECT_FALSE(decode_message(bytes, &error));
  EXPECT_NE(error.reason.find("source"), std::string::npos) << error.reason;
}

TEST(DecodeErrors, RejectStringRunningPastMessageEnd) {
  std::string bytes = hex(kVectorB);
  bytes[bytes.size() - 10] = 0x40;  // string value claims 64 bytes but only 6 remain
  DecodeError error;
  EXPECT_FALSE(decode_message(bytes, &error));
}

TEST(DecodeErrors, RejectLengthFieldDisagreeingWithContent) {
  std::string bytes = hex(kVectorA) + std::string(4, '\0');
  bytes[0] = 68;  // claims 68 bytes; fields consume 64
  DecodeError error;
  EXPECT_FALSE(decode_message(bytes, &error));
  EXPECT_NE(error.reason.find("length field"), std::string::npos) << error.reason;
}

TEST(DecodeErrors, RejectCountThatCannotFit) {
  std::string packet = encode_packet({vector_a()});
  packet[4] = 100;  // 100 messages cannot fit in 64 bytes
  DecodeError error;
  EXPECT_FALSE(decode_packet(packet, &error));
}

TEST(DecodeErrors, RejectNegativeMessageCount) {
  std::string packet = encode_packet({vector_a()});
  packet[4] = packet[5] = packet[6] = packet[7] = '\xff';  // count -1
  DecodeError error;
  EXPECT_FALSE(decode_packet(packet, &error));
  EXPECT_NE(error.reason.find("negative message count -1"), std::string::npos) << error.reason;
}

TEST(PacketReader, ReassemblesOneByteAtATime) {
  const std::string stream = encode_packet({vector_a(), vector_b()}) + encode_packet({vector_b()});
  PacketReader reader;
  std::vector<std::vector<Message>> packets;
  for (char c : stream) {
    reader.feed(std::string_view(&c, 1));
    std::vector<Message> out;
    while (reader.next(out) == PacketReader::Status::kPacket) packets.push_back(out);
  }
  ASSERT_EQ(packets.size(), 2u);
  ASSERT_EQ(packets[0].size(), 2u);
  EXPECT_EQ(packets[0][1], vector_b());
  ASSERT_EQ(packets[1].size(), 1u);
  EXPECT_EQ(reader.buffered(), 0u);
}

TEST(PacketReader, ManyPacketsInOneRead) {
  std::string stream;
  for (int i = 0; i < 1000; ++i) {
    Message m = make_double_notify("X", i, "pTest", kT0);
    m.id = i;
    stream += encode_packet({m});
  }
  PacketReader reader;
  reader.feed(stream);
  std::vector<Message> out;
  int count = 0;
  while (reader.next(out) == PacketReader::Status::kPacket) {
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].dval, count);
    ++count;
  }
  EXPECT_EQ(count, 1000);
}

TEST(PacketReader, RefusesHugeHeaderBeforeAllocating) {
  PacketReader reader(1024 * 1024);
  reader.feed(hex("00 00 00 80"));  // claims 2 GiB
  std::vector<Message> out;
  DecodeError error;
  EXPECT_EQ(reader.next(out, &error), PacketReader::Status::kError);
  EXPECT_NE(error.reason.find("announces"), std::string::npos);
  EXPECT_EQ(reader.next(out, &error), PacketReader::Status::kError);
}

TEST(PacketReader, RefusesHeaderShorterThanNineBytes) {
  PacketReader reader;
  reader.feed(hex("05 00 00 00 00"));
  std::vector<Message> out;
  EXPECT_EQ(reader.next(out), PacketReader::Status::kError);
}

TEST(PacketReader, KeepsBytesOfTheNextPacket) {
  const std::string p1 = encode_packet({vector_a()});
  const std::string p2 = encode_packet({vector_b()});
  PacketReader reader;
  reader.feed(p1 + p2.substr(0, 10));
  std::vector<Message> out;
  ASSERT_EQ(reader.next(out), PacketReader::Status::kPacket);
  EXPECT_EQ(reader.next(out), PacketReader::Status::kNeedMore);
  EXPECT_EQ(reader.take_buffered(), p2.substr(0, 10));
}

// A reader handed the same vector each time overwrites its messages in place: the strings the
// last packet left are reused, not reallocated (the sensor decodes thousands a second).
TEST(PacketReader, OverwritesTheCallersMessagesInPlace) {
  const std::string long_value(200, 'v');
  Message first = make_string_notify("A_KEY_LONGER_THAN_SSO", long_value, "pLongSourceName", kT0);
  Message second = first;
  second.sval = std::string(150, 'w');
  second.id = 7;
  PacketReader reader;
  reader.feed(encode_packet({first}) + encode_packet({second, vector_a()}));
  std::vector<Message> out;
  ASSERT_EQ(reader.next(out), PacketReader::Status::kPacket);
  ASSERT_EQ(out.size(), 1u);
  const char* const sval_storage = out[0].sval.data();
  const Message* const storage = out.data();
  ASSERT_EQ(reader.next(out), PacketReader::Status::kPacket);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0], second);
  EXPECT_EQ(out[1], vector_a());
  EXPECT_EQ(out[0].sval.data(), sval_storage);  // the 200-byte buffer holds the 150 bytes
  EXPECT_NE(out.data(), storage);               // grown to two messages
}

// write_packet: the lead message first, then the slice, over whatever `out` held.
TEST(Codec, WritePacketPutsTheLeadFirstAndReplacesTheBuffer) {
  const Message lead = make_double_notify(std::string(kTimingKey), 0.0, "", kT0);
  const std::vector<Message> rest = {vector_a(), vector_b()};
  std::string out = "stale bytes of an earlier packet";
  write_packet(out, &lead, rest.data(), rest.data() + rest.size());
  EXPECT_EQ(out, encode_packet({lead, vector_a(), vector_b()}));
  write_packet(out, nullptr, rest.data(), rest.data() + 1);
  EXPECT_EQ(out, encode_packet({vector_a()}));
}

// A sender's buffer keeps its capacity from packet to packet, but not a burst's megabytes.
TEST(Codec, WritePacketLetsABurstsBufferGo) {
  const Message big = make_string_notify("BIG", std::string(3u << 20, 'b'), "pBig", kT0);
  std::string out;
  write_packet(out, nullptr, &big, &big + 1);
  ASSERT_GE(out.capacity(), 3u << 20);
  const Message small = vector_a();
  write_packet(out, nullptr, &small, &small + 1);
  EXPECT_EQ(out, encode_packet({small}));
  EXPECT_LT(out.capacity(), 1u << 20);
  const std::size_t kept = out.capacity();
  write_packet(out, nullptr, &small, &small + 1);
  EXPECT_EQ(out.capacity(), kept);
}

}  // namespace
}  // namespace moos
