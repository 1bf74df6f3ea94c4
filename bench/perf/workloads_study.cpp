// hazard_study's lockstep runner: one whole Jake mission (seed 1, the mission as written) on the
// in-process bus with a manual clock, as `hazard_study missions/jake/jake.moos --seed=1` runs it.
// The mission and its hazard file are copied into the scratch folder, so the count does not
// depend on where the checkout lies.
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "study.hpp"
#include "study_args.hpp"
#include "workloads.hpp"

namespace perf {

namespace {

std::string read_source_file(const std::string& relative) {
  const std::string path = std::string(PERF_SOURCE_DIR) + "/" + relative;
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw std::runtime_error("cannot read " + path);
  return text.str();
}

}  // namespace

std::uint64_t study_jake() {
  ScratchFolder folder;
  const std::string mission = folder.write("jake.moos", read_source_file("missions/jake/jake.moos"));
  folder.write("hazards.txt", read_source_file("missions/jake/hazards.txt"));
  const hazard_study::ParsedArgs parsed = hazard_study::parse_args({mission, "--seed=1"});
  if (!parsed.options) throw std::runtime_error(parsed.error);
  std::ostringstream out;
  std::ostringstream err;
  if (hazard_study::run(*parsed.options, out, err) != 0)
    throw std::runtime_error("the mission failed: " + err.str());
  return checksum(kChecksumStart, out.str());
}

}  // namespace perf
