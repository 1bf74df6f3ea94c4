#include "input_log.hpp"

#include <ostream>

#include "moos/alog.hpp"

namespace hazard_replay {

std::optional<InputLog> InputLog::open(const std::string& path, std::ostream& err,
                                       std::string& problem) {
  std::optional<base::LineStream> lines = base::LineStream::open(path, kMaxInputLineBytes, problem);
  if (!lines) return std::nullopt;
  InputLog log(std::move(*lines), path, err);
  log.fill();
  return log;
}

InputLog::InputLog(base::LineStream lines, std::string path, std::ostream& err)
    : lines_(std::move(lines)), path_(std::move(path)), err_(&err) {}

bool InputLog::window_full() const {
  return window_.size() >= kReorderWindowLines || window_bytes_ >= kReorderWindowBytes;
}

bool InputLog::read_line() {
  const std::optional<std::string_view> line = lines_.next();
  if (!line) return false;
  const moos::AlogViewParse p = moos::parse_alog_view(*line);
  switch (p.kind) {
    case moos::AlogLineKind::kEntry:
      window_.push(Held{p.entry.time_s, arrivals_++, std::string(p.entry.variable),
                        std::string(p.entry.value)});
      window_bytes_ += p.entry.variable.size() + p.entry.value.size();
      break;
    case moos::AlogLineKind::kHeader:
      if (const auto logstart = moos::alog_logstart(*line)) logstart_s_ = *logstart;
      break;
    case moos::AlogLineKind::kMalformed:
      if (malformed_.admit()) {
        *err_ << path_ << ":" << lines_.line_number() << ": warning: " << p.error
              << "; line skipped\n";
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
  // Moved out of the top before pop(): the order reads only time_s and order, which stay.
  current_ = std::move(const_cast<Held&>(window_.top()));
  window_.pop();
  window_bytes_ -= current_.variable.size() + current_.value.size();
  if (last_time_s_ && current_.time_s < *last_time_s_) ++late_;
  if (!last_time_s_ || current_.time_s > *last_time_s_) last_time_s_ = current_.time_s;
  mail_ = hazard::Mail{current_.variable, current_.value, current_.time_s};
  return &mail_;
}

void InputLog::finish(std::ostream& err) const {
  const std::string where = "hazard_replay: " + path_ + ": ";
  if (malformed_.dropped() > 0) {
    err << where << malformed_.summary("malformed lines skipped (not printed)") << "\n";
  }
  if (unusable_times_ > 0) err << where << moos::unusable_times_warning(unusable_times_) << "\n";
  if (lines_.long_lines() > 0) {
    err << where << lines_.long_lines() << " lines over " << kMaxInputLineBytes
        << " bytes skipped\n";
  }
  if (late_ > 0) {
    err << where << late_ << " lines out of time order by more than the reorder window ("
        << kReorderWindowLines << " lines) delivered late\n";
  }
  if (!lines_.error().empty()) err << where << lines_.error() << "; the rest is not replayed\n";
}

}  // namespace hazard_replay
