#include "HazardStudy_Info.hpp"

namespace hazard_study {

std::string usage_line() {
  return "Usage: hazard_study MISSION.moos [--seed=N | --seeds=A..B] [--setting=LABEL]\n"
         "         [--set=BLOCK.NAME=VALUE ...] [--field=\"GEN_HAZARDS OPTIONS\"\n"
         "         [--field-seed=N | --field-seeds=A..B]] [--max-time=S] [--deploy-at=S]\n"
         "         [--final=V,...] [--alog=OUT.alog] [--summary] [--NAME=value ...]";
}

std::string help_text() {
  return usage_line() +
         "\n"
         "\n"
         "Runs whole missions in lockstep, without MOOSDB, sockets, threads or the wall\n"
         "clock: the processes of MISSION.moos's `ProcessConfig = ANTLER` block\n"
         "(uFldHazardSensor, uFldHazardMetric, pHazardMgr, uSimSurveyVehicle; MOOSDB,\n"
         "pLogLite and pWebViewer are skipped) run on an in-process MOOS database, each with\n"
         "its own ProcessConfig block, cycling at its AppTick in simulated time. One second\n"
         "after the start the runner posts DEPLOY_ALL and HAZARD_SEARCH_START; the mission\n"
         "ends when the report of every final vehicle is graded, or at --max-time.\n"
         "Writes one JSON line per mission:\n"
         "  {\"setting\":L,\"seed\":S,\"end\":E,\"score\":X,\"found\":F,\"missed\":M,\n"
         "   \"false_alarms\":A,\"time_used\":T,\"detections\":D,\"classifications\":C,\"sim_s\":R}\n"
         "E is graded, empty_report or max_time; values the mission did not produce are null.\n"
         "With --field, \"field_seed\":G follows \"setting\".\n"
         "\n"
         "Options:\n"
         "  --seed=N            the sensor's seed (replaces random_seed); default 1\n"
         "  --seeds=A..B        one mission per seed A to B, for each setting\n"
         "  --set=BLOCK.NAME=VALUE\n"
         "                      parameter NAME of ProcessConfig block BLOCK is VALUE (its lines\n"
         "                      of NAME are replaced; repeat for several lines or parameters)\n"
         "  --setting=LABEL     start a new setting: the --set that follow belong to it;\n"
         "                      every setting runs every seed\n"
         "  --field=\"OPTIONS\"   generate the field with gen_hazards' options (blank-separated:\n"
         "                      --polygon=..., --objects=N,TYPE, --exp, --aspect_*; not --seed\n"
         "                      or --output; at most 1000000 objects), in memory; it is the\n"
         "                      hazard_file of every uFldHazardSensor and uFldHazardMetric\n"
         "  --field-seed=N      the field's seed (gen_hazards --seed); default 1\n"
         "  --field-seeds=A..B  one field per seed A to B, each run with every setting and\n"
         "                      seed (field seeds x seeds at most 10000000)\n"
         "  --max-time=S        simulated seconds after deployment before a mission is\n"
         "                      stopped (default 12000)\n"
         "  --deploy-at=S       simulated seconds from the start to DEPLOY_ALL (default 1)\n"
         "  --final=V,...       the vehicles whose graded report ends a mission (default: the\n"
         "                      vname of each pHazardMgr without handover_to)\n"
         "  --alog=OUT.alog     also write every posting of the one mission (--seed) as an\n"
         "                      .alog that pWebViewer --replay and tools/render_mission.py read\n"
         "  --summary           instead of the lines, per setting: missions, mean score,\n"
         "                      standard deviation and its 95% confidence interval\n"
         "  --NAME=value        $(NAME) in MISSION.moos is value; PORT, VIEW_PORT and WARP\n"
         "                      default to 9000, 0 and 1, SEED to the first seed\n"
         "  --help, -h          this text\n"
         "  --version, -v       the release, then exit\n"
         "\n"
         "A field (the hazard files, or a generated one) is loaded once per field seed and\n"
         "shared by every mission over it. The same command gives the same output, byte for\n"
         "byte. Configuration warnings go to standard error; one caused by a --set is an\n"
         "error. Exit status: 0 done, 1 a mission or output file problem, 2 a bad command\n"
         "line, --set or --field.\n";
}

}  // namespace hazard_study
