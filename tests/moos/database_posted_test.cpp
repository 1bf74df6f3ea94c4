// moos::Database's memory of the names a client has posted (Client::posted_cache): a repeated
// NOTIFY finds its variable without a hash look-up. These tests pin down that the memory never
// changes what the DB does: the PUBLISHED lists, type checks and DB_CLEAR behave as without it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "database_fixture.hpp"

namespace moos::test {
namespace {

class DatabasePostedTest : public DatabaseTest {
 protected:
  /// The PUBLISHED part of `name`'s PROC_SUMMARY line, as client kA asks for it.
  std::string published_by(const std::string& name) {
    const auto mail = to(send(kA, {server_request("PROC_SUMMARY", "asker")}), kA);
    for (const auto& packet : mail)
      for (const auto& m : packet)
        if (m.sval.rfind(name + ":", 0) == 0) return m.sval.substr(m.sval.find("PUBLISHED="));
    return "(no line for " + name + ")";
  }
};

TEST_F(DatabasePostedTest, ANamePostedAgainAfterDbClearIsPublishedAgain_5_8) {
  connect(kA, "asker", true);
  connect(kB, "writer", true);
  send(kB, {notify_double("P", 1, "writer"), notify_double("P", 2, "writer")});
  EXPECT_EQ(published_by("writer"), "PUBLISHED=,P");
  send(kB, {server_request("DB_CLEAR", "writer")});
  EXPECT_EQ(published_by("writer"), "PUBLISHED=");
  send(kB, {notify_double("P", 3, "writer")});  // remembered before the clear
  EXPECT_EQ(published_by("writer"), "PUBLISHED=,P");
  EXPECT_EQ(db_.latest("P")->dval, 3);
}

TEST_F(DatabasePostedTest, AClientPostingMoreNamesThanAreRememberedHasThemAllPublished_5_8) {
  connect(kA, "asker", true);
  connect(kB, "writer", true);
  send(kA, {wildcard("AppPattern=*,VarPattern=V*,Interval=0", "asker")});
  std::string expected = "PUBLISHED=";
  std::vector<Message> packet;
  for (int round = 0; round < 3; ++round) {
    for (int i = 10; i < 30; ++i) {  // 20 names: more than are remembered
      packet.push_back(notify_double("V" + std::to_string(i), round, "writer"));
      if (round == 0) expected += ",V" + std::to_string(i);
    }
  }
  const auto mail = to(send(kB, packet), kA);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0].size(), 60u);  // every posting delivered, in order
  EXPECT_EQ(mail[0][59].key, "V29");
  EXPECT_EQ(mail[0][59].dval, 2);
  EXPECT_EQ(published_by("writer"), expected);  // the set's order: by variable id
}

TEST_F(DatabasePostedTest, AWriteOfAnotherTypeToARepeatedNameIsStillRefused_5_3) {
  connect(kA, "asker", true);
  connect(kB, "writer", true);
  send(kB, {notify_double("X", 1, "writer"), notify_double("X", 2, "writer")});
  send(kB, {notify_string("X", "text", "writer")});
  EXPECT_TRUE(logged("NOTIFY X as string refused"));
  EXPECT_EQ(db_.latest("X")->dval, 2);
}

}  // namespace
}  // namespace moos::test
