// .moos mission reader. Follows docs/protocol.md section 6.1-6.3 (libMOOS
// CMOOSFileReader / CProcessConfigReader behaviour) plus two nsplug habits (`#include`, `$(NAME)`),
// except for the deliberate choices listed in include/moos/mission.hpp.
//
// Contract: parsing never throws and never stops early; every problem becomes a MissionError that
// names the file and line where it is (an included file names itself).
//
// Algorithm, in passes over the whole text (libMOOS collects every `define:` before any lookup):
//   1. expand: split into lines, drop comments and the first quote pair, apply `$(NAME)`, and
//      splice `#include`d files in place (recursively, with a stack of open files for cycles);
//   2. collect `define: NAME = value` lines;
//   3. apply `${NAME}` to the remaining lines;
//   4. structure: ProcessConfig headers, `{` on the next line, parameters up to `}`; every
//      `key = value` line (blocks included) is also a candidate for global lookups.

#include "moos/mission.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <utility>

#include "base/file.hpp"
#include "base/text.hpp"

namespace moos {

namespace {

namespace fs = std::filesystem;

/// Deeper include chains are almost certainly a mistake; the limit keeps recursion bounded.
constexpr int kMaxIncludeDepth = 32;
constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
constexpr std::string_view kDefineMarker = "define:";  // case-sensitive, protocol.md 6.1
constexpr std::string_view kHeaderPrefix = "PROCESSCONFIG=";
constexpr std::string_view kIncludeDirective = "#include";
/// nsplug directives other than #include that we do not evaluate.
constexpr std::string_view kUnsupportedDirectives[] = {"#define", "#ifdef",  "#ifndef",
                                                       "#elseifdef", "#else", "#endif"};

/// One logical line after pass 1: comment-free code with its origin.
struct SourceLine {
  std::string code;
  std::string file;
  int line = 0;
};

/// Removes the comment and the first pair of double quotes (libMOOS verbatim quoting,
/// protocol.md 6.1). A `//` inside that pair does not start a comment.
std::string strip_comment_and_quotes(std::string_view raw) {
  const std::string_view lead_trimmed = base::trim(raw);
  if (base::starts_with(lead_trimmed, "//")) return {};
  const auto open_quote = raw.find('"');
  const auto close_quote =
      open_quote == std::string_view::npos ? std::string_view::npos : raw.find('"', open_quote + 1);
  const bool have_pair = close_quote != std::string_view::npos;

  std::size_t comment = raw.find("//");
  while (comment != std::string_view::npos && have_pair && comment > open_quote &&
         comment < close_quote)
    comment = raw.find("//", close_quote + 1);
  std::string code(raw.substr(0, comment));
  if (have_pair && close_quote < code.size()) {
    code.erase(close_quote, 1);
    code.erase(open_quote, 1);
  }
  return code;
}

std::string directory_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

class Reader {
 public:
  Reader(const MissionOptions& options, std::vector<MissionError>* errors)
      : options_(options), errors_(errors) {}

  // ---- pass 1 -------------------------------------------------------------------------------
  /// The top file is on the include stack too, so a file that includes itself is a cycle.
  void expand_top(std::string_view content, const std::string& file_name) {
    expanded_bytes_ = content.size();
    std::error_code ec;
    include_stack_.push_back(fs::weakly_canonical(fs::path(file_name), ec).string());
    expand(content, file_name, 0);
    include_stack_.pop_back();
  }

  void expand(std::string_view content, const std::string& file_name, int depth) {
    if (base::starts_with(content, kUtf8Bom)) content.remove_prefix(kUtf8Bom.size());
    int line_no = 0;
    std::size_t start = 0;
    while (start <= content.size() && !over_budget_) {
      const auto end = content.find('\n', start);
      std::string_view raw = content.substr(start, end == std::string_view::npos ? end : end - start);
      if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
      ++line_no;
      expand_line(raw, file_name, line_no, depth);
      if (end == std::string_view::npos) break;
      start = end + 1;
    }
  }

  // ---- pass 2 and 3 -------------------------------------------------------------------------
  void apply_defines() {
    for (auto& sl : lines_) {
      const std::string_view t = base::trim(sl.code);
      if (!base::starts_with(t, kDefineMarker)) continue;
      const std::string_view body = t.substr(kDefineMarker.size());
      const auto eq = body.find('=');
      if (eq == std::string_view::npos) {
        error(sl.file, sl.line, "define: line has no '=': " + std::string(t));
      } else {
        const std::string name = base::remove_blanks(body.substr(0, eq));
        if (name.empty())
          error(sl.file, sl.line, "define: line has no name: " + std::string(t));
        else
          defines_[name] = base::remove_blanks(body.substr(eq + 1));  // later duplicate overrides
      }
      sl.code.clear();  // a define line is not itself a parameter (protocol.md 6.1)
    }
    for (auto& sl : lines_) sl.code = substitute_braces(sl.code, sl.file, sl.line);
  }

  // ---- pass 4 -------------------------------------------------------------------------------
  void structure(std::vector<ConfigLine>& globals, std::vector<ProcessBlock>& blocks) {
    enum class State { kTop, kExpectBrace, kInBlock };
    State state = State::kTop;
    ProcessBlock current;
    auto finish_block = [&]() {
      const auto dup = std::find_if(blocks.begin(), blocks.end(), [&](const ProcessBlock& b) {
        return base::iequals(b.app_name, current.app_name);
      });
      if (dup != blocks.end())
        error(current.file, current.line,
              "second ProcessConfig = " + current.app_name + " is never read (the first, at " +
                  dup->file + ":" + std::to_string(dup->line) + ", wins)",
              current.app_name);
      blocks.push_back(std::move(current));
      current = ProcessBlock{};
    };

    for (const auto& sl : lines_) {
      const std::string_view t = base::trim(sl.code);
      if (t.empty()) continue;

      if (state == State::kExpectBrace) {
        if (t.front() == '{') {
          if (!base::trim(t.substr(1)).empty())
            error(sl.file, sl.line, "text after '{' is ignored: " + std::string(t),
                  current.app_name);
          state = State::kInBlock;
          continue;
        }
        error(current.file, current.line,
              "ProcessConfig = " + current.app_name +
                  " is not a block: the next line must start with '{' (found at " + sl.file + ":" +
                  std::to_string(sl.line) + ")",
              current.app_name);
        current = ProcessBlock{};
        state = State::kTop;
        // fall through: this line is handled as an ordinary line
      }

      std::string header_name;
      if (parse_header(t, header_name, sl)) {
        if (state == State::kInBlock) {
          error(current.file, current.line,
                "ProcessConfig = " + current.app_name + " has no closing '}' before the next "
                "ProcessConfig at " + sl.file + ":" + std::to_string(sl.line),
                current.app_name);
          finish_block();
        }
        current.app_name = header_name;
        current.file = sl.file;
        current.line = sl.line;
        state = State::kExpectBrace;
        continue;
      }

      const std::string block_name = state == State::kInBlock ? current.app_name : std::string();
      if (state == State::kInBlock && t.front() == '}') {
        if (!base::trim(t.substr(1)).empty())
          error(sl.file, sl.line, "text after '}' is ignored: " + std::string(t), block_name);
        finish_block();
        state = State::kTop;
        continue;
      }
      if (t.front() == '{' || t.front() == '}') {
        error(sl.file, sl.line, std::string("unexpected '") + t.front() + "' (no ProcessConfig open)",
              block_name);
        continue;
      }
      const auto eq = t.find('=');
      if (eq == std::string_view::npos) {
        error(sl.file, sl.line, "line has no '=' and is ignored: " + std::string(t), block_name);
        continue;
      }
      ConfigLine cl;
      cl.key = std::string(base::trim(t.substr(0, eq)));
      cl.value = std::string(base::trim(t.substr(eq + 1)));
      cl.file = sl.file;
      cl.line = sl.line;
      if (cl.key.empty()) {
        error(sl.file, sl.line, "line has no name before '=': " + std::string(t), block_name);
        continue;
      }
      globals.push_back(cl);
      if (state == State::kInBlock) current.lines.push_back(std::move(cl));
    }

    if (state == State::kExpectBrace)
      error(current.file, current.line,
            "ProcessConfig = " + current.app_name + " is not a block: no '{' before the end",
            current.app_name);
    if (state == State::kInBlock) {
      error(current.file, current.line,
            "ProcessConfig = " + current.app_name + " has no closing '}' (block runs to the end)",
            current.app_name);
      finish_block();
    }
  }

 private:
  void error(const std::string& file, int line, std::string message, std::string block = {}) {
    if (errors_) errors_->push_back(MissionError{file, line, std::move(message), std::move(block)});
  }

  /// Header: after deleting blanks, `PROCESSCONFIG=<name>` case-insensitively (protocol.md 6.3).
  /// The one-line form `ProcessConfig = X {` is reported (libMOOS does not read it) and is not
  /// a header; it stays an ordinary line, as for libMOOS.
  bool parse_header(std::string_view t, std::string& name, const SourceLine& sl) {
    const std::string compact = base::remove_blanks(t);
    if (compact.size() <= kHeaderPrefix.size() ||
        !base::iequals(std::string_view(compact).substr(0, kHeaderPrefix.size()), kHeaderPrefix))
      return false;
    name = compact.substr(kHeaderPrefix.size());
    if (name.back() == '{') {
      name.pop_back();
      error(sl.file, sl.line,
            "'{' must be on the line after 'ProcessConfig = " + name +
                "': libMOOS does not read this block, so neither do we",
            name);
      return false;
    }
    return true;
  }

  /// False (after one error naming the bound) once the whole expansion is past a bound.
  bool within_budget(std::size_t used, std::size_t bound, const char* what,
                     const std::string& file_name, int line_no) {
    if (used <= bound) return true;
    over_budget_ = true;
    error(file_name, line_no,
          "the mission file expands to more than " + std::to_string(bound) + " " + what +
              " (an #include fan-out?); the rest of it is ignored");
    return false;
  }

  void expand_line(std::string_view raw, const std::string& file_name, int line_no, int depth) {
    if (!within_budget(++expanded_lines_, options_.max_expanded_lines, "lines", file_name, line_no))
      return;
    std::string code = strip_comment_and_quotes(raw);
    code = substitute_parens(code, file_name, line_no);
    const std::string_view t = base::trim(code);
    if (is_directive(t, kIncludeDirective)) {
      include(t.substr(kIncludeDirective.size()), file_name, line_no, depth);
      return;
    }
    for (std::string_view directive : kUnsupportedDirectives) {
      if (is_directive(t, directive)) {
        error(file_name, line_no,
              "nsplug directive " + std::string(directive) +
                  " is not supported (run nsplug on the file first); line ignored");
        return;
      }
    }
    lines_.push_back(SourceLine{std::move(code), file_name, line_no});
  }

  static bool is_directive(std::string_view t, std::string_view directive) {
    if (!base::starts_with(t, directive)) return false;
    return t.size() == directive.size() || t[directive.size()] == ' ' || t[directive.size()] == '\t';
  }

  void include(std::string_view rest, const std::string& file_name, int line_no, int depth) {
    rest = base::trim(rest);
    std::string target;
    std::string_view after;
    if (!rest.empty() && rest.front() == '<') {
      const auto close = rest.find('>');
      if (close == std::string_view::npos) {
        error(file_name, line_no, "#include <... has no closing '>'");
        return;
      }
      target = std::string(rest.substr(1, close - 1));
      after = rest.substr(close + 1);
    } else {
      const auto blank = rest.find_first_of(base::kBlanks);
      target = std::string(rest.substr(0, blank));
      after = blank == std::string_view::npos ? std::string_view() : rest.substr(blank);
    }
    if (target.empty()) {
      error(file_name, line_no, "#include names no file");
      return;
    }
    if (!base::trim(after).empty()) {
      error(file_name, line_no,
            "unexpected text after the #include path: " + std::string(base::trim(after)));
      return;
    }
    fs::path path(target);
    if (path.is_relative()) path = fs::path(directory_of(file_name)) / path;
    const std::string shown = path.lexically_normal().string();
    std::error_code ec;
    const std::string canonical = fs::weakly_canonical(path, ec).string();
    for (const auto& open : include_stack_) {
      if (open == canonical) {
        std::string chain;
        for (const auto& f : include_stack_) chain += f + " -> ";
        error(file_name, line_no, "#include cycle: " + chain + canonical);
        return;
      }
    }
    if (depth >= kMaxIncludeDepth) {
      error(file_name, line_no,
            "#include nested deeper than " + std::to_string(kMaxIncludeDepth) + " files");
      return;
    }
    if (!within_budget(++included_files_, options_.max_included_files, "included files",
                       file_name, line_no))
      return;
    const base::Result<std::string> content = base::read_file_text(path.string());
    if (!content) {
      error(file_name, line_no, "cannot read included file " + shown + ": " + content.error);
      return;
    }
    expanded_bytes_ += content.value->size();
    if (!within_budget(expanded_bytes_, options_.max_expanded_bytes, "bytes", file_name, line_no))
      return;
    include_stack_.push_back(canonical);
    expand(*content.value, shown, depth + 1);
    include_stack_.pop_back();
  }

  std::optional<std::string> lookup_environment(const std::string& name) const {
    if (!options_.use_environment) return std::nullopt;
    const char* v = std::getenv(name.c_str());
    if (!v) return std::nullopt;
    return std::string(v);
  }

  /// nsplug `$(NAME)`: substitutions, then the environment; missing names are errors and the
  /// text is kept as written.
  std::string substitute_parens(const std::string& code, const std::string& file, int line) {
    return substitute(code, "$(", ')', file, line, [&](const std::string& name) {
      if (auto it = options_.substitutions.find(name); it != options_.substitutions.end())
        return std::optional<std::string>(it->second);
      if (auto env = lookup_environment(name)) return env;
      error(file, line, "$(" + name + ") is not defined (give --" + name + "=value)");
      return std::optional<std::string>();
    });
  }

  /// libMOOS `${NAME}`: `define:` values, then the environment, else the bare NAME
  /// (protocol.md 6.1).
  std::string substitute_braces(const std::string& code, const std::string& file, int line) {
    return substitute(code, "${", '}', file, line, [&](const std::string& name) {
      if (auto it = defines_.find(name); it != defines_.end())
        return std::optional<std::string>(it->second);
      if (auto env = lookup_environment(name)) return env;
      error(file, line, "${" + name + "} is not defined by a define: line or the environment");
      return std::optional<std::string>(name);
    });
  }

  /// Replaces every `<open>NAME<close>`; values are not scanned again (not recursive).
  template <typename Lookup>
  std::string substitute(const std::string& code, std::string_view open, char close,
                         const std::string& file, int line, Lookup lookup) {
    std::string out;
    std::size_t pos = 0;
    while (true) {
      const auto at = code.find(open, pos);
      if (at == std::string::npos) break;
      const auto end = code.find(close, at + open.size());
      if (end == std::string::npos) {
        error(file, line, "unterminated " + std::string(open) + " in: " + code);
        break;
      }
      out.append(code, pos, at - pos);
      const std::string name = code.substr(at + open.size(), end - at - open.size());
      if (auto value = lookup(name))
        out += *value;
      else
        out.append(code, at, end + 1 - at);
      pos = end + 1;
    }
    out.append(code, pos, std::string::npos);
    return out;
  }

  const MissionOptions& options_;
  std::vector<MissionError>* errors_;
  std::vector<std::string> include_stack_;
  // The whole expansion so far, against MissionOptions' bounds.
  std::size_t included_files_ = 0;
  std::size_t expanded_lines_ = 0;
  std::size_t expanded_bytes_ = 0;
  bool over_budget_ = false;
  std::vector<SourceLine> lines_;
  std::map<std::string, std::string> defines_;
};

}  // namespace

std::string MissionError::to_string() const {
  if (line > 0) return file + ":" + std::to_string(line) + ": " + message;
  return file + ": " + message;
}

bool MissionError::concerns(std::string_view app_name) const {
  return block.empty() || base::iequals(block, app_name);
}

std::optional<MissionFile> MissionFile::load(const std::string& path, const MissionOptions& options,
                                             std::vector<MissionError>* errors) {
  const base::Result<std::string> content = base::read_file_text(path);
  if (!content) {
    if (errors)
      errors->push_back(MissionError{path, 0, "cannot read the mission file: " + content.error, {}});
    return std::nullopt;
  }
  return parse(*content.value, path, options, errors);
}

MissionFile MissionFile::parse(std::string_view text, const std::string& file_name,
                               const MissionOptions& options, std::vector<MissionError>* errors) {
  MissionFile mission;
  mission.path_ = file_name;
  Reader reader(options, errors);
  reader.expand_top(text, file_name);
  reader.apply_defines();
  reader.structure(mission.globals_, mission.blocks_);
  return mission;
}

const ConfigLine* MissionFile::global_line(std::string_view key) const {
  const std::string wanted = base::remove_blanks(key);
  for (const auto& line : globals_)
    if (base::iequals(base::remove_blanks(line.key), wanted)) return &line;
  return nullptr;
}

std::optional<std::string> MissionFile::global(std::string_view key) const {
  const ConfigLine* line = global_line(key);
  if (!line) return std::nullopt;
  return base::remove_blanks(line->value);
}

std::optional<double> MissionFile::global_double(std::string_view key) const {
  const auto value = global(key);
  if (!value) return std::nullopt;
  return base::parse_number(*value);
}

const ProcessBlock* MissionFile::block(std::string_view app_name) const {
  for (const auto& b : blocks_)
    if (base::iequals(b.app_name, app_name)) return &b;
  return nullptr;
}

std::string MissionFile::directory() const { return directory_of(path_); }

}  // namespace moos
