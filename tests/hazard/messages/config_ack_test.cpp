// UHZ_CONFIG_ACK: the format of D22 and its strict parser.
#include <gtest/gtest.h>

#include "hazard/messages/config_ack.hpp"

namespace hazard {
namespace {

TEST(AckMessage, FormatOfD22AndStrictParse) {
  const ConfigAck ack{"archie", 25, 0.9, 0.6561, 0.8};
  EXPECT_EQ(format_config_ack(ack), "vname=archie,width=25,pd=0.9,pfa=0.656,pclass=0.8");
  const auto back = parse_config_ack(format_config_ack(ack));
  ASSERT_TRUE(back);
  EXPECT_EQ(back.value->vname, "archie");
  EXPECT_EQ(back.value->pfa, 0.656);
  EXPECT_EQ(parse_config_ack("width=25,pd=0.9,pfa=0.656,pclass=0.8").error,
            "missing field 'vname'");  // D22: the manager needs vname
  EXPECT_EQ(parse_config_ack("vname=a,width=25,pd=0.9,pfa=0.656,pclass=0.8,extra=1").error,
            "unexpected key 'extra'");
  EXPECT_EQ(parse_config_ack("vname=a,width=25,pd=0.9,pclass=0.8").error, "missing field 'pfa'");
}

}  // namespace
}  // namespace hazard
