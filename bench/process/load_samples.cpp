#include "load_samples.hpp"

#include <algorithm>

#include "base/text.hpp"

namespace bench {

bool SampleLog::open(const std::string& path) {
  out_.open(path, std::ios::trunc);
  out_ << "sim_s,sensor_rss_kb,moosdb_rss_kb,worst_iter_gap,worst_iter_len\n";
  return static_cast<bool>(out_);
}

void SampleLog::note_iteration_gap(double periods) { worst_gap_ = std::max(worst_gap_, periods); }

void SampleLog::note_iteration_length(double periods) {
  worst_len_ = std::max(worst_len_, periods);
}

void SampleLog::write(double sim_s, long long sensor_rss_kb, long long moosdb_rss_kb) {
  out_ << base::fix(sim_s, 1) << ',' << sensor_rss_kb << ',' << moosdb_rss_kb << ','
       << base::fix(worst_gap_, 3) << ',' << base::fix(worst_len_, 4) << '\n';
  out_.flush();  // a run that fails half-way still leaves its samples
  worst_gap_ = 0;
  worst_len_ = 0;
}

}  // namespace bench
