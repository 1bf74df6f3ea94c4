// Fuzz target: hazard_replay's reading of an input .alog, end to end: the input is written as
// the .alog of a replay of a small fixed mission (three sensor options, a handful of objects,
// the jake settings), and hazard_replay::run streams it (base::LineStream, the reorder window,
// the skipped and counted lines) and feeds every entry through the sensor engine, as the
// program does. --until bounds the simulated time, so a far-future time stamp in the input
// cannot make one run last for hours.

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "replay.hpp"

namespace {

constexpr const char* kMission = R"(ServerPort = 9000
Community = shoreside
LatOrigin = 43.825300
LongOrigin = -70.330400

ProcessConfig = uFldHazardSensor
{
  AppTick = 4
  sensor_config = width=25, exp=4, pclass=0.85
  sensor_config = width=50, exp=2, pclass=0.60
  sensor_config = width=10, exp=6, pclass=0.93
  min_classify_interval = 30
  min_reset_interval = 300
  swath_length = 5
  show_pfa = true
  hazard = x=10,y=-20,label=1,type=hazard
  hazard = x=40,y=-60,label=2,type=benign,hr=0.4
  hazard = x=-30,y=-90,label=3,type=hazard,aspect=45,aspect_min=20,aspect_max=70
  hazard = x=80,y=-15,label=4,type=benign
}
)";

/// A scratch folder holding the mission, created once per fuzzing process and removed when it
/// exits.
class ScratchDir {
 public:
  ScratchDir() {
    char pattern[] = "/tmp/hazard-fuzz-replay-XXXXXX";
    if (mkdtemp(pattern) == nullptr) std::abort();
    path_ = pattern;
    std::ofstream(path_ + "/mission.moos") << kMission;
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

const std::string& scratch_dir() {
  static const ScratchDir dir;
  return dir.path();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input = scratch_dir() + "/input.alog";
  {
    std::ofstream out(input, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  hazard_replay::Options options;
  options.config_path = scratch_dir() + "/mission.moos";
  options.input_path = input;
  options.seed = 1;
  options.until_s = 120.0;
  std::ostringstream out, err;
  (void)hazard_replay::run(options, out, err);
  return 0;
}
