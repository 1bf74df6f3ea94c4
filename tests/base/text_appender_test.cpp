// base::TextAppender: the text is what appending each piece in turn would give, however the
// pieces fall on the buffer's edge, with numbers outside write_fmt_fast's range and pieces
// longer than the buffer.
#include "base/text_appender.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace base {
namespace {

TEST(TextAppender, WritesThePiecesInOrderAndFlushesAtTheEnd) {
  std::string out = "head:";
  {
    TextAppender text(out);
    text.put("pts=");
    text.put('{');
    text.put_fmt(-0.04, 1);  // FMT's "-0" is "0"
    text.put(',');
    text.put_fmt(12.25, 1);
    text.put('}');
    EXPECT_EQ(out, "head:");  // still in the buffer
    text.flush();
    EXPECT_EQ(out, "head:pts={0,12.2}");
    text.put(",x=");
  }
  EXPECT_EQ(out, "head:pts={0,12.2},x=");
}

TEST(TextAppender, PutFieldIsTheKeyThenFmt) {
  std::string out;
  {
    TextAppender text(out);
    text.put_field("x=", 12.5, 2);
    text.put_field(",y=", -0.001, 2);  // FMT's "-0" is "0"
    text.put_field(",r=", 3.0, 5);
  }
  EXPECT_EQ(out, "x=12.5,y=0,r=3");
}

TEST(TextAppender, TakesNumbersOutsideTheFastPathAndPiecesLongerThanTheBuffer) {
  const std::string long_piece(1000, 'q');
  std::string out;
  {
    TextAppender text(out);
    text.put("a=");
    text.put_fmt(1e300, 2);
    text.put(",b=");
    text.put_fmt(std::nan(""), 1);
    text.put(",c=");
    text.put_fmt(1.0 / 3.0, 12);
    text.put(long_piece);
    text.put('!');
  }
  std::string want = "a=";
  append_fmt(want, 1e300, 2);
  want += ",b=";
  append_fmt(want, std::nan(""), 1);
  want += ",c=";
  append_fmt(want, 1.0 / 3.0, 12);
  want += long_piece + "!";
  EXPECT_EQ(out, want);
}

// Random runs of pieces across many buffer edges, against plain appends.
TEST(TextAppender, EqualsPlainAppendsForRandomPieces) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> coordinate(-20000.0, 20000.0);
  for (int run = 0; run < 200; ++run) {
    std::string got = "x";
    std::string want = "x";
    {
      TextAppender text(got);
      const int pieces = static_cast<int>(rng() % 400);
      for (int i = 0; i < pieces; ++i) {
        switch (rng() % 4) {
          case 0:
            text.put(':');
            want.push_back(':');
            break;
          case 1: {
            const std::string word(rng() % 300, static_cast<char>('a' + rng() % 26));
            text.put(word);
            want += word;
            break;
          }
          default: {
            const double v = rng() % 50 == 0 ? 1e200 : coordinate(rng);
            const int decimals = static_cast<int>(rng() % 12);
            if (rng() % 2) {
              text.put_fmt(v, decimals);
              append_fmt(want, v, decimals);
              break;
            }
            // The read-back form: the same text, and the number it reads as when it knows it.
            const std::size_t at = want.size();
            double read_back = 0.0;
            const bool known = text.put_fmt(v, decimals, read_back);
            append_fmt(want, v, decimals);
            ASSERT_EQ(known, decimals <= 9 && v != 1e200) << v << " " << decimals;
            if (known) {
              ASSERT_EQ(parse_number(want.substr(at)), read_back) << want.substr(at);
            }
          }
        }
        ASSERT_EQ(text.size(), want.size()) << "run " << run;  // buffered bytes counted
      }
    }
    ASSERT_EQ(got, want) << "run " << run;
  }
}

}  // namespace
}  // namespace base
