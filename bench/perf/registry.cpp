// The gate's workloads, in its order.
#include "workloads.hpp"

namespace perf {

const std::vector<Workload>& workloads() {
  static const std::vector<Workload> all = {
      {"gate-selftest", "the reference survey once at 1 Hz: the gate's own test runs this one", gate_selftest},
      {"engine-survey", "the reference survey, 200 objects, 2 vehicles, 4 seeds (engine only)", engine_survey},
      {"engine-dense", "40,000 objects 5 m apart, 100 vehicles, 30 s, classify every detection (engine only)",
       engine_dense},
      {"sensor-sparse", "uFldHazardSensor on the in-process bus: 10,000 objects, 10 vehicles, 60 s", sensor_sparse},
      {"sensor-dense", "uFldHazardSensor on the in-process bus: 40,000 objects 5 m apart, 100 vehicles, 20 s",
       sensor_dense},
      {"sensor-dense-late", "sensor-dense with 20 MOOS seconds of mail at once: the mail backlog drains it",
       sensor_dense_late},
      {"replay", "hazard_replay::run: 100,000 objects, 100 vehicles, 30 s log (30,000 node reports)", replay_log},
      {"moosdb-relay", "moos::Database with the codec: 21 clients, 120 s of a 20-vehicle mission's mail",
       database_relay},
#ifdef PERF_WITH_STUDY
      {"study-jake", "hazard_study's lockstep runner: one whole Jake mission, seed 1 (6 apps, 4,700 MOOS s)",
       study_jake},
#endif
#ifdef PERF_WITH_VIEWER
      {"viewer-retained", "pWebViewer's retained state: 60 s of a 100-vehicle mission, 4 snapshots",
       viewer_retained},
#endif
  };
  return all;
}

}  // namespace perf
