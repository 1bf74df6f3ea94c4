#include "replay.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <ostream>

#include "app_support.hpp"
#include "hazard/config.hpp"
#include "hazard/driver.hpp"
#include "hazard/engine.hpp"
#include "base/file.hpp"
#include "base/text.hpp"
#include "moos/alog.hpp"
#include "moos/mission.hpp"
#include "score.hpp"

namespace hazard_replay {

namespace {

namespace fs = std::filesystem;
using base::fix;

// The bytes of the input log and its entries, which are views into them.
struct Input {
  base::WholeFile file;               // (moving it keeps the views valid)
  std::vector<hazard::Mail> entries;  // in time order
  double logstart_s = 0.0;
};

// Bytes of an input line, about (a NODE_REPORT line is about 110): a first guess of the entries.
constexpr std::size_t kTypicalLineBytes = 96;

std::optional<Input> read_input(const std::string& path, std::string& problem,
                                std::ostream& err) {
  std::optional<base::WholeFile> file = base::WholeFile::open(path, kMaxInputLogBytes, problem);
  if (!file) return std::nullopt;
  Input input{std::move(*file), {}, 0.0};
  const std::string_view all = input.file.text();
  input.entries.reserve(all.size() / kTypicalLineBytes);
  int number = 0;
  // Lines as std::getline gives them: split at '\n', a last line without one still counts.
  for (std::size_t start = 0; start < all.size();) {
    const std::size_t newline = all.find('\n', start);
    const std::size_t end = newline == std::string_view::npos ? all.size() : newline;
    const std::string_view line = all.substr(start, end - start);
    start = end + 1;
    ++number;
    const moos::AlogViewParse p = moos::parse_alog_view(line);
    if (p.kind == moos::AlogLineKind::kEntry) {
      input.entries.push_back(hazard::Mail{p.entry.variable, p.entry.value, p.entry.time_s});
    } else if (p.kind == moos::AlogLineKind::kHeader) {
      if (const auto logstart = moos::alog_logstart(line)) input.logstart_s = *logstart;
    } else if (p.kind == moos::AlogLineKind::kMalformed) {
      err << path << ":" << number << ": warning: " << p.error << "; line skipped\n";
    }
  }
  const auto earlier = [](const hazard::Mail& a, const hazard::Mail& b) {
    return a.time_s < b.time_s;
  };
  // A logger writes in time order: sorting (moving every entry) only when it did not.
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
    for (const auto& w : o.config_warnings) err_ << when << "config warning: " << w << "\n";
    for (const auto& w : o.run_warnings) err_ << when << "run warning: " << w << "\n";
    for (const auto& w : o.retracted_run_warnings) err_ << when << "resolved: " << w << "\n";
    for (const auto& e : o.events) err_ << when << "event: " << e << "\n";
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
};

// A guard against a mistyped --until (1e12 s at 4 Hz would never finish).
constexpr double kMaxIterations = 1e8;

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
  const auto input = read_input(options.input_path, problem, err);
  if (!input) {
    err << "hazard_replay: cannot read input log '" << options.input_path << "': " << problem
        << "\n";
    return 1;
  }

  // Hazard files are named relative to the mission file.
  // LatOrigin/LongOrigin place LAT/LON-only node reports and lat/lon hazard lines (geodesy).
  hazard::Engine built = app_support::make_sensor_engine(
      block->lines, mission->directory(), app_support::mission_origin(*mission),
      options.seeds ? options.seeds->first : options.seed, app_support::operating_system_seed);
  const double tick_hz = built.config().app_tick_hz;
  const auto& mail = input->entries;
  const double start_s = mail.empty() ? 0.0 : mail.front().time_s;
  const double end_s = options.until_s.value_or(mail.empty() ? start_s : mail.back().time_s);
  if ((end_s - start_s) * tick_hz > kMaxIterations) {
    err << "hazard_replay: " << fix((end_s - start_s) * tick_hz, 0)
        << " iterations from the first input to the end; more than " << fix(kMaxIterations, 0)
        << " is refused (check --until and AppTick)\n";
    return 1;
  }
  const Timeline timeline{&mail, start_s, end_s, tick_hz};
  if (options.seeds) {
    std::optional<double> score;
    if (options.score) {
      // The recorded report does not depend on the dice: graded once, the same on every line.
      const RecordedScore graded = score_recorded_reports(*mission, mail, end_s, err);
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

  hazard::Driver driver(std::move(built));
  const hazard::SeedChoice& seed = driver.engine().seed();
  err << "hazard_replay: seed " << seed.seed << " (" << hazard::seed_source_name(seed.source)
      << "), AppTick " << base::fmt(tick_hz) << " Hz\n";
  out << moos::alog_header(fs::path(options.input_path).filename().string(), input->logstart_s);
  if (mail.empty()) {
    err << "hazard_replay: '" << options.input_path << "' holds no input lines\n";
    return 0;
  }
  Writer writer(out, err, options.app_name);
  replay(driver, timeline, [&](const hazard::TimedOutputs& t) { writer.write(t); });
  writer.flush();
  out.flush();
  return 0;
}

void replay(hazard::Driver& driver, const Timeline& timeline,
            const std::function<void(const hazard::TimedOutputs&)>& sink) {
  const std::vector<hazard::Mail>& mail = *timeline.mail;
  if (mail.empty()) return;
  sink(driver.start(timeline.start_s));
  std::size_t next = 0;
  auto deliver_until = [&](double t) {
    for (; next < mail.size() && mail[next].time_s <= t; ++next) {
      sink(driver.deliver(mail[next]));
    }
  };
  for (long k = 0;; ++k) {
    const double now_s = timeline.start_s + static_cast<double>(k) / timeline.tick_hz;
    if (now_s > timeline.end_s) break;
    deliver_until(now_s);
    sink(driver.step(now_s));
  }
  deliver_until(timeline.end_s);
}

}  // namespace hazard_replay
