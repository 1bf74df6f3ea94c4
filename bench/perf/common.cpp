// What the workloads share: checksums, the scratch folder, the fleet's tracks.
#include <stdlib.h>   // mkdtemp
#include <unistd.h>

#include <charconv>
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

namespace {

// `value` with two decimals, in integer arithmetic: snprintf's %.2f would be a large part of
// the workloads' own count, which is not the code under test.
void append_centi(std::string& out, double value) {
  long long centi = std::llround(value * 100.0);
  if (centi < 0) {
    out.push_back('-');
    centi = -centi;
  }
  char digits[32];
  const auto end = std::to_chars(digits, digits + sizeof digits, centi / 100).ptr;
  out.append(digits, end);
  out.push_back('.');
  out.push_back(static_cast<char>('0' + centi / 10 % 10));
  out.push_back(static_cast<char>('0' + centi % 10));
}

}  // namespace

std::string Fleet::node_report(int v, double t) const {
  std::string text;
  text.reserve(96);
  text += "NAME=v";
  text += std::to_string(v);
  text += ",X=";
  append_centi(text, -half_extent_m + std::fmod(t * 1.5, 2.0 * half_extent_m));
  text += ",Y=";
  append_centi(text, -half_extent_m + (v + 0.5) * lane_spacing_m);
  text += ",SPD=1.5,HDG=90,TYPE=kayak,TIME=";
  append_centi(text, 1700000000.0 + t);
  text += ",LENGTH=4";
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
