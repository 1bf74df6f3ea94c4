#include "export_html.hpp"

#include <regex>

#include "base/text.hpp"
#include "view_mail.hpp"

namespace web_viewer {

namespace {

constexpr const char* kModulePrefix = "pwv/";

const WebFile* find(const std::vector<WebFile>& files, const std::string& path) {
  for (const WebFile& f : files)
    if (f.path == path) return &f;
  return nullptr;
}

/// `spec` (relative to the folder of `from`) as a path below web/; "" when it leaves web/ or
/// is not relative.
std::string resolve(const std::string& from, const std::string& spec) {
  if (!base::starts_with(spec, "./") && !base::starts_with(spec, "../")) return std::string();
  std::vector<std::string> parts;
  for (std::string_view p : base::split(from, '/')) parts.emplace_back(p);
  parts.pop_back();  // the file's own name
  for (std::string_view p : base::split(spec, '/')) {
    if (p == ".") continue;
    if (p == "..") {
      if (parts.empty()) return std::string();
      parts.pop_back();
    } else {
      parts.emplace_back(p);
    }
  }
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : "/") + p;
  return out;
}

/// A module's text with its relative imports of embedded files renamed to "pwv/<path>".
std::string rename_imports(const std::vector<WebFile>& files, const WebFile& module) {
  static const std::regex kImport(R"(((?:\bfrom|\bimport)\s*\(?\s*)(['"])([^'"\n]+)\2)");
  const std::string text(module.bytes);
  std::string out;
  auto last = text.cbegin();
  for (std::sregex_iterator it(text.begin(), text.end(), kImport), end; it != end; ++it) {
    const std::smatch& m = *it;
    const std::string target = resolve(std::string(module.path), m[3].str());
    out.append(last, m[0].first);
    if (!target.empty() && find(files, target))
      out += m[1].str() + m[2].str() + kModulePrefix + target + m[2].str();
    else
      out += m[0].str();
    last = m[0].second;
  }
  out.append(last, text.cend());
  return out;
}

std::string import_map(const std::vector<WebFile>& files) {
  std::string imports;
  for (const WebFile& f : files) {
    if (!base::ends_with(f.path, ".js") && !base::ends_with(f.path, ".mjs")) continue;
    if (!imports.empty()) imports += ",\n";
    imports += json_string(kModulePrefix + std::string(f.path)) + ":\"data:text/javascript;base64," +
               base64(rename_imports(files, f)) + "\"";
  }
  return "<script type=\"importmap\">{\"imports\":{\n" + imports + "}}</script>\n";
}

// The data and the two stand-ins of the contract (see the header).
std::string replay_prelude(const std::string& replay_json) {
  return "<script>\nwindow.VIEWER_REPLAY = " + replay_json + ";\n" + R"JS((function () {
  const data = window.VIEWER_REPLAY;
  const realFetch = window.fetch ? window.fetch.bind(window) : null;
  window.fetch = function (url, options) {
    if (/(^|\/)replay\.json$/.test(String(url))) {
      return Promise.resolve(new Response(JSON.stringify(data),
        { headers: { 'Content-Type': 'application/json' } }));
    }
    return realFetch ? realFetch(url, options) : Promise.reject(new Error('offline'));
  };
  window.EventSource = class {
    constructor() {
      this.readyState = 1;
      this.listeners = [];
      setTimeout(() => {
        const event = { data: JSON.stringify(data.hello) };
        if (this.onopen) this.onopen({});
        if (this.onmessage) this.onmessage(event);
        this.listeners.forEach((f) => f(event));
      }, 0);
    }
    addEventListener(type, f) { if (type === 'message') this.listeners.push(f); }
    removeEventListener() {}
    close() { this.readyState = 2; }
  };
})();
</script>
)JS";
}

/// The value of attribute `name` in a tag's text ("" when absent).
std::string attribute(const std::string& tag, const std::string& name) {
  const std::regex re("\\b" + name + R"(\s*=\s*["']([^"']*)["'])", std::regex::icase);
  std::smatch m;
  return std::regex_search(tag, m, re) ? m[1].str() : std::string();
}

std::string inline_tags(const std::vector<WebFile>& files, const std::string& html) {
  static const std::regex kTag(R"(<link\b[^>]*>|<script\b[^>]*>\s*</script>)", std::regex::icase);
  std::string out;
  auto last = html.cbegin();
  for (std::sregex_iterator it(html.begin(), html.end(), kTag), end; it != end; ++it) {
    const std::string tag = (*it)[0].str();
    out.append(last, (*it)[0].first);
    last = (*it)[0].second;
    const bool is_link = base::starts_with(base::to_lower(tag), "<link");
    const std::string path = attribute(tag, is_link ? "href" : "src");
    const WebFile* file = path.empty() ? nullptr : find(files, path);
    if (!file || (is_link && !base::iequals(attribute(tag, "rel"), "stylesheet"))) {
      out += tag;
    } else if (is_link) {
      out += "<style>\n" + std::string(file->bytes) + "\n</style>";
    } else if (base::iequals(attribute(tag, "type"), "module")) {
      out += "<script type=\"module\">import \"" + std::string(kModulePrefix) + path + "\";</script>";
    } else {
      static const std::regex kEnd("</script");
      out += "<script>\n" + std::regex_replace(std::string(file->bytes), kEnd, "<\\/script") + "\n</script>";
    }
  }
  out.append(last, html.cend());
  return out;
}

}  // namespace

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned>(static_cast<unsigned char>(bytes[k])); };
    const unsigned v = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += kAlphabet[v >> 6 & 63];
    out += kAlphabet[v & 63];
  }
  if (i < bytes.size()) {
    const bool two = i + 1 < bytes.size();
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 |
                       (two ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0u);
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += two ? kAlphabet[v >> 6 & 63] : '=';
    out += '=';
  }
  return out;
}

std::optional<std::string> export_html(const std::vector<WebFile>& files, const std::string& replay_json,
                                       std::string* error) {
  const WebFile* index = find(files, "index.html");
  if (!index) {
    *error = "the page has no index.html";
    return std::nullopt;
  }
  std::string html = inline_tags(files, std::string(index->bytes));
  const std::string prelude = replay_prelude(replay_json) + import_map(files);
  // Before the first script (an import map must precede every module), else before </head>.
  std::size_t at = html.find("<script");
  const std::size_t head_end = html.find("</head>");
  if (at == std::string::npos || (head_end != std::string::npos && head_end < at)) at = head_end;
  if (at == std::string::npos) at = 0;
  html.insert(at, prelude);
  return html;
}

}  // namespace web_viewer
