#pragma once
// A MOOS message (core-moos CMOOSMsg) as it travels on the wire.
// Field meanings and defaults: docs/protocol.md sections 2.1-2.6.

#include <cstdint>
#include <string>
#include <string_view>

namespace moos {

/// Message type codes (docs/protocol.md 2.3). Stored as a plain char so that unknown codes survive
/// decoding and can be ignored by receivers instead of failing the whole packet.
namespace msg_type {
inline constexpr char kNotify = 'N';
inline constexpr char kRegister = 'R';
inline constexpr char kUnregister = 'U';
inline constexpr char kWildcardRegister = '*';
inline constexpr char kWildcardUnregister = '/';
inline constexpr char kNull = '.';
inline constexpr char kData = 'i';  ///< handshake identification only
inline constexpr char kWelcome = 'W';
inline constexpr char kPoison = 'K';
inline constexpr char kServerRequest = 'Q';
inline constexpr char kTiming = 'T';
inline constexpr char kCommand = 'C';
}  // namespace msg_type

/// Data type codes (docs/protocol.md 2.4).
namespace data_type {
inline constexpr char kDouble = 'D';
inline constexpr char kString = 'S';
inline constexpr char kBinary = 'B';
inline constexpr char kNotSet = '~';
}  // namespace data_type

/// The identification key that selects asynchronous mode and the WELCOME string value that
/// advertises it, compared case-insensitively (docs/protocol.md 1.5, 1.6).
inline constexpr std::string_view kAsynchronousKey = "asynchronous";
/// The key of TIMING messages (docs/protocol.md 2.6).
inline constexpr std::string_view kTimingKey = "_async_timing";

/// Unused doubles and ids are -1, as libMOOS writes them (docs/protocol.md 2.2).
inline constexpr double kUnsetDouble = -1.0;
inline constexpr std::int32_t kUnsetId = -1;
/// SERVER_REQUEST messages and their answers carry id -2 (docs/protocol.md 2.5).
inline constexpr std::int32_t kServerRequestId = -2;

struct Message {
  std::int32_t id = kUnsetId;
  char type = msg_type::kNull;
  char data_type = data_type::kDouble;
  std::string source;
  std::string source_aux;
  std::string community;
  std::string key;
  double time = kUnsetDouble;  ///< MOOS seconds (epoch based, warped)
  double dval = kUnsetDouble;
  double dval2 = kUnsetDouble;
  std::string sval;  ///< string value, or raw bytes for binary messages

  bool is_double() const { return data_type == data_type::kDouble; }
  bool is_string() const { return data_type == data_type::kString; }
  bool is_binary() const { return data_type == data_type::kBinary; }

  /// Serialized size in bytes: 54 + the lengths of the five strings (docs/protocol.md 2.1).
  std::size_t encoded_size() const {
    return kFixedEncodedSize + source.size() + source_aux.size() + community.size() +
           key.size() + sval.size();
  }

  /// Bytes a message occupies with every string empty.
  static constexpr std::size_t kFixedEncodedSize = 54;

  /// Member by member: the strings trade their storage, nothing is allocated or copied.
  friend void swap(Message& a, Message& b) noexcept;
  friend bool operator==(const Message& a, const Message& b);
  friend bool operator!=(const Message& a, const Message& b) { return !(a == b); }
};

/// A NOTIFY carrying a double (docs/protocol.md 2.2): string value empty, dval2 -1.
Message make_double_notify(std::string key, double value, std::string source, double time);
/// A NOTIFY carrying a string: dval -1 as libMOOS writes it.
Message make_string_notify(std::string key, std::string value, std::string source, double time);
/// A NOTIFY carrying raw bytes: as a string notify, data type 'B'.
Message make_binary_notify(std::string key, std::string bytes, std::string source, double time);

}  // namespace moos
