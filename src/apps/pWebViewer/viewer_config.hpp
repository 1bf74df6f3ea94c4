#pragma once
// pWebViewer's block (docs/viewer.md, "Parameters"): the same lines configure the live app, the
// replay server and the export, so one .moos file serves all three.

#include <string>
#include <vector>

#include "buttons.hpp"
#include "http_server.hpp"
#include "live_feed.hpp"
#include "moos/mission.hpp"

namespace web_viewer {

/// What pMarineViewer draws, the AppCasts and the mission's score: watched unless
/// `watch_defaults = false`; `watch` lines add variables (patterns with * and ? allowed).
const std::vector<std::string>& default_watch();
/// True when `var` is in `watch` as written.
bool watch_contains(const std::vector<std::string>& watch, std::string_view var);
/// At most this many `watch` variables (each is a MOOS subscription).
inline constexpr std::size_t kMaxWatch = 64;
/// At most this many `allowed_hosts` names (each is compared with every request's Host).
inline constexpr std::size_t kMaxAllowedHosts = 32;

struct ViewerConfig {
  HttpOptions http;
  std::vector<std::string> watch = default_watch();
  std::vector<Button> buttons;
  FeedLimits limits;
  bool appcast_request = true;  ///< ask every app for its AppCast (APPCAST_REQ)
};

/// The hello's fixed part that the configuration decides (buttons, the page's bounds).
Hello configured_hello(const ViewerConfig& config);

/// Applies the block's lines in order. Each line not understood, or with a bad value, adds a
/// warning naming file:line, key and value, and changes nothing.
ViewerConfig read_viewer_config(const std::vector<moos::ConfigLine>& lines,
                                std::vector<std::string>* warnings);

}  // namespace web_viewer
