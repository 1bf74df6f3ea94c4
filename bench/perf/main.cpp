// perf_workloads: the fixed workloads of the instruction-count gate (bench/perf/gate.py,
// docs/performance.md "The instruction-count gate").
//
//   perf_workloads --list             the workloads, one per line: NAME  SUMMARY
//   perf_workloads --workload=NAME    runs one and prints "NAME checksum=HEX"
//   perf_workloads --toolchain        the compiler and build type it was built with (the
//                                     gate records them beside the counts)
//
// Exit status: 0 done, 2 bad arguments or an unknown workload, 1 a workload failed.
#include <cstdio>
#include <exception>
#include <string>

#include "workloads.hpp"

namespace {

int usage() {
  std::fprintf(stderr, "usage: perf_workloads --list | --toolchain | --workload=NAME\n");
  return 2;
}

int run(const std::string& name) {
  for (const perf::Workload& w : perf::workloads()) {
    if (name != w.name) continue;
    try {
      const std::uint64_t sum = w.run();
      std::printf("%s checksum=%016llx\n", w.name, static_cast<unsigned long long>(sum));
      return 0;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "perf_workloads: %s: %s\n", w.name, e.what());
      return 1;
    }
  }
  std::fprintf(stderr, "perf_workloads: no workload named '%s' (--list shows them)\n", name.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) return usage();
  const std::string arg = argv[1];
  if (arg == "--list") {
    for (const perf::Workload& w : perf::workloads()) std::printf("%-16s %s\n", w.name, w.summary);
    return 0;
  }
  if (arg == "--toolchain") {
#if defined(__clang__)
    std::printf("clang %s", __clang_version__);
#elif defined(__GNUC__)
    std::printf("gcc %s", __VERSION__);
#else
    std::printf("unknown compiler");
#endif
#ifdef NDEBUG
    std::printf(", NDEBUG\n");
#else
    std::printf(", assertions on\n");
#endif
    return 0;
  }
  const std::string prefix = "--workload=";
  if (arg.compare(0, prefix.size(), prefix) != 0 || arg.size() == prefix.size()) return usage();
  return run(arg.substr(prefix.size()));
}
