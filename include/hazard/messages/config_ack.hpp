#pragma once
// UHZ_CONFIG_ACK and UHZ_CONFIG_ACK_<V> (differences.md D22, D23): the settings in force after an
// accepted configuration request (or the automatic default, D4).
//
// Example: vname=archie,width=25,pd=0.9,pfa=0.656,pclass=0.8
//
// Exactly these keys in this order; width FMT(.,1), pd/pfa/pclass FMT(.,3). Both variables carry
// vname (D22: the original vehicle-side manager rejects an ack without it or with any extra key),
// and parse_config_ack is as strict: all five keys, non-empty, nothing else.

#include <string>
#include <string_view>

#include "hazard/messages/parsed.hpp"

namespace hazard {

struct ConfigAck {
  std::string vname;
  double width_m = 0.0;
  double pd = 0.0;
  double pfa = 0.0;
  double pclass = 0.0;
};

Parsed<ConfigAck> parse_config_ack(std::string_view text);
std::string format_config_ack(const ConfigAck& ack);

}  // namespace hazard
