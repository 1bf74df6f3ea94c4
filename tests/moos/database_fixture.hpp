#pragma once
// The fixture of the moos::Database tests (database_*_test.cpp): a DB of community "alpha" on
// host "dbhost" at MOOS time kT0, whose log lines and observed NOTIFYs are kept.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "moos/database.hpp"
#include "wire_messages.hpp"

namespace moos::test {

namespace mt = moos::msg_type;
namespace dt = moos::data_type;

constexpr ClientId kA = 1;
constexpr ClientId kB = 2;
constexpr ClientId kC = 3;

class DatabaseTest : public ::testing::Test {
 protected:
  static DatabaseConfig config() {
    DatabaseConfig c;
    c.community = "alpha";
    c.hostname = "dbhost";
    return c;
  }

  void connect(ClientId id, const std::string& name, bool async, double now = kT0) {
    ASSERT_TRUE(db_.connect(id, {identification(name, async, now)}, now));
    db_.take_output();
  }

  std::vector<OutPacket> send(ClientId id, const std::vector<Message>& packet, double now = kT0) {
    db_.process_packet(id, packet, now);
    return db_.take_output();
  }

  static std::vector<std::vector<Message>> to(const std::vector<OutPacket>& out, ClientId id) {
    std::vector<std::vector<Message>> packets;
    for (const auto& p : out)
      if (p.to == id) packets.push_back(p.messages);
    return packets;
  }

  static std::vector<std::string> keys(const std::vector<Message>& messages) {
    std::vector<std::string> k;
    for (const auto& m : messages) k.push_back(m.key);
    return k;
  }

  bool logged(const std::string& fragment) const {
    return std::any_of(logs_.begin(), logs_.end(), [&](const std::string& line) {
      return line.find(fragment) != std::string::npos;
    });
  }

  std::vector<std::string> logs_;
  std::vector<Message> observed_;
  Database db_{config(), kT0, [this](const std::string& line) { logs_.push_back(line); },
               [this](const Message& m) { observed_.push_back(m); }};
};

}  // namespace moos::test
