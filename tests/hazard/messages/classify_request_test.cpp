// UHZ_CLASSIFY_REQUEST: the forms of manual 3.2 and the rejections.
#include <gtest/gtest.h>

#include "hazard/messages/classify_request.hpp"

namespace hazard {
namespace {

TEST(RequestMessages, ClassifyRequestForms_Manual3_2) {
  const auto plain = parse_classify_request("vname=archie,label=152");
  ASSERT_TRUE(plain);
  EXPECT_FALSE(plain.value->priority);
  EXPECT_EQ(plain.value->action, ClassifyAction::kNormal);
  const auto top = parse_classify_request("vname=archie,label=152,priority=100,action=top");
  ASSERT_TRUE(top);
  EXPECT_EQ(top.value->priority, 100);
  EXPECT_EQ(top.value->action, ClassifyAction::kTop);
  const auto clear = parse_classify_request("vname=archie,action=clear");
  ASSERT_TRUE(clear);
  EXPECT_EQ(clear.value->action, ClassifyAction::kClear);
  for (const auto* text : {"vname=archie,label=152", "vname=archie,label=152,priority=95",
                           "vname=archie,label=152,priority=100,action=top",
                           "vname=archie,action=clear"}) {
    EXPECT_EQ(format_classify_request(*parse_classify_request(text).value), text);
  }
}

TEST(RequestMessages, ClassifyRequestRejections) {
  EXPECT_EQ(parse_classify_request("label=1").error, "missing field 'vname'");
  EXPECT_EQ(parse_classify_request("vname=a").error, "missing field 'label'");
  EXPECT_EQ(parse_classify_request("vname=a,label=1,priority=high").error,
            "field 'priority' value 'high' is not a finite number");
  EXPECT_EQ(parse_classify_request("vname=a,label=1,action=bottom").error,
            "field 'action' value 'bottom' is neither 'top' nor 'clear'");
}

}  // namespace
}  // namespace hazard
