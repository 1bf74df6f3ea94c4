#include "moos/message.hpp"

#include <cstring>
#include <utility>

namespace moos {

namespace {
// Doubles compare bit for bit so that NaN payloads and -0.0 round-trip exactly in tests.
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
}  // namespace

bool operator==(const Message& a, const Message& b) {
  return a.id == b.id && a.type == b.type && a.data_type == b.data_type && a.source == b.source &&
         a.source_aux == b.source_aux && a.community == b.community && a.key == b.key &&
         same_bits(a.time, b.time) && same_bits(a.dval, b.dval) && same_bits(a.dval2, b.dval2) &&
         a.sval == b.sval;
}

void swap(Message& a, Message& b) noexcept {
  using std::swap;
  swap(a.id, b.id);
  swap(a.type, b.type);
  swap(a.data_type, b.data_type);
  a.source.swap(b.source);
  a.source_aux.swap(b.source_aux);
  a.community.swap(b.community);
  a.key.swap(b.key);
  swap(a.time, b.time);
  swap(a.dval, b.dval);
  swap(a.dval2, b.dval2);
  a.sval.swap(b.sval);
}

Message make_double_notify(std::string key, double value, std::string source, double time) {
  Message m;
  m.type = msg_type::kNotify;
  m.data_type = data_type::kDouble;
  m.key = std::move(key);
  m.dval = value;
  m.source = std::move(source);
  m.time = time;
  return m;
}

Message make_string_notify(std::string key, std::string value, std::string source, double time) {
  Message m;
  m.type = msg_type::kNotify;
  m.data_type = data_type::kString;
  m.key = std::move(key);
  m.sval = std::move(value);
  m.source = std::move(source);
  m.time = time;
  return m;
}

Message make_binary_notify(std::string key, std::string bytes, std::string source, double time) {
  Message m = make_string_notify(std::move(key), std::move(bytes), std::move(source), time);
  m.data_type = data_type::kBinary;
  return m;
}

}  // namespace moos
