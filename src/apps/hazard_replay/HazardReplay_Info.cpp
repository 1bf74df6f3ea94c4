#include "HazardReplay_Info.hpp"

namespace hazard_replay {

std::string usage_line() {
  return "Usage: hazard_replay CONFIG.moos INPUT.alog [--alias=NAME] "
         "[--seed=N | --seeds=A..B [--score]] [--until=T] [--output=OUT.alog] [--NAME=value ...]";
}

std::string help_text() {
  return usage_line() +
         "\n"
         "\n"
         "Runs the uFldHazardSensor engine offline, without MOOS: reads the\n"
         "`ProcessConfig = uFldHazardSensor` block of CONFIG.moos (hazard files relative to\n"
         "the mission file), delivers each line of INPUT.alog at its time, iterates at the\n"
         "block's AppTick (default 4 Hz) from the first input to the last, and writes every\n"
         "posting as an .alog line (time, variable, source, value). The file's\n"
         "LatOrigin and LongOrigin place node reports given only as LAT/LON and\n"
         "hazard lines given only as lat/lon (the block's `geodesy` chooses how).\n"
         "\n"
         "Options:\n"
         "  --alias=NAME       read `ProcessConfig = NAME` instead; NAME is also the source\n"
         "                     column of the output\n"
         "  --seed=N           dice seed, a whole number (beats random_seed and seed_random)\n"
         "  --seeds=A..B       replay once per seed A to B; instead of the .alog, one JSON line\n"
         "                     per seed: {\"seed\":S,\"detections\":D,\"classifications\":C}\n"
         "  --score            with --seeds: each line also carries ,\"score\":X, the last\n"
         "                     HAZARD_SEARCH_SCORE of the input's HAZARDSET_REPORT lines graded\n"
         "                     by CONFIG.moos's `ProcessConfig = uFldHazardMetric` block (its\n"
         "                     hazard_file is the truth); left out when no report is accepted\n"
         "  --until=T          stop at time T (input time base) instead of the last input\n"
         "  --output=OUT.alog  write the postings to OUT.alog instead of standard output\n"
         "  --NAME=value       $(NAME) in CONFIG.moos is value, as on a MOOS app's command\n"
         "                     line (NAME starts with a capital letter)\n"
         "  --help, -h         this text\n"
         "  --version, -v      the release, then exit\n"
         "\n"
         "Same inputs and seed give the same output, byte for byte. Warnings, events and the\n"
         "seed in use go to standard error. Exit status: 0 done, 1 a file or block problem,\n"
         "2 a bad command line.\n";
}

}  // namespace hazard_replay
