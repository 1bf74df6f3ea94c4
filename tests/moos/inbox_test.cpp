// moos::Inbox: mail written over the storage of read mail, within its bounds.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "moos/inbox.hpp"

namespace moos {
namespace {

/// A NOTIFY whose value is `bytes` long: beyond any small-string buffer, so it owns storage.
Message mail_of(char fill, std::size_t bytes = 200) {
  return make_string_notify("NODE_REPORT", std::string(bytes, fill), "uSimSurveyVehicle_archie",
                            1.0);
}

TEST(Inbox, HandsOverTheMailInOrderAndIsEmptyAfterwards) {
  Inbox inbox;
  inbox.push_copy(mail_of('a'));
  inbox.push_copy(mail_of('b'));
  std::vector<Message> mail;
  inbox.hand_over(mail);
  ASSERT_EQ(mail.size(), 2u);
  EXPECT_EQ(mail[0], mail_of('a'));
  EXPECT_EQ(mail[1], mail_of('b'));
  EXPECT_TRUE(inbox.empty());
  inbox.hand_over(mail);  // nothing new: the read mail is taken back, none handed out
  EXPECT_TRUE(mail.empty());
  EXPECT_EQ(inbox.kept(), 2u);
}

TEST(Inbox, ACopyIsWrittenIntoTheStorageOfReadMail) {
  Inbox inbox;
  std::vector<Message> mail{mail_of('a')};
  const char* storage = mail[0].sval.data();
  inbox.hand_over(mail);  // the read message is kept
  const std::string blocker(200, 'x');  // had it been freed, this would take its storage
  inbox.push_copy(mail_of('b', 150));
  inbox.hand_over(mail);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0], mail_of('b', 150));
  EXPECT_EQ(mail[0].sval.data(), storage);  // no new string
}

TEST(Inbox, ATradeGivesTheDecodedMessageAKeptOnesStorage) {
  Inbox inbox;
  std::vector<Message> mail{mail_of('a')};
  const char* kept = mail[0].sval.data();
  inbox.hand_over(mail);
  const std::string blocker(200, 'x');  // had it been freed, this would take its storage
  Message decoded = mail_of('b');
  const char* decoded_storage = decoded.sval.data();
  inbox.push_trade(decoded);
  EXPECT_EQ(decoded.sval.data(), kept);  // the next decode writes into it
  inbox.hand_over(mail);
  ASSERT_EQ(mail.size(), 1u);
  EXPECT_EQ(mail[0], mail_of('b'));
  EXPECT_EQ(mail[0].sval.data(), decoded_storage);
}

TEST(Inbox, ATradeWithNothingKeptLeavesTheDecodedMessageEmpty) {
  Inbox inbox;
  Message decoded = mail_of('b');
  inbox.push_trade(decoded);
  EXPECT_EQ(decoded, Message{});
  EXPECT_EQ(inbox.size(), 1u);
}

TEST(Inbox, LargeReadMailIsNotKept) {
  Inbox inbox;
  std::vector<Message> mail{mail_of('a', Inbox::kMaxKeptBytes + 1), mail_of('b')};
  inbox.hand_over(mail);
  EXPECT_LE(inbox.kept_bytes(), 1000u);  // the large value went, the small one stays
  EXPECT_GE(inbox.kept_bytes(), 200u);
}

TEST(Inbox, KeptMessagesAreBounded) {
  Inbox inbox;
  std::vector<Message> mail(Inbox::kMaxKept + 10, mail_of('a', 20));
  inbox.hand_over(mail);
  EXPECT_EQ(inbox.kept(), Inbox::kMaxKept);
}

TEST(Inbox, KeepsAsManyAsTheLargerOfTheReadAndTheHandedOverMail) {
  Inbox inbox;
  std::vector<Message> mail(10, mail_of('a'));
  inbox.hand_over(mail);  // 10 read ones kept
  for (int i = 0; i < 3; ++i) inbox.push_copy(mail_of('b'));
  mail.resize(2);  // the caller read only two this time
  inbox.hand_over(mail);
  EXPECT_EQ(mail.size(), 3u);
  EXPECT_EQ(inbox.kept(), 3u);  // the two read ones and one of the seven left over
}

TEST(Inbox, DroppingTheOldestKeepsTheOrderOfTheRest) {
  Inbox inbox;
  for (char c : std::string("abcd")) inbox.push_copy(mail_of(c));
  inbox.drop_oldest(2);
  EXPECT_EQ(inbox.size(), 2u);
  EXPECT_EQ(inbox.kept(), 2u);
  std::vector<Message> mail;
  inbox.hand_over(mail);
  ASSERT_EQ(mail.size(), 2u);
  EXPECT_EQ(mail[0], mail_of('c'));
  EXPECT_EQ(mail[1], mail_of('d'));
  inbox.push_copy(mail_of('e'));
  inbox.drop_oldest(5);  // more than it holds
  EXPECT_TRUE(inbox.empty());
}

}  // namespace
}  // namespace moos
