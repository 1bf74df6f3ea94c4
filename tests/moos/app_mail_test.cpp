// MoosApp hands its read mail back to the comms at the next fetch (Comms::fetch_into), so the
// comms can write new mail into its storage.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "moos/app.hpp"
#include "moos/comms.hpp"

namespace moos {
namespace {

constexpr double kT0 = 1700000000.0;

/// A connected Comms that delivers one message per fetch and records what each fetch got back.
class HandBackRecorder final : public Comms {
 public:
  HandBackRecorder() : Comms("pReader") {}
  bool is_connected() const override { return true; }
  std::uint64_t connection_count() const override { return 1; }
  std::string community() const override { return "alpha"; }
  Clock& clock() const override { return clock_; }
  double time_warp() const override { return 1.0; }
  double skew_s() const override { return 0.0; }
  void fetch_into(std::vector<Message>& mail) override {
    std::vector<std::string> keys;
    for (const Message& m : mail) keys.push_back(m.key);
    handed_back.push_back(keys);
    mail.clear();
    mail.push_back(make_double_notify("IN_" + std::to_string(handed_back.size()), 1.0, "pA", kT0));
  }

  std::vector<std::vector<std::string>> handed_back;

 protected:
  bool transmit(Message&&) override { return true; }

 private:
  mutable ManualClock clock_{kT0};
};

class Reader : public MoosApp {
 public:
  Reader() : MoosApp(AppTraits{"pReader", 4.0}) {}
  std::vector<std::string> seen;

 protected:
  void on_new_mail(const std::vector<Message>& mail) override {
    for (const Message& m : mail) seen.push_back(m.key);
  }
};

TEST(AppMail, EachFetchHandsBackTheMailOfThePreviousCycle) {
  HandBackRecorder comms;
  Reader app;
  AppSettings s;
  s.app_name = s.moos_name = "pReader";
  s.community = "alpha";
  ASSERT_TRUE(app.start(comms, s));
  app.cycle();
  app.cycle();
  app.cycle();
  EXPECT_EQ(app.seen, (std::vector<std::string>{"IN_1", "IN_2", "IN_3"}));
  ASSERT_GE(comms.handed_back.size(), 3u);
  const std::size_t n = comms.handed_back.size();
  EXPECT_EQ(comms.handed_back[n - 2], (std::vector<std::string>{"IN_1"}));
  EXPECT_EQ(comms.handed_back[n - 1], (std::vector<std::string>{"IN_2"}));
}

}  // namespace
}  // namespace moos
