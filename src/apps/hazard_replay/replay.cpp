#include "replay.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <filesystem>
#include <limits>
#include <ostream>
#include <utility>

#include "app_support.hpp"
#include "hazard/config.hpp"
#include "hazard/driver.hpp"
#include "hazard/engine.hpp"
#include "base/text.hpp"
#include "base/warning_budget.hpp"
#include "input_log.hpp"
#include "moos/alog.hpp"
#include "moos/mission.hpp"
#include "score.hpp"

namespace hazard_replay {

namespace {

namespace fs = std::filesystem;
using base::fix;

// --seeds replays the input once per seed, so it holds the entries (the streamed single replay
// does not): their text, and views into it in time order.
struct HeldInput {
  std::deque<std::string> texts;      // variable, value, variable, ... (never moved)
  std::vector<hazard::Mail> entries;  // in time order
};

std::optional<HeldInput> hold_input(InputLog& log, std::string& problem) {
  HeldInput input;
  std::size_t bytes = 0;
  for (const hazard::Mail* m = log.next(); m != nullptr; m = log.next()) {
    bytes += m->variable.size() + m->value.size() + sizeof(hazard::Mail);
    if (bytes > kMaxInputLogBytes) {
      problem = "its entries take more than " + std::to_string(kMaxInputLogBytes) +
                " bytes (--seeds holds them all)";
      return std::nullopt;
    }
    const std::string& variable = input.texts.emplace_back(m->variable);
    const std::string& value = input.texts.emplace_back(m->value);
    input.entries.push_back(hazard::Mail{variable, value, m->time_s});
  }
  const auto earlier = [](const hazard::Mail& a, const hazard::Mail& b) {
    return a.time_s < b.time_s;
  };
  // In order but for lines beyond the reorder window: sorting only then.
  if (!std::is_sorted(input.entries.begin(), input.entries.end(), earlier)) {
    std::stable_sort(input.entries.begin(), input.entries.end(), earlier);
  }
  return input;
}

// Writes one engine call's outputs: postings to the log (through a large buffer, not one
// stream call per line), the rest to the error stream.
class Writer {
 public:
  Writer(std::ostream& out, std::ostream& err, std::string source)
      : out_(out), err_(err), source_(std::move(source)) {
    buffer_.reserve(kFlushBytes + kFlushBytes / 4);
  }
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;
  ~Writer() { flush(); }

  void write(const hazard::TimedOutputs& timed) {
    const hazard::Outputs& o = timed.outputs;
    const double time_s = timed.time_s;
    for (const hazard::Posting& p : o.postings) {
      append_columns(time_s, p.variable);
      moos::append_alog_value(buffer_, p.value);
    }
    if (buffer_.size() >= kFlushBytes) flush();
    if (o.config_warnings.empty() && o.run_warnings.empty() &&
        o.retracted_run_warnings.empty() && o.events.empty()) {
      return;
    }
    const std::string when = "[" + fix(time_s, 3) + "] ";
    print(config_warnings_, when, "config warning: ", o.config_warnings);
    print(run_warnings_, when, "run warning: ", o.run_warnings);
    print(resolved_, when, "resolved: ", o.retracted_run_warnings);
    for (const auto& e : o.events) err_ << when << "event: " << e << "\n";
  }

  // The count of each kind of warning left unprinted, one line each.
  void finish() {
    flush();
    for (const auto& [budget, what] :
         {std::pair{&config_warnings_, "config warnings"}, {&run_warnings_, "run warnings"},
          {&resolved_, "resolved run warnings"}}) {
      if (budget->dropped() > 0) {
        err_ << "hazard_replay: " << budget->summary(what) << " (not printed)\n";
      }
    }
  }

  // The TIME, VARIABLE and SOURCE columns; built once for a run of lines that share them (an
  // iteration's swath polygons), then copied.
  void append_columns(double time_s, std::string_view variable) {
    const bool same = time_s == columns_time_s_ &&
                      std::signbit(time_s) == std::signbit(columns_time_s_) &&  // "-0.000"
                      variable == columns_variable_;
    if (!same) {
      columns_.clear();
      moos::append_alog_columns(columns_, time_s, variable, source_);
      columns_time_s_ = time_s;
      columns_variable_.assign(variable.data(), variable.size());
    }
    buffer_.append(columns_);
  }

  // Warnings of one kind: the first base::kMaxWarningsPerKind of a run, then only counted.
  void print(base::WarningBudget& budget, const std::string& when, const char* kind,
             const std::vector<std::string>& warnings) {
    for (const auto& w : warnings) {
      if (budget.admit()) err_ << when << kind << w << "\n";
    }
  }

  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  static constexpr std::size_t kFlushBytes = std::size_t{1} << 20;
  std::ostream& out_;
  std::ostream& err_;
  std::string source_;
  std::string buffer_;
  std::string columns_;  // the columns of the last line written, for columns_time_s_ and ...
  double columns_time_s_ = std::numeric_limits<double>::quiet_NaN();  // (never equal at first)
  std::string columns_variable_;  // ... columns_variable_
  base::WarningBudget config_warnings_{base::kMaxWarningsPerKind};
  base::WarningBudget run_warnings_{base::kMaxWarningsPerKind};
  base::WarningBudget resolved_{base::kMaxWarningsPerKind};
};

// A guard against a mistyped --until (1e12 s at 4 Hz would never finish).
constexpr double kMaxIterations = 1e8;

}  // namespace

namespace {

// The refusal of a --until beyond kMaxIterations from the first input; empty when it is within.
std::string too_many_iterations(double start_s, double end_s, double tick_hz) {
  if ((end_s - start_s) * tick_hz <= kMaxIterations) return {};
  return "hazard_replay: " + fix((end_s - start_s) * tick_hz, 0) +
         " iterations from the first input to the end; more than " + fix(kMaxIterations, 0) +
         " is refused (check --until and AppTick)\n";
}

void report_too_far(const StreamCounts& counts, double tick_hz, std::ostream& err) {
  if (counts.too_far == 0) return;
  err << "hazard_replay: " << counts.too_far << " lines more than " << fix(kMaxIterations, 0)
      << " iterations (" << fix(kMaxIterations / tick_hz, 0)
      << " s at AppTick) after the first input skipped\n";
}

// --seeds: the held input replayed once per seed, one JSON line each.
int run_seeds(const Options& options, const moos::MissionFile& mission,
              const hazard::Engine& built, InputLog& log, std::ostream& out, std::ostream& err) {
  std::string problem;
  const std::optional<HeldInput> input = hold_input(log, problem);
  if (!input) {
    err << "hazard_replay: cannot read input log '" << options.input_path << "': " << problem
        << "\n";
    return 1;
  }
  const double tick_hz = built.config().app_tick_hz;
  const auto& mail = input->entries;
  const double start_s = mail.empty() ? 0.0 : mail.front().time_s;
  const double end_s = options.until_s.value_or(mail.empty() ? start_s : mail.back().time_s);
  if (const std::string refusal = too_many_iterations(start_s, end_s, tick_hz); !refusal.empty()) {
    err << refusal;
    return 1;
  }
  const Timeline timeline{&mail, start_s, end_s, tick_hz};
  std::optional<double> score;
  if (options.score) {
    // The recorded report does not depend on the dice: graded once, the same on every line.
    const RecordedScore graded = score_recorded_reports(mission, mail, end_s, err);
    if (!graded.error.empty()) {
      err << "hazard_replay: " << graded.error << " (in '" << options.config_path << "')\n";
      return 1;
    }
    score = graded.score;
    if (!score) {
      err << "hazard_replay: --score: '" << options.input_path
          << "' holds no HAZARDSET_REPORT the metric accepts; the lines carry no score\n";
    }
  }
  err << "hazard_replay: seeds " << options.seeds->first << ".." << options.seeds->last
      << ", AppTick " << base::fmt(tick_hz) << " Hz\n";
  for (std::uint64_t seed = options.seeds->first;; ++seed) {
    hazard::Driver seeded(study_engine(built, seed));
    out << seed_summary_json(seed, count_reports(seeded, timeline), score) << "\n";
    if (seed == options.seeds->last) break;
  }
  out.flush();
  return 0;
}

// One replay, streamed from the log to the .alog written.
int run_single(const Options& options, hazard::Engine built, InputLog& log, std::ostream& out,
               std::ostream& err) {
  const double tick_hz = built.config().app_tick_hz;
  const hazard::Mail* first = log.next();
  if (first && options.until_s) {
    const std::string refusal = too_many_iterations(first->time_s, *options.until_s, tick_hz);
    if (!refusal.empty()) {
      err << refusal;
      return 1;
    }
  }
  hazard::Driver driver(std::move(built));
  const hazard::SeedChoice& seed = driver.engine().seed();
  err << "hazard_replay: seed " << seed.seed << " (" << hazard::seed_source_name(seed.source)
      << "), AppTick " << base::fmt(tick_hz) << " Hz\n";
  out << moos::alog_header(fs::path(options.input_path).filename().string(), log.logstart_s());
  if (!first) {
    err << "hazard_replay: '" << options.input_path << "' holds no input lines\n";
    return 0;
  }
  Writer writer(out, err, options.app_name);
  const StreamCounts counts = replay_stream(
      driver,
      [&, given = false]() mutable { return std::exchange(given, true) ? log.next() : first; },
      options.until_s, tick_hz, [&](const hazard::TimedOutputs& t) { writer.write(t); });
  writer.finish();
  out.flush();
  report_too_far(counts, tick_hz, err);
  return 0;
}

}  // namespace

int run(const Options& options, std::ostream& out, std::ostream& err) {
  std::vector<moos::MissionError> mission_errors;
  moos::MissionOptions mission_options;
  mission_options.substitutions = options.substitutions;
  const auto mission =
      moos::MissionFile::load(options.config_path, mission_options, &mission_errors);
  if (!mission) {
    err << "hazard_replay: cannot read mission file '" << options.config_path << "'\n";
    return 1;
  }
  for (const moos::MissionError& e : mission_errors) {
    if (e.concerns(options.app_name)) err << e.to_string() << "\n";
  }
  const moos::ProcessBlock* block = mission->block(options.app_name);
  if (!block) {
    err << "hazard_replay: no 'ProcessConfig = " << options.app_name << "' block in '"
        << options.config_path << "'\n";
    return 1;
  }
  std::string problem;
  std::optional<InputLog> log = InputLog::open(options.input_path, err, problem);
  if (!log) {
    err << "hazard_replay: cannot read input log '" << options.input_path << "': " << problem
        << "\n";
    return 1;
  }
  // Hazard files are named relative to the mission file.
  // LatOrigin/LongOrigin place LAT/LON-only node reports and lat/lon hazard lines (geodesy).
  hazard::Engine built = app_support::make_sensor_engine(
      block->lines, mission->directory(), app_support::mission_origin(*mission),
      options.seeds ? options.seeds->first : options.seed, app_support::operating_system_seed);
  const int status = options.seeds ? run_seeds(options, *mission, built, *log, out, err)
                                   : run_single(options, std::move(built), *log, out, err);
  log->finish(err);
  return status;
}

StreamCounts replay_stream(hazard::Driver& driver,
                           const std::function<const hazard::Mail*()>& next_mail,
                           std::optional<double> until_s, double tick_hz,
                           const std::function<void(const hazard::TimedOutputs&)>& sink) {
  StreamCounts counts;
  const hazard::Mail* mail = next_mail();
  if (mail == nullptr) return counts;
  const double start_s = mail->time_s;
  const double last_allowed_s = start_s + kMaxIterations / tick_hz;
  sink(driver.start(start_s));
  long k = 0;
  double now_s = start_s;
  // Iterations before `t` (or at it too): mail stamped at an iteration's time goes first.
  const auto step_until = [&](double t, bool at_t_too) {
    while (at_t_too ? now_s <= t : now_s < t) {
      sink(driver.step(now_s));
      ++k;
      now_s = start_s + static_cast<double>(k) / tick_hz;
    }
  };
  double last_s = start_s;
  for (; mail != nullptr; mail = next_mail()) {
    if (until_s && mail->time_s > *until_s) continue;  // read on: a pipe's writer finishes
    if (mail->time_s > last_allowed_s) {
      ++counts.too_far;
      continue;
    }
    step_until(mail->time_s, false);
    sink(driver.deliver(*mail));
    last_s = std::max(last_s, mail->time_s);
  }
  step_until(until_s.value_or(last_s), true);
  return counts;
}

void replay(hazard::Driver& driver, const Timeline& timeline,
            const std::function<void(const hazard::TimedOutputs&)>& sink) {
  std::size_t next = 0;
  const std::vector<hazard::Mail>& mail = *timeline.mail;
  (void)replay_stream(
      driver, [&]() { return next < mail.size() ? &mail[next++] : nullptr; }, timeline.end_s,
      timeline.tick_hz, sink);
}

}  // namespace hazard_replay
