#include "WebViewer_Info.hpp"

#include "WebViewer.hpp"
#include "mission_app.hpp"

namespace web_viewer {

namespace {

const std::vector<mission::ParamInfo> kServer = {
    {"http_port", "8080", "TCP port of the page (0: any free port, printed at start-up)"},
    {"http_bind", "127.0.0.1", "address to listen on (0.0.0.0 lets other machines in)"},
    {"allowed_hosts", "", "more Host names the page may be opened by (comma list; repeatable)"},
    {"max_clients", "8", "browsers connected at once (1..64)"},
    {"max_queued", "20000", "events waiting per browser before it is dropped as too slow"},
};

const std::vector<mission::ParamInfo> kWatch = {
    {"watch", "", "more variables to show (comma list, * and ? allowed; repeatable)"},
    {"watch_defaults", "true", "watch NODE_REPORT, VIEW_*, APPCAST and the score variables"},
    {"appcast_request", "true", "post APPCAST_REQ so every app keeps posting its AppCast"},
};

const std::vector<mission::ParamInfo> kBounds = {
    {"trail_length", "200", "node reports kept per vehicle for a new page's trail"},
    {"max_vehicles", "100", "vehicles kept"},
    {"max_labels", "20000", "labelled postings kept per VIEW_* variable"},
    {"unlabelled_ring", "2000", "newest unlabelled postings kept per VIEW_* variable"},
    {"max_appcasts", "500", "AppCasts kept (one per node and app)"},
    {"max_value_bytes", "65536", "longer strings are shown live but not kept"},
};

const std::vector<mission::ParamInfo> kButtons = {
    {"button_one", "", "LABEL # VAR=value # ... (pMarineViewer's convention; off unless set)"},
    {"button_two", "", "as button_one"},
    {"button_three", "", "as button_one"},
    {"button_four", "", "as button_one"},
};

const char* const kExampleButton = "DEPLOY # DEPLOY_ALL=true # MOOS_MANUAL_OVERRIDE_ALL=false";

}  // namespace

std::string help_text() {
  return mission_app::help_text(
      kAppName,
      "Serves a live map of the mission to a browser: vehicles and trails (NODE_REPORT),\n"
      "markers, polygons, circles, seglists and points (VIEW_*), each app's AppCast and\n"
      "the score, over HTTP with server-sent events. Without a MOOSDB it replays an .alog.\n"
      "Open the URL it prints (http://HOST:PORT/?token=...): the buttons work only with\n"
      "that run's token. See docs/viewer.md (\"Trust model\").\n",
      "  --replay=FILE.alog\n"
      "      Serve the page driven by the log instead of a MOOSDB\n"
      "      (until SIGINT or SIGTERM; the mission file is optional).\n"
      "  --export=FILE.alog --output=FILE.html\n"
      "      Write the page and the log as one self-contained HTML\n"
      "      file, then exit.\n");
}

std::string example_text() {
  return mission_app::example_text(
      kAppName, mission_app::example_body(kDefaultAppTick_hz, {{"The server", &kServer},
                                                               {"What is shown", &kWatch},
                                                               {"Bounds of the retained state", &kBounds},
                                                               {"Buttons", &kButtons}},
                                          {{"watch", "HAZARDSET_REPORT"},
                                           {"button_one", kExampleButton}}));
}

std::string interface_text() {
  const std::vector<mission_app::InterfaceVariable> subscriptions = {
      {"NODE_REPORT", "NAME=archie,X=-180,Y=-40,HDG=180,TYPE=kayak,...", "vehicles and trails"},
      {"VIEW_MARKER, VIEW_POLYGON, VIEW_CIRCLE, VIEW_SEGLIST, VIEW_POINT",
       "x=51,y=11.3,width=8,type=triangle,label=12", "shapes, by label (active=false removes)"},
      {"APPCAST", "proc=uFldHazardSensor!@#iter=12!@#node=shoreside!@#...", "the AppCast pane"},
      {"UHZ_MISSION_SCORE, HAZARD_SEARCH_SCORE, HAZARDSET_EVAL", "86.666667", "the score"},
      {"<watch variable>", "(any)", "each `watch` line"},
  };
  std::vector<mission_app::InterfaceVariable> publications = {
      {"PMV_CONNECT", "pWebViewer", "at each connection: apps post their markers again"},
      {"APPCAST_REQ", appcast_request_text(), "every 20 MOOS s (appcast_request = true)"},
      {"<button variable>", "DEPLOY_ALL=true", "each assignment of a pressed button"},
  };
  for (auto& p : mission_app::framework_publications(kAppName)) publications.push_back(p);
  return mission_app::interface_text(kAppName, subscriptions, publications);
}

std::string version_text() { return mission_app::version_text(kAppName); }

}  // namespace web_viewer
