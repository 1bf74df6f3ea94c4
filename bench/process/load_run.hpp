#pragma once
// One measured run of the process benchmark: a MOOSDB and a sensor started on a fresh port, V
// lawnmower vehicles played against them for a simulated duration, the costs read from /proc.
//
// Contract:
// - The hazard file must exist; the run writes mission.moos and the processes' logs into
//   `work_dir` (created if needed) and leaves them there.
// - Every wait is bounded (start-up_timeout_real_s for the sensor to acknowledge every
//   vehicle's configuration, a few seconds for everything else); both processes are stopped
//   before run_load returns, whatever happened.
// - The measurement window starts when the sensor has iterated once (its first APPCAST) and
//   every vehicle has its configuration acknowledged; it lasts duration_s / warp real seconds.
//   CPU is the difference of the /proc figures at its two ends.
// - Soak options (bench/soak/run.sh; all off by default, so the table runs are unchanged):
//   the MOOSDB's --log (moosdb-lite: every posting in an .alog), a UHZ_CONFIG_REQUEST per
//   vehicle every config_every_s, classify requests paced to one per vehicle every
//   classify_every_s (the newest unclassified detection; 0: one per detection at once), a drain
//   after the load (mail still read, nothing sent) so that pending answers arrive, and one
//   sample every sample_every_s (resident memory of both processes, the sensor's worst
//   iteration gap since the last sample) written to samples_csv.

#include <cstddef>
#include <ostream>
#include <optional>
#include <string>

namespace bench {

struct LoadSpec {
  int vehicles = 1;
  double field_side_m = 2000;
  double time_warp = 50;
  double duration_s = 600;       ///< simulated seconds of load
  double report_hz = 10;         ///< node reports per vehicle per MOOS second
  double request_hz = 4;         ///< UHZ_SENSOR_REQUEST per vehicle per MOOS second
  double app_tick_hz = 4;
  double speed_mps = 1.5;
  double sensor_width_m = 25;    ///< requested in UHZ_CONFIG_REQUEST; lanes are 2x apart
  double swath_length_m = 5;
  double swath_half_length_m = 2.5;  ///< the sensor's along-track half-extent, for matching
  bool show_hazards = false;
  double startup_timeout_real_s = 600;
  // Soak options (simulated seconds; 0 = off).
  std::string moosdb_log;        ///< --log=FILE for moosdb-lite, relative to the work folder
  double config_every_s = 0;
  double classify_every_s = 0;
  double drain_s = 0;
  double sample_every_s = 0;
  std::string samples_csv;       ///< where the samples go (required with sample_every_s)
};

struct Target {
  std::string label;      ///< "ours", "original"
  std::string sensor;     ///< the uFldHazardSensor program
  std::string moosdb;     ///< the MOOSDB program (MOOSDB or moosdb-lite)
  std::string hazard_file;
  std::string work_dir;
  /// IdleAppTick for this sensor's block (ours only: the original does not know it).
  std::optional<double> idle_app_tick_hz;
};

struct LoadResult {
  bool ok = false;
  std::string error;
  double startup_real_s = 0;       ///< sensor start to the last configuration ACK
  double window_real_s = 0;
  double simulated_h = 0;
  double sensor_cpu_per_h = 0;     ///< CPU seconds per simulated hour
  double moosdb_cpu_per_h = 0;
  double sensor_cpu_share = 0;     ///< fraction of one core during the window
  double iterations_per_s = -1;    ///< per MOOS second, from two APPCASTs; -1 when unknown
  long long sensor_rss_kb = 0;
  long long sensor_hwm_kb = 0;
  long long moosdb_hwm_kb = 0;
  std::size_t reports_sent = 0;
  double reports_nominal = 0;
  std::size_t detections = 0;
  std::size_t matched = 0;         ///< detections traced to the node report that caused them
  std::size_t hazard_reports = 0;
  double delay_p50_ms = -1;        ///< node report sent -> detection report received, real ms
  double delay_p99_ms = -1;
};


LoadResult run_load(const LoadSpec& spec, const Target& target, std::ostream& log);

}  // namespace bench
