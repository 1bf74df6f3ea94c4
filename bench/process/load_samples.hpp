#pragma once
// The samples of a soak run (bench/soak/run.sh): one CSV line per sample, so that memory growth
// and iteration lag can be judged after the run.
//
// Contract:
// - open() writes the header: sim_s,sensor_rss_kb,moosdb_rss_kb,worst_iter_gap,worst_iter_len.
// - note_iteration_gap() and note_iteration_length() take the sensor's <MOOSNAME>_ITER_GAP (the
//   MOOS time between two iterations) and _ITER_LEN (the MOOS time one iteration took), both in
//   AppTick periods (1 = one period), as they arrive.
// - write() appends one line with the worst gap and length noted since the previous line
//   (0 when none arrived), then forgets them.

#include <fstream>
#include <string>

namespace bench {

class SampleLog {
 public:
  bool open(const std::string& path);
  void note_iteration_gap(double periods);
  void note_iteration_length(double periods);
  void write(double sim_s, long long sensor_rss_kb, long long moosdb_rss_kb);

 private:
  std::ofstream out_;
  double worst_gap_ = 0;
  double worst_len_ = 0;
};

}  // namespace bench
