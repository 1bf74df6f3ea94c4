#pragma once
// The fixed workloads of the instruction-count gate (docs/performance.md, "The instruction-count
// gate"). Each one runs the same code on the same input every time, with fixed seeds and a
// manual clock, so its instruction count under valgrind is a property of the code, not of the
// machine. Each returns a checksum of what it produced (postings, bytes, counts): printed, so
// the work cannot be optimised away and a change of behaviour shows as a changed number.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace perf {

struct Workload {
  const char* name;
  const char* summary;
  std::uint64_t (*run)();
};

/// Every workload, in the gate's order.
const std::vector<Workload>& workloads();

// FNV-1a over `text`, continuing from `hash`: the checksums.
std::uint64_t checksum(std::uint64_t hash, std::string_view text);
inline constexpr std::uint64_t kChecksumStart = 1469598103934665603ull;

/// A scratch folder under /tmp with a name of fixed length (the count must not depend on it);
/// removed with its files on destruction.
class ScratchFolder {
 public:
  ScratchFolder();
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  /// Writes `text` to `name` in the folder; returns the file's path.
  std::string write(const std::string& name, const std::string& text) const;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// A lawn-mowing fleet over a square field centred on the origin: vehicle v drives lane v
/// (lanes `lane_spacing_m` apart from the south edge inward), west to east, 1.5 m/s.
struct Fleet {
  int vehicles = 1;
  double half_extent_m = 100.0;
  double lane_spacing_m = 50.0;
  std::string name(int v) const { return "v" + std::to_string(v); }
  /// NODE_REPORT text of vehicle v at MOOS time t (seconds since the start).
  std::string node_report(int v, double t) const;
};

/// The value of `key` in a comma list "a=1,b=2" ("" when absent).
std::string field_value(const std::string& list, const std::string& key);

/// The smallest: the gate's own test runs it (tests/bench/test_perf_gate.py).
std::uint64_t gate_selftest();
std::uint64_t engine_survey();
std::uint64_t engine_dense();
std::uint64_t sensor_sparse();
std::uint64_t sensor_dense();
std::uint64_t sensor_dense_late();
std::uint64_t replay_log();
std::uint64_t database_relay();
std::uint64_t viewer_retained();
std::uint64_t study_jake();

}  // namespace perf
