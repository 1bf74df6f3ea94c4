#include "LogLite_Info.hpp"

#include "LogLite.hpp"
#include "mission_app.hpp"

namespace plog_lite {

namespace {

const std::vector<mission::ParamInfo> kParameters = {
    {"path", ".", "folder of the log (created if missing; relative to the current directory)"},
    {"file", "MOOSLog", "log name, without .alog"},
    {"file_timestamp", "true", "append _YYYY_MM_DD_____HH_MM_SS to the name"},
    {"wildcard_logging", "true", "log every variable (default false, as pLogger)"},
    {"wildcard_omit_pattern", "*_ITER_GAP, *_ITER_LEN", "variables not written (patterns)"},
    {"log", "DB_TIME @ 5", "log VAR at most every T s (repeatable; with wildcard logging too)"},
    {"async_log", "true", "pLogger's asynchronous log (the only mode)"},
};

}  // namespace

std::string help_text() {
  return mission_app::help_text(
      kAppName,
      "A small logger: writes every message it hears as pLogger's asynchronous log\n"
      "(.alog: TIME VARIABLE SOURCE VALUE after a LOGSTART header), for a community on a\n"
      "real MOOSDB. (moosdb-lite writes the same file itself with --log.)\n"
      "Records lost (a full disk, a deleted log file) are counted: a `%% GAP: N records\n"
      "lost` line marks where, a run warning says why, and the exit status is 3.\n"
      "See docs/missions.md.\n");
}

std::string example_text() {
  return mission_app::example_text(
      kAppName, mission_app::example_body(kDefaultAppTick_hz, {{"pLogger's parameters", &kParameters}}));
}

std::string interface_text() {
  const std::vector<mission_app::InterfaceVariable> subscriptions = {
      {"*", "(any)", "with wildcard_logging: every variable of every process"},
      {"<log variable>", "(any)", "each `log = VAR @ T`"},
  };
  return mission_app::interface_text(kAppName, subscriptions,
                                     mission_app::framework_publications(kAppName));
}

std::string version_text() { return mission_app::version_text(kAppName); }

}  // namespace plog_lite
