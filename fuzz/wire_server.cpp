// Fuzz target: the server side of the MOOS wire protocol: the bytes one client sends after the
// banner, reassembled and decoded as the server does (PacketReader), then handed to the
// database: the first packet is the identification (connect), every later one goes through
// process_packet, with the clock moving on and the DB variables refreshed between packets.
// A second client subscribed to everything receives all mail, so delivery is exercised too.
//
// The database is moosdb-lite's (src/apps/moosdb-lite/database.hpp); only its public API is used
// (connect, process_packet, refresh_db_variables, take_output, take_drop_requests, disconnect).

#include <vector>

#include "moos/codec.hpp"
#include "moos/database.hpp"

namespace {

using Db = moos::Database;
using ClientId = moos::ClientId;

constexpr double kStartMoosS = 1700000000.0;
constexpr ClientId kWatcher = 1;
constexpr ClientId kFuzzed = 2;
/// A small limit, so the fuzzer reaches the "packet too large" refusal too.
constexpr std::size_t kMaxPacketBytes = 1u << 16;

moos::Message message(char type, char data_type, std::string key, std::string sval) {
  moos::Message m;
  m.id = 0;
  m.type = type;
  m.data_type = data_type;
  m.source = "watcher";
  m.key = std::move(key);
  m.sval = std::move(sval);
  m.time = kStartMoosS;
  return m;
}

/// Connects an asynchronous client that registers for every variable of every application.
void connect_watcher(Db& db) {
  moos::Message ident = message(moos::msg_type::kData, moos::data_type::kString,
                                std::string(moos::kAsynchronousKey), "watcher");
  ident.id = moos::kUnsetId;
  db.connect(kWatcher, {ident}, kStartMoosS);
  db.process_packet(kWatcher,
                    {message(moos::msg_type::kWildcardRegister, moos::data_type::kString,
                             "watcher", "AppPattern=*,VarPattern=*,Interval=0")},
                    kStartMoosS);
}

void drain(Db& db) {
  (void)db.take_output();
  (void)db.take_drop_requests();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Db db({}, kStartMoosS, [](const std::string&) {});
  connect_watcher(db);
  drain(db);

  moos::PacketReader reader(kMaxPacketBytes);
  reader.feed({reinterpret_cast<const char*>(data), size});
  double now = kStartMoosS;
  bool connected = false;
  std::vector<moos::Message> packet;
  while (reader.next(packet) == moos::PacketReader::Status::kPacket) {
    now += 0.25;
    if (!connected) {
      connected = db.connect(kFuzzed, packet, now);
      drain(db);
      if (!connected) return 0;  // POISON: the server closes the connection
      continue;
    }
    db.process_packet(kFuzzed, std::move(packet), now);
    db.refresh_db_variables(now);
    drain(db);
    packet.clear();
  }
  db.disconnect(kFuzzed, now);
  db.disconnect(kWatcher, now);
  drain(db);
  return 0;
}
