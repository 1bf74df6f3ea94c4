#pragma once
// UHZ_CONFIG_REQUEST (manual 4.4, differences.md D3, D11, "Settings"): choose a sensor setting.
//
// Examples: vname=archie,width=50,pd=0.9   (width request)
//           vname=archie,pd=0.75           (pd-only update)
//           vname=archie,width=25          (width request keeping the current pd)
//
// vname is required; width, if given, is a number > 0 (m, to each side); pd, if given, is a
// number in [0, 1]; at least one of them must be given. Unknown keys are ignored.

#include <optional>
#include <string>
#include <string_view>

#include "hazard/messages/parsed.hpp"

namespace hazard {

struct ConfigRequest {
  std::string vname;
  std::optional<double> width_m;
  std::optional<double> pd;
};

Parsed<ConfigRequest> parse_config_request(std::string_view text);
std::string format_config_request(const ConfigRequest& request);

}  // namespace hazard
