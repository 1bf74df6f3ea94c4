// hazard_study's run. Contract in study.hpp.

#include "study.hpp"

#include <ostream>

#include "base/output_file.hpp"
#include "base/text.hpp"
#include "field.hpp"
#include "field_cache.hpp"
#include "mission_plan.hpp"
#include "mission_run.hpp"
#include "study_output.hpp"

namespace hazard_study {

namespace {

/// The warnings of a setting's first mission: those about a --set line are the error (returned);
/// the others go to `err` once, for the first setting (they are the mission's own).
std::string sort_warnings(const MissionResult& r, const Setting& setting, bool first_setting,
                          std::ostream& err) {
  const std::string set_place = std::string(kSetFile) + ":";
  for (const std::string& w : r.config_warnings) {
    const auto colon = w.find(": ");
    const std::string text = colon == std::string::npos ? w : w.substr(colon + 2);
    const auto at = text.find(set_place);
    if (at != std::string::npos) {
      const auto index = base::parse_unsigned(
          text.substr(at + set_place.size(), text.find(':', at + set_place.size()) - at - set_place.size()));
      const auto end = text.find(": ", at);
      const std::string why = end == std::string::npos ? text : text.substr(end + 2);
      const std::string typed = index && *index >= 1 && *index <= setting.assignments.size()
                                    ? setting.assignments[*index - 1].as_typed
                                    : std::string("?");
      return "--set '" + base::excerpt(typed) + "': " + w.substr(0, colon) + ": " + why;
    }
    if (first_setting) err << "hazard_study: warning: " << w << "\n";
  }
  return {};
}

int write_alog(const std::string& path, const std::string& alog, std::ostream& err) {
  const base::Result<void> written = base::write_output_file(path, alog);
  if (!written) err << "hazard_study: --alog: " << written.error << "\n";
  return written ? 0 : 1;
}

/// The plan of one field: a generated field's name and text go to the plan and the cache;
/// "" or the generator's error.
std::string start_field(const Options& options, std::uint64_t field_seed, MissionPlan& plan,
                        FieldCache& fields) {
  if (!options.field) {
    fields.start_field(std::nullopt);
    return {};
  }
  FieldText field = generate_field(*options.field, field_seed);
  if (!field.text) return field.error;
  plan.field_file = field_name(field_seed);
  fields.start_field(std::make_pair(*plan.field_file, std::move(*field.text)));
  return {};
}

}  // namespace

int run(const Options& options, std::ostream& out, std::ostream& err) {
  std::string error;
  auto plan = load_plan(options, error);
  if (!plan) {
    err << "hazard_study: " << error << "\n";
    return 1;
  }
  if (error = check_assignments(*plan, options.settings); !error.empty()) {
    err << "hazard_study: " << error << "\n";
    return 2;
  }
  FieldCache fields;
  const RunOptions run_options{options.deploy_s, options.max_time_s, &fields};
  std::string alog;
  std::vector<SettingScores> summary;
  for (const Setting& setting : options.settings)
    summary.push_back(SettingScores{setting.label, {}, 0, 0});
  // Field seeds outermost: each field is generated and loaded once, for every setting and seed.
  for (std::uint64_t field_seed = options.first_field_seed;; ++field_seed) {
    if (error = start_field(options, field_seed, *plan, fields); !error.empty()) {
      err << "hazard_study: " << error << "\n";
      return 2;
    }
    for (std::size_t s = 0; s < options.settings.size(); ++s) {
      const Setting& setting = options.settings[s];
      for (std::uint64_t seed = options.first_seed;; ++seed) {
        MissionResult r =
            run_mission(*plan, setting, seed, run_options, options.alog_path ? &alog : nullptr);
        if (options.field) r.field_seed = field_seed;
        if (seed == options.first_seed && field_seed == options.first_field_seed) {
          if (error = sort_warnings(r, setting, s == 0, err); !error.empty()) {
            err << "hazard_study: " << error << "\n";
            return 2;
          }
        }
        if (options.summary) {
          ++summary[s].missions;
          if (r.score) summary[s].scores.push_back(*r.score);
          if (r.end == "max_time") ++summary[s].max_time;
        } else {
          // One line at a time: a study stopped midway (a cluster's time limit) keeps its lines.
          out << json_line(r) << std::flush;
        }
        if (seed == options.last_seed) break;
      }
    }
    if (field_seed == options.last_field_seed) break;
  }
  if (options.summary) out << summary_table(summary);
  out.flush();
  if (!out) {
    err << "hazard_study: cannot write the standard output\n";
    return 1;
  }
  if (options.alog_path) return write_alog(*options.alog_path, alog, err);
  return 0;
}

}  // namespace hazard_study
