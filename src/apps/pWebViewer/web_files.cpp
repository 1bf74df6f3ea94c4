#include "web_files.hpp"

#include "base/text.hpp"

namespace web_viewer {

const WebFile* find_web_file(std::string_view path) {
  for (const WebFile& f : web_files())
    if (f.path == path) return &f;
  return nullptr;
}

std::string_view content_type(std::string_view path) {
  struct Type {
    std::string_view extension;
    std::string_view type;
  };
  static constexpr Type kTypes[] = {
      {".html", "text/html; charset=utf-8"},       {".js", "text/javascript; charset=utf-8"},
      {".mjs", "text/javascript; charset=utf-8"},  {".css", "text/css; charset=utf-8"},
      {".json", "application/json"},               {".svg", "image/svg+xml"},
      {".png", "image/png"},                       {".ico", "image/x-icon"},
      {".txt", "text/plain; charset=utf-8"},
  };
  for (const Type& t : kTypes)
    if (base::ends_with(path, t.extension)) return t.type;
  return "application/octet-stream";
}

}  // namespace web_viewer
