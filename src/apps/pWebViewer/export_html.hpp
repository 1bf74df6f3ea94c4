#pragma once
// --export: the page and a run's mail as ONE self-contained HTML file that any browser opens
// from disk (no server, no network).
//
// Contract
// - index.html is the frame. Each <link rel="stylesheet" href="F"> of an embedded file becomes
//   a <style> block; each <script src="F"> of an embedded classic script is inlined; each
//   <script type="module" src="F"> becomes an inline module importing "pwv/F".
// - Every embedded .js file is a data: URL in an import map under "pwv/<path>", its relative
//   imports ('./x.js', '../x.js') rewritten to those names, so ES modules work from file://.
// - Before the page's scripts: window.VIEWER_REPLAY = {hello, mail} (replay_json's text), a
//   fetch() that answers "replay.json" from it, and an EventSource that only says the hello, so
//   the page runs its replay code whichever way it looks for the data.
// - nullopt with `error` when there is no index.html.

#include <optional>
#include <string>
#include <vector>

#include "web_files.hpp"

namespace web_viewer {

std::optional<std::string> export_html(const std::vector<WebFile>& files, const std::string& replay_json,
                                       std::string* error);

/// RFC 4648 base64 of `bytes`.
std::string base64(std::string_view bytes);

}  // namespace web_viewer
