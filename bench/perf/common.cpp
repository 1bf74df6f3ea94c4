// What the workloads share: checksums, the scratch folder, the fleet's tracks.
#include <stdlib.h>   // mkdtemp
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "workloads.hpp"

namespace perf {

std::uint64_t checksum(std::uint64_t hash, std::string_view text) {
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

ScratchFolder::ScratchFolder() {
  // Always /tmp, never $TMPDIR: the path's length reaches the mission parser's work.
  char name[] = "/tmp/perf_workloads.XXXXXX";
  if (mkdtemp(name) == nullptr) throw std::runtime_error("perf_workloads: cannot create /tmp/perf_workloads.*");
  path_ = name;
}

ScratchFolder::~ScratchFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::string ScratchFolder::write(const std::string& name, const std::string& text) const {
  const std::string file = path_ + "/" + name;
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out.flush()) throw std::runtime_error("perf_workloads: cannot write " + file);
  return file;
}

std::string Fleet::node_report(int v, double t) const {
  const double x = -half_extent_m + std::fmod(t * 1.5, 2.0 * half_extent_m);
  const double y = -half_extent_m + (v + 0.5) * lane_spacing_m;
  char text[160];
  std::snprintf(text, sizeof text,
                "NAME=v%d,X=%.2f,Y=%.2f,SPD=1.5,HDG=90,TYPE=kayak,TIME=%.2f,LENGTH=4", v, x, y,
                1700000000.0 + t);
  return text;
}

std::string field_value(const std::string& list, const std::string& key) {
  const std::string tag = key + "=";
  std::size_t at = 0;
  while (at < list.size()) {
    const std::size_t end = std::min(list.find(',', at), list.size());
    if (list.compare(at, tag.size(), tag) == 0) return list.substr(at + tag.size(), end - at - tag.size());
    at = end + 1;
  }
  return "";
}

}  // namespace perf
