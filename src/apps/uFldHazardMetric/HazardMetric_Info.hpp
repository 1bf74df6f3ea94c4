#pragma once
// The texts of uFldHazardMetric's information switches (--help, --example, --interface,
// --version). --example is generated from mission::metric_parameters().

#include <string>

namespace ufld_hazard_metric {

std::string help_text();
std::string example_text();
std::string interface_text();
std::string version_text();

}  // namespace ufld_hazard_metric
