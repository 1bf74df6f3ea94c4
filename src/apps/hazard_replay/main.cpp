// hazard_replay: the uFldHazardSensor engine driven offline by an .alog of inputs.
#include <iostream>

#include "HazardReplay_Info.hpp"
#include "base/diagnostics.hpp"
#include "base/output_file.hpp"
#include "base/version.hpp"
#include "args.hpp"
#include "replay.hpp"

namespace {

/// The replay written to --output (base/output_file.hpp): a regular file replaced only when the
/// replay succeeded (else it stays as it was), a device or FIFO written through.
int replay_to_file(const hazard_replay::Options& options) {
  auto file = base::OutputFile::open(*options.output_path, base::OutputMode::kReplace);
  if (!file) {
    std::cerr << "hazard_replay: --output: " << file.error << "\n";
    return 1;
  }
  base::OutputFileBuffer buffer(*file.value);
  std::ostream out(&buffer);
  const int status = hazard_replay::run(options, out, std::cerr);
  if (status != 0) return status;
  if (auto committed = file.value->commit(); !committed) {
    std::cerr << "hazard_replay: --output: " << committed.error << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // Events can be many (one per detection): buffer standard error instead of one write each.
  std::ios::sync_with_stdio(false);
  std::cerr.unsetf(std::ios::unitbuf);
  // Warnings and events are diagnostics: a standard error nobody reads must not stop the replay
  // (after sync_with_stdio, which would replace the routing).
  base::install_nonblocking_diagnostics();
  const std::vector<std::string> args(argv + 1, argv + argc);
  const hazard_replay::ParsedArgs parsed = hazard_replay::parse_args(args);
  if (!parsed.options) {
    std::cerr << "hazard_replay: " << parsed.error << "\n" << hazard_replay::usage_line() << "\n";
    return 2;
  }
  const hazard_replay::Options& options = *parsed.options;
  if (options.help) {
    std::cout << hazard_replay::help_text();
    return 0;
  }
  if (options.version) {
    std::cout << base::version_line("hazard_replay");
    return 0;
  }
  if (!options.output_path) return hazard_replay::run(options, std::cout, std::cerr);
  return replay_to_file(options);
}
