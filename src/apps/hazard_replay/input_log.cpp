#include "input_log.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <ostream>

#include "moos/alog.hpp"

namespace hazard_replay {

std::optional<InputLog> InputLog::open(const std::string& path, std::ostream& err,
                                       std::string& problem) {
  InputLog log(path, err);
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode)) {
    base::Result<base::WholeFile> whole = base::WholeFile::open(path, kMaxMappedLogBytes);
    if (!whole) {
      problem = std::move(whole.error);
      return std::nullopt;
    }
    log.mapped_ = std::move(whole.value);
  } else {
    base::Result<base::LineStream> stream = base::LineStream::open(path, kMaxInputLineBytes);
    if (!stream) {
      problem = std::move(stream.error);
      return std::nullopt;
    }
    log.stream_.emplace(std::move(*stream.value));
  }
  log.fill();
  return log;
}

bool InputLog::window_full() const {
  return window_.size() >= kReorderWindowLines || window_bytes_ >= kReorderWindowBytes;
}

void InputLog::hold(Held entry) {
  window_bytes_ += entry.variable_size + entry.value_size;
  if (window_.empty() || !(entry.time_s < window_.back().time_s)) {
    window_.push_back(std::move(entry));
    return;
  }
  // After every entry of the same time or earlier: equal times keep the log's order.
  const auto at = std::upper_bound(window_.begin(), window_.end(), entry.time_s,
                                   [](double t, const Held& e) { return t < e.time_s; });
  window_.insert(at, std::move(entry));
}

// The next line of the mapped file (split as std::getline splits) or of the stream.
std::optional<std::string_view> InputLog::next_line() {
  if (stream_) {
    auto line = stream_->next();
    line_number_ = stream_->line_number();
    return line;
  }
  const std::string_view all = mapped_->text();
  while (cursor_ < all.size()) {
    const std::size_t newline = all.find('\n', cursor_);
    const std::size_t end = newline == std::string_view::npos ? all.size() : newline;
    const std::string_view line = all.substr(cursor_, end - cursor_);
    cursor_ = end + 1;
    ++line_number_;
    if (line.size() <= kMaxInputLineBytes) return line;
    ++long_lines_;
  }
  return std::nullopt;
}

bool InputLog::read_line() {
  const std::optional<std::string_view> line = next_line();
  if (!line) return false;
  const moos::AlogViewParse p = moos::parse_alog_view(*line);
  switch (p.kind) {
    case moos::AlogLineKind::kEntry: {
      Held held;
      held.time_s = p.entry.time_s;
      held.variable_size = p.entry.variable.size();
      held.value_size = p.entry.value.size();
      if (mapped_) {
        held.base = mapped_->text().data();
        held.variable_at = static_cast<std::size_t>(p.entry.variable.data() - held.base);
        held.value_at = static_cast<std::size_t>(p.entry.value.data() - held.base);
      } else {
        held.text.reserve(held.variable_size + held.value_size);
        held.text.append(p.entry.variable).append(p.entry.value);
        held.value_at = held.variable_size;
      }
      hold(std::move(held));
      break;
    }
    case moos::AlogLineKind::kHeader:
      if (const auto logstart = moos::alog_logstart(*line)) logstart_s_ = *logstart;
      break;
    case moos::AlogLineKind::kMalformed:
      if (malformed_.admit()) {
        *err_ << path_ << ":" << line_number_ << ": warning: " << p.error << "; line skipped\n";
      }
      break;
    case moos::AlogLineKind::kUnusableTime:
      ++unusable_times_;
      break;
    case moos::AlogLineKind::kBlank:
      break;
  }
  return true;
}

void InputLog::fill() {
  while (!at_end_ && !window_full()) {
    if (!read_line()) at_end_ = true;
  }
}

const hazard::Mail* InputLog::next() {
  fill();
  if (window_.empty()) return nullptr;
  current_ = std::move(window_.front());
  window_.pop_front();
  window_bytes_ -= current_.variable_size + current_.value_size;
  if (last_time_s_ && current_.time_s < *last_time_s_) ++late_;
  if (!last_time_s_ || current_.time_s > *last_time_s_) last_time_s_ = current_.time_s;
  mail_ = hazard::Mail{current_.variable(), current_.value(), current_.time_s};
  return &mail_;
}

void InputLog::finish(std::ostream& err) const {
  const std::string where = "hazard_replay: " + path_ + ": ";
  if (malformed_.dropped() > 0) {
    err << where << malformed_.summary("malformed lines skipped (not printed)") << "\n";
  }
  if (unusable_times_ > 0) err << where << moos::unusable_times_warning(unusable_times_) << "\n";
  const std::size_t long_lines = stream_ ? stream_->long_lines() : long_lines_;
  if (long_lines > 0) {
    err << where << base::long_lines_warning(long_lines, kMaxInputLineBytes) << "\n";
  }
  if (late_ > 0) {
    err << where << late_ << " lines out of time order by more than the reorder window ("
        << kReorderWindowLines << " lines) delivered late\n";
  }
  if (stream_ && !stream_->error().empty()) {
    err << where << stream_->error() << "; the rest is not replayed\n";
  }
}

}  // namespace hazard_replay
