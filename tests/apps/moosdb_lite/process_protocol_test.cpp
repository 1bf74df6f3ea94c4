// Process tests: the moosdb-lite binary on a free port, spoken to in raw MOOS protocol over
// real sockets (docs/protocol.md 1, 5). Each test starts its own server.

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "moos/alog.hpp"
#include "moosdb_server.hpp"
#include "raw_client.hpp"
#include "wire_messages.hpp"

namespace moosdb_lite::test {

using namespace moos::test;
namespace {

using moos::Message;
using test_support::MoosdbServer;
using test_support::run_program;
using test_support::RunResult;
using test_support::ScratchDir;
using test_support::steady_now_s;
using test_support::write_file;
namespace mt = moos::msg_type;
namespace dt = moos::data_type;

/// Clock agreement expected between the test and the server on one machine.
constexpr double kClockTolerance_s = 2.0;

std::string host_name() {
  char name[256] = {};
  ::gethostname(name, sizeof name - 1);
  return name;
}

std::vector<std::string> keys_of(const std::vector<Message>& messages) {
  std::vector<std::string> keys;
  for (const auto& m : messages) keys.push_back(m.key);
  return keys;
}

// ---------------------------------------------------------------------------------------
// Handshake (protocol.md 1.4-1.8)

TEST(MoosdbLiteProcess, WelcomeCarriesHostnameCommunitySkewAndAsynchronous_1_6) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--moos_community=alpha"});
  ASSERT_TRUE(server.ok());
  RawClient client;
  ASSERT_TRUE(client.connect(server.port()));
  const double skewed_time = moos_now() - 100.0;  // a client clock 100 s behind
  const auto reply = client.handshake("pWelcome", true, skewed_time);
  ASSERT_TRUE(reply);
  ASSERT_EQ(reply->size(), 1u);
  const Message& w = reply->front();
  EXPECT_EQ(w.type, mt::kWelcome);
  EXPECT_EQ(w.data_type, dt::kDouble);
  EXPECT_EQ(w.id, -1);
  EXPECT_EQ(w.source, "");
  EXPECT_EQ(w.source_aux, "hostname=" + host_name());
  EXPECT_EQ(w.community, "alpha");
  EXPECT_EQ(w.key, "");
  EXPECT_NEAR(w.time, moos_now(), kClockTolerance_s);
  EXPECT_NEAR(w.dval, 100.0, kClockTolerance_s);  // skew = server time - identification time
  EXPECT_EQ(w.dval2, -1.0);
  EXPECT_EQ(w.sval, "asynchronous");
}

TEST(MoosdbLiteProcess, DuplicateNameIsPoisonedAndClosedWhileTheFirstKeepsWorking_1_6) {
  MoosdbServer server(MOOSDB_LITE_PATH);
  ASSERT_TRUE(server.ok());
  RawClient first;
  ASSERT_TRUE(first.join(server.port(), "pTwin", false));
  RawClient second;
  ASSERT_TRUE(second.connect(server.port()));
  const auto reply = second.handshake("pTwin", true, moos_now());
  ASSERT_TRUE(reply);
  ASSERT_EQ(reply->size(), 1u);
  EXPECT_EQ(reply->front().type, mt::kPoison);
  EXPECT_EQ(reply->front().data_type, dt::kString);
  EXPECT_EQ(reply->front().sval, "A client of this name (\"pTwin\") already exists");
  EXPECT_TRUE(second.wait_closed(kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("handshake refused: A client of this name (\"pTwin\") already exists",
                                  kArrivalTimeout_s));
  const auto still = first.exchange({null_message("pTwin")});
  ASSERT_TRUE(still);
  EXPECT_EQ(still->front().type, mt::kNull);
}

TEST(MoosdbLiteProcess, ReconnectingClientFindsItsNameFreeImmediately_1_9) {
  MoosdbServer server(MOOSDB_LITE_PATH);
  ASSERT_TRUE(server.ok());
  for (int round = 0; round < 5; ++round) {
    RawClient client;
    ASSERT_TRUE(client.join(server.port(), "pBounce", true)) << "round " << round;
  }
}

// ---------------------------------------------------------------------------------------
// Delivery rules (protocol.md 5.6)

TEST(MoosdbLiteProcess, SyncClientGetsOneReplyPerPacketStartingWithNullAndNothingUnsolicited_5_6) {
  MoosdbServer server(MOOSDB_LITE_PATH);
  ASSERT_TRUE(server.ok());
  RawClient sync;
  ASSERT_TRUE(sync.join(server.port(), "pSync", false));
  RawClient pub;
  ASSERT_TRUE(pub.join(server.port(), "pPub", false));

  auto reply = sync.exchange({registration("SYNC_VAR", 0, "pSync")});
  ASSERT_TRUE(reply);
  ASSERT_EQ(reply->size(), 1u);
  EXPECT_EQ(reply->front().type, mt::kNull);
  EXPECT_NEAR(reply->front().dval, moos_now(), kClockTolerance_s);
  EXPECT_EQ(reply->front().time, -1.0);

  // The publisher's reply proves the posts were processed before the sync client asks.
  ASSERT_TRUE(pub.exchange({notify_double("SYNC_VAR", 1.5, "pPub"), notify_string("SYNC_VAR", "x", "pPub"),
                            notify_double("SYNC_VAR", 2.5, "pPub")}));
  EXPECT_FALSE(sync.read_packet(kSilence_s)) << "unsolicited packet to a sync client";

  reply = sync.exchange({null_message("pSync")});
  ASSERT_TRUE(reply);
  ASSERT_EQ(reply->size(), 3u);
  EXPECT_EQ(reply->at(0).type, mt::kNull);
  EXPECT_EQ(reply->at(1).dval, 1.5);
  EXPECT_EQ(reply->at(2).dval, 2.5);
  EXPECT_FALSE(sync.read_packet(kSilence_s)) << "more than one reply";

  // A TIMING from a sync client is not echoed (no TIMING to sync clients).
  reply = sync.exchange({timing(moos_now())});
  ASSERT_TRUE(reply);
  for (const auto& m : *reply) EXPECT_NE(m.type, mt::kTiming);
  EXPECT_EQ(reply->front().type, mt::kNull);
}

TEST(MoosdbLiteProcess, AsyncClientGetsTimingEchoFirstAndMailWithoutAsking_5_6) {
  MoosdbServer server(MOOSDB_LITE_PATH);
  ASSERT_TRUE(server.ok());
  RawClient async;
  ASSERT_TRUE(async.join(server.port(), "pAsync", true));
  RawClient pub;
  ASSERT_TRUE(pub.join(server.port(), "pPub", false));

  // Registrations for unwritten variables: no reply at all (never an empty packet).
  ASSERT_TRUE(async.send({registration("ASYNC_VAR", 0, "pAsync")}));
  EXPECT_FALSE(async.read_packet(kSilence_s));

  const double t = moos_now() - 0.5;
  ASSERT_TRUE(async.send({timing(t)}));
  auto packet = async.read_packet();
  ASSERT_TRUE(packet);
  ASSERT_EQ(packet->size(), 1u);
  EXPECT_EQ(packet->front().type, mt::kTiming);
  EXPECT_EQ(packet->front().time, t);
  EXPECT_NEAR(packet->front().dval, moos_now(), kClockTolerance_s);
  EXPECT_EQ(packet->front().dval2, 0.0);

  ASSERT_TRUE(pub.exchange({notify_string("ASYNC_VAR", "pushed", "pPub")}));
  packet = async.read_packet();
  ASSERT_TRUE(packet);
  ASSERT_EQ(packet->size(), 1u);
  EXPECT_EQ(packet->front().type, mt::kNotify);
  EXPECT_EQ(packet->front().sval, "pushed");
  EXPECT_EQ(packet->front().source, "pPub");

  // Own post, with a TIMING in front: echo first, then the mail.
  ASSERT_TRUE(async.send({timing(t), notify_double("ASYNC_VAR2", 1, "pAsync"),
                          registration("ASYNC_VAR2", 0, "pAsync"), notify_double("ASYNC_VAR2", 2, "pAsync")}));
  packet = async.read_packet();
  ASSERT_TRUE(packet);
  ASSERT_EQ(packet->size(), 3u);
  EXPECT_EQ(packet->at(0).type, mt::kTiming);
  EXPECT_EQ(packet->at(1).dval, 1.0);  // snapshot of the first write
  EXPECT_EQ(packet->at(2).dval, 2.0);  // own post delivered
}

TEST(MoosdbLiteProcess, PacketSentJustBeforeClosingIsProcessed_5_6) {
  MoosdbServer server(MOOSDB_LITE_PATH);
  ASSERT_TRUE(server.ok());
  RawClient watcher;
  ASSERT_TRUE(watcher.join(server.port(), "pWatch", true));
  ASSERT_TRUE(watcher.send({registration("POKED", 0, "pWatch")}));
  for (int i = 0; i < 3; ++i) {
    // uPokeDB style: handshake, post, close at once, without reading.
    RawClient poke;
    ASSERT_TRUE(poke.connect(server.port()));
    ASSERT_TRUE(poke.send_bytes(moos::protocol_banner() +
                                moos::encode_packet({identification("uPokeDB", true, moos_now())}) +
                                moos::encode_packet({notify_double("POKED", i, "uPokeDB")})));
    poke.close();
    const auto mail = watcher.read_notifies(1);
    ASSERT_EQ(mail.size(), 1u) << "poke " << i;
    EXPECT_EQ(mail[0].dval, i);
  }
}

// ---------------------------------------------------------------------------------------
// NOTIFY, REGISTER, wildcards (protocol.md 5.3-5.5)

TEST(MoosdbLiteProcess, RegisterGetsSnapshotWithWriterIdAndOriginalTime_5_4) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--moos_community=alpha"});
  ASSERT_TRUE(server.ok());
  RawClient writer;
  ASSERT_TRUE(writer.join(server.port(), "pWriter", false));
  const double stamp = moos_now() - 42.0;
  ASSERT_TRUE(writer.exchange({notify_string("SNAP", "value", "pWriter", stamp, 5)}));
  RawClient reader;
  ASSERT_TRUE(reader.join(server.port(), "pReader", true));
  ASSERT_TRUE(reader.send({registration("SNAP", 0, "pReader")}));
  const auto mail = reader.read_notifies(1);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0].id, -1);
  EXPECT_EQ(mail[0].source, "pWriter");
  EXPECT_EQ(mail[0].time, stamp);
  EXPECT_EQ(mail[0].sval, "value");
  EXPECT_EQ(mail[0].community, "alpha");
  EXPECT_EQ(mail[0].dval2, -1.0);
}

TEST(MoosdbLiteProcess, ThrottledUpdatesAreDropped_5_3) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--moos_timeout=60"});
  ASSERT_TRUE(server.ok());
  RawClient reader;
  ASSERT_TRUE(reader.join(server.port(), "pReader", true));
  RawClient writer;
  ASSERT_TRUE(writer.join(server.port(), "pWriter", true));
  ASSERT_TRUE(reader.send({registration("THROTTLED", 0.5, "pReader")}));
  ASSERT_TRUE(reader.send({timing(moos_now())}));
  ASSERT_TRUE(reader.read_packet());  // the echo: the registration has been processed
  ASSERT_TRUE(writer.send({notify_double("THROTTLED", 1, "pWriter"), notify_double("THROTTLED", 2, "pWriter")}));
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  ASSERT_TRUE(writer.send({notify_double("THROTTLED", 3, "pWriter")}));
  const auto mail = reader.read_notifies(3, 1.5);
  ASSERT_EQ(mail.size(), 2u);
  EXPECT_EQ(mail[0].dval, 1.0);
  EXPECT_EQ(mail[1].dval, 3.0);
}

TEST(MoosdbLiteProcess, TypeFixedAtFirstWriteRefusesOtherTypesWithLoggedReason_5_3) {
  MoosdbServer server(MOOSDB_LITE_PATH);
  ASSERT_TRUE(server.ok());
  RawClient client;
  ASSERT_TRUE(client.join(server.port(), "pTyped", false));
  ASSERT_TRUE(client.exchange({registration("TYPED", 0, "pTyped"), notify_double("TYPED", 1, "pTyped")}));
  auto reply = client.exchange({notify_string("TYPED", "s", "pTyped"),
                                moos::make_binary_notify("TYPED", "b", "pTyped", moos_now())});
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->size(), 1u);  // the NULL only: both refused
  EXPECT_TRUE(server.wait_for_log("client \"pTyped\": NOTIFY TYPED as string refused", kArrivalTimeout_s));
}

TEST(MoosdbLiteProcess, WildcardCommaAndSpaceFormsBothWork_5_5) {
  MoosdbServer server(MOOSDB_LITE_PATH);
  ASSERT_TRUE(server.ok());
  RawClient comma;
  ASSERT_TRUE(comma.join(server.port(), "pComma", true));
  RawClient space;
  ASSERT_TRUE(space.join(server.port(), "pSpace", false));
  RawClient writer;
  ASSERT_TRUE(writer.join(server.port(), "pWriter", false));
  ASSERT_TRUE(writer.exchange({notify_double("NAV_X", 1, "pWriter")}));
  ASSERT_TRUE(comma.send({wildcard("AppPattern=*,VarPattern=NAV_*,Interval=0", "pComma")}));
  auto mail = comma.read_notifies(1);
  ASSERT_EQ(keys_of(mail), std::vector<std::string>{"NAV_X"});  // existing variable

  auto reply = space.exchange({wildcard("AppPattern=pWriter VarPattern=NAV_* Interval=0.0", "pSpace")});
  ASSERT_TRUE(reply);
  ASSERT_EQ(keys_of(*reply), (std::vector<std::string>{"", "NAV_X"}));  // NULL, then snapshot

  ASSERT_TRUE(writer.exchange({notify_double("NAV_Y", 2, "pWriter"), notify_double("DEPTH", 3, "pWriter")}));
  mail = comma.read_notifies(1);
  ASSERT_EQ(keys_of(mail), std::vector<std::string>{"NAV_Y"});
  reply = space.exchange({null_message("pSpace")});
  ASSERT_TRUE(reply);
  ASSERT_EQ(keys_of(*reply), (std::vector<std::string>{"", "NAV_Y"}));
}

// ---------------------------------------------------------------------------------------
// DB variables and server requests (protocol.md 5.7, 5.8)

TEST(MoosdbLiteProcess, DbVariablesExistAtOnceAndAreRefreshedByTimer_5_7) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--moos_community=alpha", "--moos_timeout=60"});
  ASSERT_TRUE(server.ok());
  RawClient client;
  ASSERT_TRUE(client.join(server.port(), "pDb", true));
  ASSERT_TRUE(client.send({registration("DB_TIME", 0, "pDb"), registration("DB_UPTIME", 0, "pDb"),
                           registration("DB_CLIENTS", 0, "pDb")}));
  auto mail = client.read_notifies(3);
  ASSERT_EQ(keys_of(mail), (std::vector<std::string>{"DB_TIME", "DB_UPTIME", "DB_CLIENTS"}));
  EXPECT_NEAR(mail[0].dval, moos_now(), kClockTolerance_s);
  EXPECT_EQ(mail[0].source, "MOOSDB_alpha");
  EXPECT_EQ(mail[1].community, "alpha");  // uXMS reads the community from DB_UPTIME
  EXPECT_EQ(mail[2].sval, "pDb,");
  const double first_time = mail[0].dval;
  // Refreshed within about a second without the client sending anything.
  mail = client.read_notifies(3, 3.0);
  ASSERT_EQ(keys_of(mail), (std::vector<std::string>{"DB_TIME", "DB_UPTIME", "DB_CLIENTS"}));
  EXPECT_GT(mail[0].dval, first_time);
  EXPECT_GT(mail[1].dval, 0.0);
}

TEST(MoosdbLiteProcess, DbClientsAndDbEventFollowConnections_5_7) {
  MoosdbServer server(MOOSDB_LITE_PATH);
  ASSERT_TRUE(server.ok());
  RawClient watcher;
  ASSERT_TRUE(watcher.join(server.port(), "pWatch", true));
  ASSERT_TRUE(watcher.send({registration("DB_EVENT", 0, "pWatch")}));
  const auto snapshot = watcher.read_notifies(1);
  ASSERT_EQ(snapshot.size(), 1u);
  EXPECT_EQ(snapshot[0].sval, "connected=pWatch");  // the latest event: this client's own
  {
    RawClient visitor;
    ASSERT_TRUE(visitor.join(server.port(), "pVisitor", false));
    auto mail = watcher.read_notifies(1);
    ASSERT_EQ(mail.size(), 1u);
    EXPECT_EQ(mail[0].sval, "connected=pVisitor");
  }
  const auto mail = watcher.read_notifies(1);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0].sval, "disconnected=pVisitor");
}

TEST(MoosdbLiteProcess, ServerRequestsVarSummaryAndAll_5_8) {
  MoosdbServer server(MOOSDB_LITE_PATH);
  ASSERT_TRUE(server.ok());
  RawClient client;
  ASSERT_TRUE(client.join(server.port(), "pAsk", false));
  ASSERT_TRUE(client.exchange({notify_double("ASKED", 4.5, "pAsk")}));
  auto reply = client.exchange({server_request("VAR_SUMMARY", "pAsk")});
  ASSERT_TRUE(reply);
  ASSERT_EQ(reply->size(), 2u);
  EXPECT_EQ(reply->at(1).id, -2);
  EXPECT_EQ(reply->at(1).key, "VAR_SUMMARY");
  EXPECT_EQ(reply->at(1).sval, "DB_TIME,DB_UPTIME,DB_CLIENTS,DB_RWSUMMARY,DB_EVENT,ASKED");

  reply = client.exchange({server_request("ALL", "pAsk")});
  ASSERT_TRUE(reply);
  ASSERT_EQ(reply->size(), 7u);  // NULL + one per variable
  EXPECT_EQ(reply->at(6).key, "ASKED");
  EXPECT_EQ(reply->at(6).dval, 4.5);
  EXPECT_EQ(reply->at(6).id, -2);
}

// ---------------------------------------------------------------------------------------
// Timeouts, time warp, --log, configuration

TEST(MoosdbLiteProcess, SilentClientIsDroppedAfterClientTimeoutAndTalkerStays_1_9) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--moos_timeout=1"});
  ASSERT_TRUE(server.ok());
  RawClient quiet;
  ASSERT_TRUE(quiet.join(server.port(), "pQuiet", true));
  RawClient talker;
  ASSERT_TRUE(talker.join(server.port(), "pTalker", true));
  const double start = steady_now_s();
  while (steady_now_s() - start < 2.5) {
    ASSERT_TRUE(talker.send({timing(moos_now())}));
    ASSERT_TRUE(talker.read_packet()) << "the active client must stay connected";
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  EXPECT_TRUE(quiet.wait_closed(kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("client \"pQuiet\"", kArrivalTimeout_s));
  EXPECT_TRUE(server.wait_for_log("nothing received for more than 1 s (ClientTimeout)", kArrivalTimeout_s));
}

TEST(MoosdbLiteProcess, TimeWarpMultipliesDbTime_0_3) {
  MoosdbServer server(MOOSDB_LITE_PATH, {"--moos_time_warp=10"});
  ASSERT_TRUE(server.ok());
  RawClient client;
  ASSERT_TRUE(client.join(server.port(), "pWarp", false));
  const auto reply = client.exchange({null_message("pWarp")});
  ASSERT_TRUE(reply);
  EXPECT_NEAR(reply->front().dval / 10.0, moos_now(), kClockTolerance_s);
}

TEST(MoosdbLiteProcess, LogWritesEveryAcceptedNotifyInAlogFormat) {
  const ScratchDir dir;
  const std::string log_path = (dir / "run.alog").string();
  MoosdbServer logged(MOOSDB_LITE_PATH, {"--log=" + log_path, "--moos_community=alpha"});
  ASSERT_TRUE(logged.ok());
  RawClient client;
  ASSERT_TRUE(client.join(logged.port(), "pLogMe", false));
  const double t = moos_now();
  ASSERT_TRUE(client.exchange({notify_double("LOGGED_D", 12.5, "pLogMe", t),
                               notify_string("LOGGED_S", "two words", "pLogMe", t + 0.5),
                               notify_string("LOGGED_D", "refused", "pLogMe", t + 1)}));
  client.close();
  EXPECT_EQ(logged.stop(), 0);

  std::ifstream in(log_path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_GE(lines.size(), 4u);
  const auto logstart = moos::alog_logstart(lines[1]);
  ASSERT_TRUE(logstart);
  EXPECT_NEAR(*logstart, t, kClockTolerance_s);
  std::vector<moos::AlogEntry> mine;
  for (const auto& line : lines) {
    const auto parsed = moos::parse_alog_line(line);
    if (parsed.kind == moos::AlogLineKind::kEntry && parsed.entry.source == "pLogMe")
      mine.push_back(parsed.entry);
  }
  ASSERT_EQ(mine.size(), 2u);
  EXPECT_EQ(mine[0].variable, "LOGGED_D");
  EXPECT_EQ(mine[0].value, "12.5");
  EXPECT_NEAR(mine[0].time_s, t - *logstart, 0.002);
  EXPECT_EQ(mine[1].variable, "LOGGED_S");
  EXPECT_EQ(mine[1].value, "two words");
}

TEST(MoosdbLiteProcess, MissionGlobalsConfigureTheServerAndSwitchesOverride_5_11) {
  const ScratchDir dir;
  const std::string mission = (dir / "test.moos").string();
  write_file(mission, "// a mission\nServerPort = 0\nCommunity = shore\nMOOSTimeWarp = 2\n\n"
                     "ProcessConfig = ANTLER\n{\n  Run = MOOSDB @ NewConsole = false\n}\n");
  MoosdbServer from_mission(MOOSDB_LITE_PATH, {mission, "MOOSDB_alias"});
  ASSERT_TRUE(from_mission.ok());
  RawClient client;
  ASSERT_TRUE(client.connect(from_mission.port()));
  auto reply = client.handshake("pMission", false, moos_now());
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->front().community, "shore");
  reply = client.exchange({null_message("pMission")});
  ASSERT_TRUE(reply);
  EXPECT_NEAR(reply->front().dval / 2.0, moos_now(), kClockTolerance_s);

  MoosdbServer overridden(MOOSDB_LITE_PATH, {mission, "--moos_community=override"});
  ASSERT_TRUE(overridden.ok());
  RawClient other;
  ASSERT_TRUE(other.connect(overridden.port()));
  reply = other.handshake("pMission", false, moos_now());
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->front().community, "override");
}

TEST(MoosdbLiteProcess, HelpExitsZeroAndBadCommandLineExitsTwoWithReason) {
  // Each ends at once; the start-up bound only stops a hang.
  auto run_server = [](const std::vector<std::string>& args) {
    return run_program(MOOSDB_LITE_PATH, args, MoosdbServer::kStartTimeout_s);
  };
  const RunResult help = run_server({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--port-file=FILE"), std::string::npos);
  const RunResult bad_port = run_server({"--moos_port=banana"});
  EXPECT_EQ(bad_port.exit_code, 2);
  EXPECT_NE(bad_port.err.find("--moos_port=banana: not a port number"), std::string::npos);
  const RunResult no_mission = run_server({"/nonexistent/mission.moos"});
  EXPECT_EQ(no_mission.exit_code, 2);
  EXPECT_NE(no_mission.err.find("cannot read mission file /nonexistent/mission.moos"), std::string::npos);
}

TEST(MoosdbLiteProcess, SigtermStopsCleanlyWithExitZero) {
  MoosdbServer server(MOOSDB_LITE_PATH);
  ASSERT_TRUE(server.ok());
  RawClient client;
  ASSERT_TRUE(client.join(server.port(), "pStay", true));
  EXPECT_EQ(server.stop(), 0);
  EXPECT_TRUE(client.wait_closed(kArrivalTimeout_s));
}

}  // namespace
}  // namespace moosdb_lite::test
