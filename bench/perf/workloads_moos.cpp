// moos::Database relaying a mission's traffic, with the wire codec on both sides as moosdb-lite
// runs it: each client's packet is decoded from its bytes, processed, and every packet the DB
// sends is encoded. A shoreside client (the sensor's role) subscribes to the fleet's node
// reports and requests; 20 vehicle clients each subscribe to their own detection reports.
#include <stdexcept>
#include <string>
#include <vector>

#include "moos/codec.hpp"
#include "moos/database.hpp"
#include "moos/message.hpp"
#include "workloads.hpp"

namespace perf {

namespace {

constexpr int kVehicles = 20;
constexpr int kRounds = 1200;  // 10 Hz: 120 MOOS seconds
constexpr double kT0 = 1700000000.0;

moos::Message identification(const std::string& name, double now) {
  moos::Message m;
  m.type = moos::msg_type::kData;
  m.data_type = moos::data_type::kString;
  m.key = std::string(moos::kAsynchronousKey);
  m.time = now;
  m.sval = name;
  return m;
}

moos::Message registration(const std::string& key, const std::string& source) {
  moos::Message m;
  m.id = 0;
  m.type = moos::msg_type::kRegister;
  m.data_type = moos::data_type::kDouble;
  m.key = key;
  m.dval = 0.0;
  m.source = source;
  m.time = kT0;
  return m;
}

struct Relay {
  moos::Database db{moos::DatabaseConfig{}, kT0, [](const std::string&) {}};
  std::uint64_t sum = kChecksumStart;

  /// `packet` through the wire: encoded by the client, decoded and processed by the DB, every
  /// reply encoded.
  void send(moos::ClientId id, const std::vector<moos::Message>& packet, double now) {
    const std::string bytes = moos::encode_packet(packet);
    std::optional<std::vector<moos::Message>> decoded = moos::decode_packet(bytes);
    if (!decoded) throw std::runtime_error("a packet did not decode");
    db.process_packet(id, std::move(*decoded), now);
    for (const moos::OutPacket& out : db.take_output()) {
      sum = checksum(sum, moos::encode_packet(out.messages));
    }
  }
};

}  // namespace

std::uint64_t database_relay() {
  Relay relay;
  const moos::ClientId shoreside = 1;
  if (!relay.db.connect(shoreside, {identification("uFldHazardSensor", kT0)}, kT0))
    throw std::runtime_error("the shoreside client was refused");
  relay.send(shoreside, {registration("NODE_REPORT", "uFldHazardSensor"),
                         registration("UHZ_SENSOR_REQUEST", "uFldHazardSensor"),
                         registration("UHZ_CLASSIFY_REQUEST", "uFldHazardSensor")}, kT0);
  Fleet fleet;
  fleet.vehicles = kVehicles;
  fleet.half_extent_m = 1000.0;
  fleet.lane_spacing_m = 100.0;
  for (int v = 0; v < kVehicles; ++v) {
    const std::string name = fleet.name(v);
    if (!relay.db.connect(2 + v, {identification(name, kT0)}, kT0))
      throw std::runtime_error("a vehicle client was refused");
    relay.send(2 + v, {registration("UHZ_DETECTION_REPORT_" + name, name)}, kT0);
  }
  relay.db.take_output();
  for (int k = 1; k <= kRounds; ++k) {
    const double t = k / 10.0, now = kT0 + t;
    std::vector<moos::Message> sensor_mail;
    for (int v = 0; v < kVehicles; ++v) {
      const std::string name = fleet.name(v);
      std::vector<moos::Message> packet = {
          moos::make_string_notify("NODE_REPORT", fleet.node_report(v, t), name, now)};
      if (k % 3 == 0) packet.push_back(moos::make_string_notify("UHZ_SENSOR_REQUEST", "vname=" + name, name, now));
      if (k % 7 == 0)
        packet.push_back(moos::make_string_notify("UHZ_CLASSIFY_REQUEST", "vname=" + name + ",label=" + std::to_string(k), name, now));
      relay.send(2 + v, packet, now);
      sensor_mail.push_back(moos::make_string_notify(
          "UHZ_DETECTION_REPORT_" + name, "x=" + std::to_string(k % 97) + ",y=11.3,label=" + std::to_string(k), "uFldHazardSensor", now));
    }
    sensor_mail.push_back(moos::make_double_notify("UFLDHAZARDSENSOR_ITER_GAP", 1.0, "uFldHazardSensor", now));
    relay.send(shoreside, sensor_mail, now);
    if (k % 10 == 0) relay.db.refresh_db_variables(now);
  }
  return relay.sum;
}

}  // namespace perf
