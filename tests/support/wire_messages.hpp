#pragma once
// Message builders shared by the MOOSDB tests (moos::Database in tests/moos, moosdb-lite in
// tests/apps/moosdb_lite): what libMOOS and pymoos2 clients send
// (docs/protocol.md 1.5, 2.6).

#include <string>
#include <vector>

#include "moos/message.hpp"

namespace moos::test {

/// A fixed MOOS time for unit tests (1700000000.0, protocol.md 8).
inline constexpr double kT0 = 1700000000.0;

/// Identification message (protocol.md 1.5): name in the string value, key `asynchronous` or "".
inline moos::Message identification(const std::string& name, bool async, double time = kT0) {
  moos::Message m;
  m.id = moos::kUnsetId;
  m.type = moos::msg_type::kData;
  m.data_type = moos::data_type::kString;
  m.key = async ? "asynchronous" : "";
  m.time = time;
  m.sval = name;
  return m;
}

inline moos::Message notify_double(const std::string& key, double value, const std::string& source,
                                   double time = kT0, int id = 0) {
  moos::Message m = moos::make_double_notify(key, value, source, time);
  m.id = id;
  return m;
}

inline moos::Message notify_string(const std::string& key, const std::string& value,
                                   const std::string& source, double time = kT0, int id = 0) {
  moos::Message m = moos::make_string_notify(key, value, source, time);
  m.id = id;
  return m;
}

inline moos::Message registration(const std::string& key, double interval_s,
                                  const std::string& source) {
  moos::Message m;
  m.id = 0;
  m.type = moos::msg_type::kRegister;
  m.data_type = moos::data_type::kDouble;
  m.key = key;
  m.dval = interval_s;
  m.source = source;
  m.time = kT0;
  return m;
}

inline moos::Message unregistration(const std::string& key, const std::string& source) {
  moos::Message m = registration(key, 0.0, source);
  m.type = moos::msg_type::kUnregister;
  return m;
}

/// WILDCARD_REGISTER / UNREGISTER with a verbatim specification string (protocol.md 2.6, 5.5).
inline moos::Message wildcard(const std::string& spec, const std::string& source,
                              char type = moos::msg_type::kWildcardRegister) {
  moos::Message m;
  m.id = 0;
  m.type = type;
  m.data_type = moos::data_type::kString;
  m.key = source;
  m.source = source;
  m.time = kT0;
  m.sval = spec;
  return m;
}

inline moos::Message server_request(const std::string& request, const std::string& source) {
  moos::Message m;
  m.id = moos::kServerRequestId;
  m.type = moos::msg_type::kServerRequest;
  m.data_type = moos::data_type::kString;
  m.key = request;
  m.source = source;
  m.time = kT0;
  return m;
}

/// Client TIMING (protocol.md 2.6, vector I): source "", key `_async_timing`, dval 0.
inline moos::Message timing(double local_time) {
  moos::Message m;
  m.id = moos::kUnsetId;
  m.type = moos::msg_type::kTiming;
  m.data_type = moos::data_type::kDouble;
  m.key = "_async_timing";
  m.time = local_time;
  m.dval = 0.0;
  return m;
}

/// Client NULL keep-alive (protocol.md 2.6, vector G).
inline moos::Message null_message(const std::string& source) {
  moos::Message m;
  m.id = moos::kUnsetId;
  m.type = moos::msg_type::kNull;
  m.data_type = moos::data_type::kDouble;
  m.source = source;
  return m;
}

}  // namespace moos::test
