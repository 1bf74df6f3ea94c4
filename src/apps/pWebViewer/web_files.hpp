#pragma once
// The page's files (src/apps/pWebViewer/web/), embedded in the binary at build time by
// embed_web_files.cmake: the install is one program and nothing is fetched from elsewhere.

#include <string_view>
#include <vector>

namespace web_viewer {

struct WebFile {
  std::string_view path;  ///< relative to web/, '/'-separated, e.g. "viewer.js"
  std::string_view bytes;
};

/// Every embedded file, sorted by path (generated).
const std::vector<WebFile>& web_files();
/// The file at `path` (no leading '/'); nullptr when there is none.
const WebFile* find_web_file(std::string_view path);
/// The HTTP content type for a path, by its extension.
std::string_view content_type(std::string_view path);

}  // namespace web_viewer
