// pWebViewer's retained state (src/apps/pWebViewer/retained_state.cpp): a mission's mail applied
// posting by posting, and a snapshot for a page that connects every 20 MOOS seconds. 100
// vehicles' node reports (trails), their swath polygons (labelled per vehicle), a growing set of
// detection markers (labelled, past the label bound so the oldest are evicted), unlabelled
// circles (the ring), AppCasts and per-vehicle score rows.
#include <stdexcept>
#include <string>
#include <vector>

#include "retained_state.hpp"
#include "workloads.hpp"

namespace perf {

namespace {

constexpr int kVehicles = 100;
constexpr int kTenths = 600;  // 60 MOOS seconds

web_viewer::Mail text_mail(std::string var, std::string value, double t) {
  web_viewer::Mail m;
  m.var = std::move(var);
  m.src = "uFldHazardSensor";
  m.time_s = 1700000000.0 + t;
  m.sval = std::move(value);
  return m;
}

}  // namespace

std::uint64_t viewer_retained() {
  web_viewer::RetainedState state;
  Fleet fleet;
  fleet.vehicles = kVehicles;
  fleet.half_extent_m = 1000.0;
  fleet.lane_spacing_m = 20.0;
  std::uint64_t sum = kChecksumStart;
  int markers = 0;
  for (int k = 0; k <= kTenths; ++k) {
    const double t = k / 10.0;
    state.set_clock(1700000000.0 + t);
    for (int v = 0; v < kVehicles; ++v) {
      const std::string name = fleet.name(v);
      state.apply(text_mail("NODE_REPORT", fleet.node_report(v, t), t));
      if (k % 3 == 0) {
        state.apply(text_mail("VIEW_POLYGON", "pts={" + std::to_string(k) + ",0:10,10:0,10},label=uhz_" + name +
                                                  ",edge_color=white,duration=5", t));
      }
      if ((k + v) % 4 == 0) {
        state.apply(text_mail("VIEW_MARKER", "x=" + std::to_string(v) + ",y=" + std::to_string(k) +
                                                 ",type=triangle,label=d" + std::to_string(markers++), t));
      }
      if ((k + v) % 10 == 0) state.apply(text_mail("VIEW_CIRCLE", "x=1,y=2,radius=5,duration=3", t));
      if ((k + v) % 50 == 0)
        state.apply(text_mail("HAZARDSET_EVAL", "vname=" + name + ",score=" + std::to_string(k), t));
    }
    if (k % 10 == 0)
      state.apply(text_mail("APPCAST", "node=shoreside!@#proc=uFldHazardSensor!@#iter=" + std::to_string(k), t));
    if (k % 200 == 0) {
      for (const web_viewer::Mail& m : state.snapshot()) sum = checksum(checksum(sum, m.var), m.sval);
    }
  }
  return sum + state.size();
}

}  // namespace perf
