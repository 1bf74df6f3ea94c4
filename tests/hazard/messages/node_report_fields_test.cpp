// NodeReportFields (the one-pass scan parse_node_report reads) against the generic rule it
// replaces: base::split_key_values(text, ',', braces), each key compared with base::iequals, the
// last one winning, numbers read by base::parse_number. Generated texts near and off the format.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "base/text.hpp"
#include "hazard/messages/node_report_fields.hpp"

namespace hazard {
namespace {

struct Slot {
  const char* key;
  NodeReportField NodeReportFields::*field;
};
constexpr Slot kSlots[] = {
    {"NAME", &NodeReportFields::name}, {"X", &NodeReportFields::x},
    {"Y", &NodeReportFields::y},       {"SPD", &NodeReportFields::spd},
    {"SPEED", &NodeReportFields::speed}, {"HDG", &NodeReportFields::hdg},
    {"HEADING", &NodeReportFields::heading}, {"LAT", &NodeReportFields::lat},
    {"LON", &NodeReportFields::lon},   {"TIME", &NodeReportFields::time},
    {"TYPE", &NodeReportFields::type}};

// The generic rule: the last piece with '=' whose key is `key`, as a view into `text`.
std::optional<std::string_view> reference_value(std::string_view text, std::string_view key) {
  std::optional<std::string_view> found;
  for (const base::KeyValue& kv : base::split_key_values(text, ',', /*respect_braces=*/true))
    if (kv.has_equals && base::iequals(kv.key, key)) found = kv.value;
  return found;
}

std::uint64_t bits(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

void expect_fields_as_the_rule_finds_them(const std::string& text, bool pose_only) {
  const NodeReportFields fields(text, pose_only);
  for (const Slot& slot : kSlots) {
    const NodeReportField& got = fields.*slot.field;
    const auto want = reference_value(text, slot.key);
    ASSERT_EQ(got.present, want.has_value()) << slot.key << " in '" << text << "'";
    if (!want) continue;
    // The same view: the same bytes at the same place.
    ASSERT_EQ(got.text.data(), want->data()) << slot.key << " in '" << text << "'";
    ASSERT_EQ(got.text.size(), want->size()) << slot.key << " in '" << text << "'";
    if (pose_only && (slot.field == &NodeReportFields::lat || slot.field == &NodeReportFields::lon ||
                      slot.field == &NodeReportFields::time)) {
      ASSERT_FALSE(got.has_number) << slot.key << " in '" << text << "'";
    }
    if (!got.has_number) continue;
    const auto number = base::parse_number(got.text);
    ASSERT_TRUE(number) << slot.key << " in '" << text << "'";
    ASSERT_EQ(bits(got.number), bits(*number)) << slot.key << " in '" << text << "'";
  }
}

// Both forms of the scan: every number read, and the pose's only.
void expect_fields_as_the_rule_finds_them(const std::string& text) {
  expect_fields_as_the_rule_finds_them(text, /*pose_only=*/false);
  expect_fields_as_the_rule_finds_them(text, /*pose_only=*/true);
}

std::string pick(std::mt19937_64& rng, const std::vector<std::string>& from) {
  return from[rng() % from.size()];
}

std::string digits(std::mt19937_64& rng, int max_count) {
  std::string out;
  const int n = static_cast<int>(rng() % static_cast<std::uint64_t>(max_count + 1));
  for (int i = 0; i < n; ++i) out.push_back(static_cast<char>('0' + rng() % 10));
  return out;
}

std::string value(std::mt19937_64& rng) {
  switch (rng() % 6) {
    case 0:
      return pick(rng, {"archie", "", " b ", "{a,b}", "a=b", "{x", "}", "UUV", "nan", "1e3"});
    case 1:  // a plain decimal, sometimes too long or too precise for one division
      return std::string(rng() % 3 == 0 ? "-" : rng() % 5 == 0 ? "+" : "") +
             digits(rng, rng() % 6 == 0 ? 24 : 6) + (rng() % 2 ? "." + digits(rng, 12) : "");
    case 2:
      return pick(rng, {" 12", "12 ", "1.5e2", "0x10", "-", ".", "5.", ".5", "1.2.3", "--1"});
    case 3:
      return "9007199254740993";  // just above 2^53: from_chars, not the division
    default:
      return digits(rng, 4) + "." + digits(rng, 8);
  }
}

std::string generated_text(std::mt19937_64& rng) {
  static const std::vector<std::string> keys = {
      "NAME", "name", "X",   "x",   "Y",    "SPD",   "Speed", "HDG",  "heading", "LAT", "lon",
      "TIME", "TYPE", "tYpE", " X ", "XX", "LENGTH", "MODE", "N{AME", "",     "H DG", "SPD\t"};
  std::string out;
  const int pieces = static_cast<int>(rng() % 12);
  for (int i = 0; i < pieces; ++i) {
    if (i > 0) out += rng() % 10 == 0 ? ",," : ",";
    out += pick(rng, keys);
    if (rng() % 8 != 0) out += "=" + value(rng);
  }
  // Now and then a stray separator, brace, '=' or blank anywhere.
  if (rng() % 4 == 0) out.insert(rng() % (out.size() + 1), 1, ",={} \t"[rng() % 6]);
  if (rng() % 8 == 0) out += ",";
  return out;
}

TEST(NodeReportFields, GeneratedTextsGiveWhatTheGenericRuleGives) {
  std::mt19937_64 rng(20261128);
  for (int i = 0; i < 200000; ++i) {
    expect_fields_as_the_rule_finds_them(generated_text(rng));
    if (HasFatalFailure()) return;
  }
}

TEST(NodeReportFields, HandPickedTexts) {
  for (const char* text :
       {"", ",", "=", "X", "X=", "X=,", "X=1", "X=1,", "x=1,X=2", "X={1,2},Y=3", "X=1{,}2,Y=3",
        "N{AME=a,b}=c,X=1", "NAME=a=b,X= 1 ,Y=2 ", "X=1e3,Y=.5,SPD=5.,HDG=-0",
        "NAME=archie,X=-145,Y=-388.53,SPD=1.5,HDG=180,LAT=43.82180313,LON=-70.33220245,"
        "TIME=1700000250,TYPE=UUV"}) {
    expect_fields_as_the_rule_finds_them(text);
  }
}

}  // namespace
}  // namespace hazard
