// The Comms base: messages built exactly as libMOOS builds them (docs/protocol.md 2.6, vectors D
// and L
// of section 8), the subscription book and its replay, and the wildcard pattern language (4.1, 5.5).
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "moos/codec.hpp"
#include "moos/comms.hpp"
#include "moos/wildcard.hpp"

namespace moos {
namespace test {

// Shared with the other libmoos test files: "40 00 0a ..." into bytes.
std::string hex_bytes(const std::string& spaced_hex) {
  std::string out;
  int nibbles = 0;
  unsigned value = 0;
  for (char c : spaced_hex) {
    unsigned digit = 0;
    if (c >= '0' && c <= '9') digit = static_cast<unsigned>(c - '0');
    else if (c >= 'a' && c <= 'f') digit = static_cast<unsigned>(c - 'a' + 10);
    else continue;
    value = value * 16 + digit;
    if (++nibbles == 2) {
      out.push_back(static_cast<char>(value));
      nibbles = 0;
      value = 0;
    }
  }
  return out;
}

}  // namespace test

namespace {

using test::hex_bytes;

/// What a transport may leave in a message it was given (Comms::transmit may leave anything;
/// the in-process bus leaves the storage of the mail it wrote over): something else in every
/// field.
void leave_litter(Message& msg) {
  msg.id = 77;
  msg.type = msg_type::kCommand;
  msg.data_type = data_type::kNotSet;
  msg.source = std::string(40, 's');
  msg.source_aux = "left";
  msg.community = "left";
  msg.key = "LEFT";
  msg.time = msg.dval = msg.dval2 = 42.0;
  msg.sval = std::string(100, 'v');
}

/// A Comms that records what it would send, with a settable connection state.
class RecordingComms final : public Comms {
 public:
  explicit RecordingComms(std::string posted_community = {})
      : Comms("pTest", /*takes_fetch_promises=*/true, std::move(posted_community)) {}
  bool is_connected() const override { return connected; }
  std::uint64_t connection_count() const override { return 1; }
  std::string community() const override { return "alpha"; }
  Clock& clock() const override { return clock_; }
  double time_warp() const override { return 1.0; }
  double skew_s() const override { return 0.0; }
  void fetch_into(std::vector<Message>& mail) override { mail.clear(); }
  using Comms::replay_messages;

  bool connected = true;
  /// Leave something else in every field of each message sent (see leave_litter).
  bool litter = false;
  std::vector<Message> sent;

 protected:
  bool transmit(Message&& msg) override {
    if (!connected) return false;
    if (!litter) {
      sent.push_back(std::move(msg));
      return true;
    }
    sent.push_back(msg);
    leave_litter(msg);
    return true;
  }

 private:
  mutable ManualClock clock_{1700000000.0};
};

constexpr const char* kVectorD =
    "40 00 00 00 02 00 00 00 52 44 05 00 00 00 70 54 65 73 74 00 00 00 00 00 00 00 00 05 00 00 00"
    " 4e 41 56 5f 58 00 00 00 40 fc 54 d9 41 00 00 00 00 00 00 00 00 00 00 00 00 00 00 f0 bf 00 00"
    " 00 00";
constexpr const char* kVectorLMessage =
    "6a 00 00 00 04 00 00 00 2a 53 05 00 00 00 70 54 65 73 74 00 00 00 00 00 00 00 00 05 00 00 00"
    " 70 54 65 73 74 00 00 00 40 fc 54 d9 41 00 00 00 00 00 00 f0 bf 00 00 00 00 00 00 f0 bf 2a 00"
    " 00 00 41 70 70 50 61 74 74 65 72 6e 3d 2a 2c 56 61 72 50 61 74 74 65 72 6e 3d 4e 41 56 5f 2a"
    " 2c 49 6e 74 65 72 76 61 6c 3d 30 2e 35";

TEST(CommsMessages, RegisterIsBuiltAsVectorD_2_6) {
  RecordingComms c;
  ASSERT_TRUE(c.register_variable("NAV_X", 0.0));
  ASSERT_EQ(c.sent.size(), 1u);
  Message m = c.sent[0];
  m.id = 2;  // ids are the transport's business; the vector used id 2
  EXPECT_EQ(encode_message(m), hex_bytes(kVectorD));
}

TEST(CommsMessages, WildcardRegisterIsBuiltAsVectorL_2_6) {
  RecordingComms c;
  ASSERT_TRUE(c.register_wildcard("NAV_*", "*", 0.5));
  ASSERT_EQ(c.sent.size(), 1u);
  Message m = c.sent[0];
  m.id = 4;
  EXPECT_EQ(encode_message(m), hex_bytes(kVectorLMessage));
}

TEST(CommsMessages, UnregisterAndWildcardUnregisterFields_2_6) {
  RecordingComms c;
  c.register_variable("X", 2.0);
  c.unregister_variable("X");
  c.unregister_wildcard("NAV_*", "pA");
  ASSERT_EQ(c.sent.size(), 3u);
  EXPECT_EQ(c.sent[1].type, msg_type::kUnregister);
  EXPECT_EQ(c.sent[1].key, "X");
  EXPECT_EQ(c.sent[1].dval, 0.0);
  EXPECT_EQ(c.sent[2].type, msg_type::kWildcardUnregister);
  EXPECT_EQ(c.sent[2].key, "pTest");
  EXPECT_EQ(c.sent[2].sval, "AppPattern=pA,VarPattern=NAV_*,Interval=0");
}

TEST(CommsMessages, NotifyFieldsFollowLibMoosDefaults_2_2) {
  RecordingComms c;
  c.notify("D", 1.5);
  c.notify("S", std::string("txt"), 5.0, "aux");
  c.notify_binary("B", std::string("\0\1", 2));
  Message custom;
  custom.key = "C";
  custom.data_type = data_type::kString;
  custom.sval = "v";
  custom.source = "ignored";
  c.post(custom);
  ASSERT_EQ(c.sent.size(), 4u);
  EXPECT_EQ(c.sent[0].dval, 1.5);
  EXPECT_EQ(c.sent[0].dval2, kUnsetDouble);
  EXPECT_EQ(c.sent[0].time, 1700000000.0);  // "now" in MOOS time
  EXPECT_EQ(c.sent[1].dval, kUnsetDouble);
  EXPECT_EQ(c.sent[1].time, 5.0);
  EXPECT_EQ(c.sent[1].source_aux, "aux");
  EXPECT_TRUE(c.sent[2].is_binary());
  EXPECT_EQ(c.sent[2].sval.size(), 2u);
  EXPECT_EQ(c.sent[3].type, msg_type::kNotify);
  EXPECT_EQ(c.sent[3].source, "pTest");
  EXPECT_EQ(c.sent[3].time, 1700000000.0);  // -1 means now
  for (const auto& m : c.sent) EXPECT_EQ(m.community, "");  // libMOOS leaves it empty
}

TEST(CommsMessages, ATransportsPostedCommunityIsInEveryNotifyWhateverWasLeft) {
  RecordingComms c("alpha");  // as BusClient passes its bus's community
  c.litter = true;            // each message sent leaves "left" in the community
  c.notify("S", std::string("text"));
  c.notify("D", 1.5);
  c.notify_binary("B", std::string("\0\1", 2));
  ASSERT_EQ(c.sent.size(), 3u);
  for (const auto& m : c.sent) EXPECT_EQ(m.community, "alpha");
}

TEST(CommsMessages, EachNotifyIsBuiltWholeWhateverTheTransportLeftOfTheLast) {
  RecordingComms c;
  c.litter = true;
  const double now = 1700000000.0;
  c.notify("S", std::string("text"), 5.0, "aux");
  c.notify("D", 1.5);
  c.notify_binary("B", std::string("\0\1", 2));
  c.notify("S", std::string("again"));
  Message with_aux = make_string_notify("S", "text", "pTest", 5.0);
  with_aux.source_aux = "aux";
  const std::vector<Message> expected = {
      with_aux, make_double_notify("D", 1.5, "pTest", now),
      make_binary_notify("B", std::string("\0\1", 2), "pTest", now),
      make_string_notify("S", "again", "pTest", now)};
  EXPECT_EQ(c.sent, expected);
}

TEST(CommsBook, RegistrationsAreRememberedWhileDisconnectedAndReplayedInOrder_1_9) {
  RecordingComms c;
  c.connected = false;
  EXPECT_TRUE(c.register_variable("B", 1.0));
  EXPECT_TRUE(c.register_wildcard("NAV_*"));
  EXPECT_TRUE(c.register_variable("A"));
  EXPECT_TRUE(c.register_variable("B", 2.0));  // updates the interval, keeps its place
  EXPECT_TRUE(c.unregister_variable("A"));
  EXPECT_TRUE(c.sent.empty());
  EXPECT_FALSE(c.notify("X", 1.0));  // posting needs a connection
  const auto replay = c.replay_messages();
  ASSERT_EQ(replay.size(), 2u);
  EXPECT_EQ(replay[0].type, msg_type::kRegister);
  EXPECT_EQ(replay[0].key, "B");
  EXPECT_EQ(replay[0].dval, 2.0);
  EXPECT_EQ(replay[1].type, msg_type::kWildcardRegister);
  EXPECT_EQ(replay[1].sval, "AppPattern=*,VarPattern=NAV_*,Interval=0");
  c.unregister_wildcard("NAV_*");
  EXPECT_EQ(c.replay_messages().size(), 1u);
}

TEST(CommsBook, EveryPostedNameIsPublishedHoweverManyAreRepeated_7_1) {
  RecordingComms c;
  // More names than the book remembers as recent, in turns: each still counts once.
  const std::vector<std::string> names = {"A", "B", "C", "D", "E", "F"};
  for (int round = 0; round < 3; ++round)
    for (const auto& name : names) ASSERT_TRUE(c.notify(name, 1.0));
  EXPECT_EQ(c.published_names(), std::set<std::string>(names.begin(), names.end()));
  EXPECT_EQ(c.sent.size(), 18u);
  // A recent name is still refused while disconnected, and a refused new name is not listed.
  c.connected = false;
  EXPECT_FALSE(c.notify("F", 2.0));
  EXPECT_FALSE(c.notify("G", 2.0));
  EXPECT_EQ(c.published_names().count("G"), 0u);
  EXPECT_EQ(c.sent.size(), 18u);
}

TEST(Wildcard, StarAndQuestionMarkWholeStringCaseSensitive_4_1) {
  EXPECT_TRUE(wildcard_match("*", ""));
  EXPECT_TRUE(wildcard_match("*", "ANYTHING"));
  EXPECT_TRUE(wildcard_match("NAV_*", "NAV_X"));
  EXPECT_TRUE(wildcard_match("NAV_*", "NAV_"));
  EXPECT_FALSE(wildcard_match("NAV_*", "nav_x"));
  EXPECT_FALSE(wildcard_match("NAV_*", "XNAV_X"));
  EXPECT_TRUE(wildcard_match("*_X", "NAV_X"));
  EXPECT_TRUE(wildcard_match("N?V_*", "NAV_SPEED"));
  EXPECT_FALSE(wildcard_match("N?V", "NV"));
  EXPECT_TRUE(wildcard_match("a*b*c", "aXXbYYbc"));
  EXPECT_FALSE(wildcard_match("a*b*c", "aXXbYYb"));
  EXPECT_TRUE(wildcard_match("", ""));
  EXPECT_FALSE(wildcard_match("", "x"));  // an empty pattern matches only the empty string (5.5)
  EXPECT_TRUE(wildcard_match("**a", "a"));
}

TEST(Wildcard, PathologicalPatternIsFast) {
  const std::string text(2000, 'a');
  const std::string pattern = std::string(50, '*').insert(25, "a") + "b";
  EXPECT_FALSE(wildcard_match(pattern, text));
}

TEST(Wildcard, SpecStringRoundTripsAndAcceptsPymoosSpaces_5_5) {
  EXPECT_EQ(format_wildcard_spec({"*", "NAV_*", 0.5}), "AppPattern=*,VarPattern=NAV_*,Interval=0.5");
  EXPECT_EQ(format_wildcard_spec({"p", "X", 1e-05}), "AppPattern=p,VarPattern=X,Interval=1e-05");
  const auto commas = parse_wildcard_spec("AppPattern=*,VarPattern=NAV_*,Interval=0.5");
  EXPECT_EQ(commas.app_pattern, "*");
  EXPECT_EQ(commas.var_pattern, "NAV_*");
  EXPECT_EQ(commas.interval_s, 0.5);
  const auto spaces = parse_wildcard_spec("AppPattern=* VarPattern=X_* Interval=0.0");
  EXPECT_EQ(spaces.app_pattern, "*");
  EXPECT_EQ(spaces.var_pattern, "X_*");
  EXPECT_EQ(spaces.interval_s, 0.0);
  const auto missing = parse_wildcard_spec("VarPattern=A");
  EXPECT_EQ(missing.app_pattern, "");
  EXPECT_EQ(missing.interval_s, 0.0);
  EXPECT_EQ(parse_wildcard_spec("Interval=abc").interval_s, 0.0);
}

}  // namespace
}  // namespace moos
