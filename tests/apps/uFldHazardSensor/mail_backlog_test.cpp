// The sensor's mail backlog (mail_backlog.hpp): arrival order while within the per-iteration
// budget, per-source shares above it, and bounds that drop the busiest source's oldest mail.
#include "mail_backlog.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace ufld_hazard_sensor {
namespace {

moos::Message mail(const std::string& source, const std::string& key, int n) {
  moos::Message m = moos::make_string_notify(key, std::to_string(n), source, 0.0);
  return m;
}

std::vector<std::string> labels(const std::vector<moos::Message>& messages) {
  std::vector<std::string> out;
  for (const auto& m : messages) out.push_back(m.source + ":" + m.sval);
  return out;
}

TEST(MailBacklog, WithinTheBudgetEverythingIsHandedOverInArrivalOrder) {
  MailBacklog backlog(4);
  backlog.add({mail("b", "NODE_REPORT", 1), mail("a", "NODE_REPORT", 2),
               mail("b", "UHZ_CONFIG_REQUEST", 3), mail("a", "NODE_REPORT", 4)});
  EXPECT_EQ(labels(backlog.take()), (std::vector<std::string>{"b:1", "a:2", "b:3", "a:4"}));
  EXPECT_TRUE(backlog.empty());
  EXPECT_EQ(backlog.bytes(), 0u);
}

// Mail within the budget passes through an empty backlog (the caller hands it over itself, as
// take() would); with a backlog waiting, or above the budget, it must queue behind it.
TEST(MailBacklog, OnlyMailWithinTheBudgetPassesThroughAnEmptyBacklog) {
  MailBacklog backlog(4);
  EXPECT_TRUE(backlog.passes_through(0));
  EXPECT_TRUE(backlog.passes_through(4));
  EXPECT_FALSE(backlog.passes_through(5));
  std::vector<moos::Message> five;
  for (int n = 1; n <= 5; ++n) five.push_back(mail("a", "NODE_REPORT", n));
  backlog.add(five);
  EXPECT_FALSE(backlog.passes_through(1));
  EXPECT_EQ(backlog.take().size(), 4u);
  EXPECT_FALSE(backlog.passes_through(1));  // one still waits
  EXPECT_EQ(backlog.take().size(), 1u);
  EXPECT_TRUE(backlog.passes_through(1));
}

TEST(MailBacklog, AboveTheBudgetARequestBehindAFloodIsInTheFirstShare) {
  MailBacklog backlog(10);
  std::vector<moos::Message> flood;
  for (int i = 0; i < 500; ++i) flood.push_back(mail("pFlooder", "NODE_REPORT", i));
  flood.push_back(mail("vehicle", "UHZ_CONFIG_REQUEST", 0));
  backlog.add(flood);
  const auto first = labels(backlog.take());
  ASSERT_EQ(first.size(), 10u);
  EXPECT_EQ(first.back(), "vehicle:0");
  for (int i = 0; i < 9; ++i) EXPECT_EQ(first[static_cast<std::size_t>(i)], "pFlooder:" + std::to_string(i));
  // The flood follows in its own order, share by share.
  int next = 9;
  while (!backlog.empty()) {
    for (const auto& label : labels(backlog.take())) EXPECT_EQ(label, "pFlooder:" + std::to_string(next++));
  }
  EXPECT_EQ(next, 500);
}

TEST(MailBacklog, SourcesWithLessThanTheirShareLeaveTheRestToTheOthers) {
  MailBacklog backlog(6);
  backlog.add({mail("a", "X", 1), mail("b", "X", 1), mail("b", "X", 2), mail("b", "X", 3),
               mail("c", "X", 1), mail("b", "X", 4), mail("c", "X", 2), mail("c", "X", 3),
               mail("c", "X", 4)});
  // a has 1; b and c share the other 5 (2 each, and one more in arrival order).
  EXPECT_EQ(labels(backlog.take()),
            (std::vector<std::string>{"a:1", "b:1", "b:2", "c:1", "c:2"}));
  EXPECT_EQ(labels(backlog.take()), (std::vector<std::string>{"b:3", "b:4", "c:3", "c:4"}));
}

TEST(MailBacklog, BeyondItsBoundsTheBusiestSourcesOldestMailIsDropped) {
  MailBacklog backlog(100, 5);
  EXPECT_EQ(backlog.add({mail("flood", "N", 1), mail("flood", "N", 2), mail("v", "R", 1),
                         mail("flood", "N", 3), mail("flood", "N", 4), mail("flood", "N", 5),
                         mail("v", "R", 2)}),
            2u);
  EXPECT_EQ(labels(backlog.take()),
            (std::vector<std::string>{"v:1", "flood:3", "flood:4", "flood:5", "v:2"}));
}

TEST(MailBacklog, BeyondItsByteBoundTheBusiestSourcesOldestMailIsDropped) {
  const std::size_t one = mail("flood", "N", 1).encoded_size();
  MailBacklog backlog(100, 100, 3 * one);
  EXPECT_EQ(backlog.add({mail("flood", "N", 1), mail("v", "N", 1), mail("flood", "N", 2),
                         mail("flood", "N", 3)}),
            1u);
  EXPECT_LE(backlog.bytes(), 3 * one);
  EXPECT_EQ(labels(backlog.take()), (std::vector<std::string>{"v:1", "flood:2", "flood:3"}));
}

// The backlog's rules written the plain way (a pass over everything it holds per call): the
// counted backlog must hand over and drop exactly what this does.
class PlainBacklog {
 public:
  PlainBacklog(std::size_t per_iteration, std::size_t max_messages, std::size_t max_bytes)
      : per_(per_iteration), max_messages_(max_messages), max_bytes_(max_bytes) {}

  std::size_t add(const std::vector<moos::Message>& mail) {
    for (const auto& m : mail) {
      bytes_ += m.encoded_size();
      mail_.push_back(m);
    }
    std::size_t dropped = 0;
    while (mail_.size() > max_messages_ || (bytes_ > max_bytes_ && mail_.size() > 1)) {
      const bool by_bytes = bytes_ > max_bytes_;
      std::map<std::string, std::size_t> held;
      for (const auto& m : mail_) held[m.source] += by_bytes ? m.encoded_size() : 1;
      const std::string source = std::max_element(held.begin(), held.end(), [](const auto& a, const auto& b) {
                                   return a.second < b.second;
                                 })->first;
      std::deque<moos::Message> kept;
      std::size_t removed = 0;
      for (auto& m : mail_) {
        if ((mail_.size() - removed > max_messages_ || bytes_ > max_bytes_) && m.source == source) {
          bytes_ -= m.encoded_size();
          ++removed;
        } else {
          kept.push_back(m);
        }
      }
      mail_.swap(kept);
      dropped += removed;
    }
    return dropped;
  }

  std::vector<moos::Message> take() {
    std::vector<moos::Message> out;
    std::map<std::string, std::size_t> counts;
    for (const auto& m : mail_) ++counts[m.source];
    std::vector<std::size_t> sizes;
    for (const auto& c : counts) sizes.push_back(c.second);
    std::sort(sizes.begin(), sizes.end());
    std::size_t share = per_, budget = per_;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      if (sizes[i] * (sizes.size() - i) > budget) {
        share = std::max<std::size_t>(budget / (sizes.size() - i), 1);
        break;
      }
      budget -= sizes[i];
    }
    std::map<std::string, std::size_t> taken;
    std::deque<moos::Message> kept;
    for (auto& m : mail_) {
      if (taken[m.source] < share && out.size() < per_) {
        ++taken[m.source];
        bytes_ -= m.encoded_size();
        out.push_back(m);
      } else {
        kept.push_back(m);
      }
    }
    mail_.swap(kept);
    return out;
  }

  std::size_t bytes() const { return bytes_; }

 private:
  std::size_t per_, max_messages_, max_bytes_, bytes_ = 0;
  std::deque<moos::Message> mail_;
};

// Random floods from up to five sources of uneven sizes, against tight bounds: every take(),
// drop count and byte total is the plain rules' (the counted backlog only avoids re-reading
// what it holds).
TEST(MailBacklog, HandsOverAndDropsExactlyWhatThePlainRulesDo) {
  std::mt19937 random(7);
  for (int round = 0; round < 200; ++round) {
    const std::size_t per = 1 + random() % 20, max_messages = 1 + random() % 60;
    const std::size_t max_bytes = 200 + random() % 4000;
    MailBacklog counted(per, max_messages, max_bytes);
    PlainBacklog plain(per, max_messages, max_bytes);
    int n = 0;
    for (int call = 0; call < 30; ++call) {
      std::vector<moos::Message> batch;
      const int size = static_cast<int>(random() % 40);
      for (int i = 0; i < size; ++i) {
        const std::string source(1 + random() % 3, static_cast<char>('a' + random() % 5));
        batch.push_back(mail(source, "NODE_REPORT", n++));
        batch.back().sval.append(random() % 50, 'x');
      }
      ASSERT_EQ(counted.add(batch), plain.add(batch)) << "round " << round << " call " << call;
      ASSERT_EQ(labels(counted.take()), labels(plain.take())) << "round " << round << " call " << call;
      ASSERT_EQ(counted.bytes(), plain.bytes());
    }
  }
}

}  // namespace
}  // namespace ufld_hazard_sensor
