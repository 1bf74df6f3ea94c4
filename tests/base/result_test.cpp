// base::Result<void>: an action with no value is done, or fails with the reason.
#include "base/result.hpp"

#include <gtest/gtest.h>

namespace base {
namespace {

TEST(Result, VoidOkIsDoneWithoutReason) {
  const Result<void> r = Result<void>::ok();
  EXPECT_TRUE(r);
  EXPECT_TRUE(r.error.empty());
}

TEST(Result, VoidFailKeepsTheReason) {
  const Result<void> r = Result<void>::fail("cannot write 'x': it is closed");
  EXPECT_FALSE(r);
  EXPECT_EQ(r.error, "cannot write 'x': it is closed");
}

TEST(Result, DefaultVoidIsNotDone) {
  // A Result<void> nobody set must not pass for success.
  EXPECT_FALSE(Result<void>{});
}

}  // namespace
}  // namespace base
