// gen_hazards: writes a random hazard field (docs/gen_hazards.md; docs/differences.md D30, D31).
// main reads the command line, picks the seed, builds the whole file in memory and writes it
// only when everything succeeded, so a bad argument never leaves a half-written file.
// Exit codes: see options.hpp (0 ok, 1 output not writable, 2 bad input).

#include <cstdio>
#include <string>
#include <vector>

#include "app_support.hpp"
#include "base/diagnostics.hpp"
#include "base/output_file.hpp"
#include "GenHazards_Info.hpp"
#include "generator.hpp"
#include "options.hpp"

namespace {

using namespace gen_hazards;

void print_error(const std::string& message) {
  std::fprintf(stderr, "gen_hazards: error: %s\n", message.c_str());
}

int write_stdout(const std::string& text) {
  const bool ok = std::fwrite(text.data(), 1, text.size(), stdout) == text.size() &&
                  std::fflush(stdout) == 0;
  if (!ok) print_error("cannot write to standard output");
  return ok ? kExitOk : kExitCannotWrite;
}

}  // namespace

int main(int argc, char** argv) {
  base::install_nonblocking_diagnostics();
  const std::vector<std::string> args(argv + 1, argv + argc);
  CommandLine cli = parse_command_line(args);
  if (cli.help) return write_stdout(help_text());
  if (cli.version) return write_stdout(version_text());
  for (const auto& error : cli.errors) print_error(error);
  if (!cli.errors.empty()) return kExitBadInput;

  cli.config.seed = cli.seed ? *cli.seed : app_support::operating_system_seed();
  const auto file = build_hazard_file(header_line(cli.recorded_args, cli.config.seed), cli.config);
  if (!file) {
    print_error(file.error);
    return kExitBadInput;
  }
  const std::string& text = *file.value;
  if (!cli.output_path) return write_stdout(text);
  if (auto written = base::write_output_file(*cli.output_path, text); !written) {
    print_error(written.error);
    return kExitCannotWrite;
  }
  return kExitOk;
}
