#!/usr/bin/env bash
# HazardSensor build driver. Installs what is missing, builds, and runs the job you name.
#
#   ./build.sh demo [WARP] [--seed=N] [--moosdb=lite|real]
#                       install dependencies, build the programs, run the Jake mission headless;
#                       ends with the score table and the picture's path (missions/jake/launch.sh)
#   ./build.sh test     install dependencies, then every test phase CI runs, in order (each
#                       builds its own preset): release (the suite, warnings as errors), perf
#                       (the instruction-count gate on the release build, bench/perf/gate.py),
#                       sanitize (the whole suite again under ASan + UBSan, halting), tsan (the
#                       threaded test programs and the programs they start under ThreadSanitizer,
#                       halting), fuzz (each
#                       fuzz target for HAZARD_FUZZ_SECONDS seconds on its seed corpus, default 10,
#                       HAZARD_JOBS at a time)
#                       HAZARD_TEST_PHASES="release sanitize" runs only the phases named
#   ./build.sh test-release | test-perf | test-sanitize | test-tsan | test-fuzz   one phase
#   ./build.sh build    install dependencies and build only
#   ./build.sh install [PREFIX]
#                       build, then install the programs, man pages, engine libraries and
#                       headers, CMake and pkg-config files, docs and demo missions under PREFIX
#                       (default ~/.local; no root needed)
#   ./build.sh package  build, then the Debian package build/package/hazardsensor_<version>_<arch>.deb
#   ./build.sh deps     install dependencies only
#   ./build.sh packages print the Debian packages it needs, one a line (for .ci/run)
#
# build, demo and test also link every program into bin/ at the top of the tree (put it on PATH).
#
# Dependencies are Debian packages (apt-get, as root or through sudo) and, for the
# wire-compatibility tests and pWebViewer's browser tests only, pymoos2 and playwright from PyPI
# in a virtual environment under build/.
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cd "$HERE"

PRESET="${HAZARD_PRESET:-release}"
BUILD_DIR="$HERE/build/$PRESET"
PYENV_DIR="$HERE/build/pyenv"
JOBS="${HAZARD_JOBS:-$(nproc 2>/dev/null || echo 2)}"

DEBIAN_PACKAGES=(
  cmake ninja-build g++ pkg-config
  libgeographiclib-dev libglm-dev libgtest-dev libbenchmark-dev
  libmimalloc-dev        # the programs' allocator (cmake/allocator.cmake)
  python3 python3-venv
  librsvg2-bin
  libboost1.74-dev chromium   # Boost.Beast and Asio (header-only): pWebViewer's HTTP server
  clang libclang-rt-14-dev
  help2man dpkg-dev file lintian
  valgrind               # the instruction-count gate (./build.sh test-perf)
  jq parallel            # docs/performance.md's study examples, run by the docs test
)
# playwright drives Debian's chromium in pWebViewer's browser tests (no browser download).
PYPI_PACKAGES=(pymoos2==0.1.0 playwright==1.65.2)
# What the demo mission runs (missions/jake/launch.sh finds them under $BUILD_DIR/src/apps).
DEMO_TARGETS=(moosdb-lite uFldHazardSensor uFldHazardMetric pHazardMgr uSimSurveyVehicle pLogLite
              moos-cli gen_hazards hazard_replay pWebViewer)

say() { printf '\033[1m[build.sh]\033[0m %s\n' "$*" >&2; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"
  elif command -v sudo >/dev/null 2>&1; then sudo "$@"
  else say "need root to run: $*"; return 1
  fi
}

missing_debian_packages() {
  local pkg
  for pkg in "${DEBIAN_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || echo "$pkg"
  done
}

install_debian_packages() {
  local missing
  missing="$(missing_debian_packages | tr '\n' ' ')"
  if [ -z "${missing// /}" ]; then return 0; fi
  say "installing Debian packages: $missing"
  as_root apt-get update -q
  # shellcheck disable=SC2086
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $missing
}

install_python_packages() {
  if [ -x "$PYENV_DIR/bin/python" ] && "$PYENV_DIR/bin/python" -c 'import pymoos2, playwright' 2>/dev/null; then
    return 0
  fi
  say "installing ${PYPI_PACKAGES[*]} into $PYENV_DIR"
  python3 -m venv "$PYENV_DIR"
  "$PYENV_DIR/bin/python" -m pip install -q --disable-pip-version-check "${PYPI_PACKAGES[@]}"
}

install_dependencies() {
  install_debian_packages
  install_python_packages
}

configure() {
  say "configuring ($PRESET) in $BUILD_DIR"
  cmake --preset "$PRESET" -DHAZARD_PYTHON="$PYENV_DIR/bin/python" >/dev/null
}

configure_and_build() {
  configure
  say "building with $JOBS jobs"
  cmake --build --preset "$PRESET" -j "$JOBS" "$@"
  if [ "$PRESET" = release ]; then link_programs_into_bin; fi
}

# bin/ at the top of the tree: a link to every program built (the build's programs.txt lists
# "name path" per program), as MOOS-IvP trees have, so that pAntler finds them by name.
link_programs_into_bin() {
  local name path
  mkdir -p "$HERE/bin"
  find "$HERE/bin" -maxdepth 1 -type l -delete
  while read -r name path; do
    [ -x "$path" ] || continue
    case "$path" in
      "$HERE"/*) ln -s "../${path#"$HERE"/}" "$HERE/bin/$name" ;;
      *) ln -s "$path" "$HERE/bin/$name" ;;
    esac
  done <"$BUILD_DIR/programs.txt"
  say "the programs are in $HERE/bin; to run them by name: export PATH=\"$HERE/bin:\$PATH\""
}

run_install() {
  local prefix="${1:-$HOME/.local}"
  install_debian_packages
  configure_and_build
  say "installing into $prefix"
  cmake --install "$BUILD_DIR" --prefix "$prefix"
  say "installed; to run the programs by name: export PATH=\"$prefix/bin:\$PATH\""
  say "the demo: $prefix/share/hazardsensor/missions/jake/launch.sh"
}

run_package() {
  install_debian_packages
  configure_and_build
  say "building the Debian package in $HERE/build/package"
  (cd "$BUILD_DIR" && cpack -B "$HERE/build/package") >&2
  local deb
  deb="$(ls -t "$HERE"/build/package/hazardsensor_*.deb | head -n 1)"
  say "package: $deb (install it with: sudo apt install $deb)"
  printf '%s\n' "$deb"
}

run_demo() {
  install_debian_packages
  configure_and_build --target "${DEMO_TARGETS[@]}"
  exec "$HERE/missions/jake/launch.sh" --bin-dir="$BUILD_DIR/src/apps" "$@"
}

run_tests() {
  say "running the test suite"
  ctest --preset "$PRESET" -j "$JOBS"
}

# The test phases of `./build.sh test` (docs/robustness.md, "Sanitizer CI"). Each selects its
# own preset and build folder, so a phase never reuses another's objects.
TEST_PHASES_ALL=(release perf sanitize tsan fuzz)
FUZZ_SECONDS="${HAZARD_FUZZ_SECONDS:-10}"

use_preset() {
  PRESET="$1"
  BUILD_DIR="$HERE/build/$PRESET"
}

test_phase_release() {
  use_preset release
  configure_and_build
  run_tests
}

# Counts the instructions of bench/perf's fixed workloads under cachegrind and fails when one
# grew beyond the tolerance of bench/perf/baseline.json (docs/performance.md).
test_phase_perf() {
  use_preset release
  configure_and_build --target perf_workloads
  python3 "$HERE/bench/perf/gate.py" --program="$BUILD_DIR/bench/perf/perf_workloads" --jobs="$JOBS"
}

test_phase_sanitize() {
  use_preset sanitize
  configure_and_build
  run_tests
}

# The tsan preset builds only the threaded_tests target and runs the tests labelled `threads`.
test_phase_tsan() {
  use_preset tsan
  configure_and_build
  run_tests
}

# Runs one fuzz target for FUZZ_SECONDS on its seed corpus (fuzz/corpus/<target>); inputs the
# run finds go to build/fuzz/corpus/<target>, a crashing input to build/fuzz/artifacts/. Any
# crash, leak, sanitizer report or input slower than 10 s fails it.
fuzz_target() {
  local program="$1" artifacts="$2" target="${1##*/fuzz_}"
  mkdir -p "$BUILD_DIR/corpus/$target"
  "$program" -max_total_time="$FUZZ_SECONDS" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$artifacts/$target-" \
    "$BUILD_DIR/corpus/$target" "$HERE/fuzz/corpus/$target" >"$BUILD_DIR/$target.log" 2>&1
}

# Every fuzz target, JOBS at a time (each is one process on one core).
test_phase_fuzz() {
  use_preset fuzz
  configure_and_build
  local artifacts="$BUILD_DIR/artifacts" failed=() program target
  local -A pids=()
  mkdir -p "$artifacts"
  for program in "$BUILD_DIR"/fuzz/fuzz_*; do
    target="${program##*/fuzz_}"
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n || true; done
    say "fuzzing $target for ${FUZZ_SECONDS}s"
    fuzz_target "$program" "$artifacts" &
    pids[$target]=$!
  done
  for target in "${!pids[@]}"; do
    if ! wait "${pids[$target]}"; then
      say "fuzz target $target failed (log: $BUILD_DIR/$target.log)"
      tail -n 40 "$BUILD_DIR/$target.log" >&2
      failed+=("$target")
    fi
  done
  if [ "${#failed[@]}" -gt 0 ]; then
    say "fuzz targets with findings: ${failed[*]} (inputs in $artifacts)"
    return 1
  fi
}

run_test_phases() {
  local phases phase
  read -r -a phases <<<"${HAZARD_TEST_PHASES:-${TEST_PHASES_ALL[*]}}"
  for phase in "${phases[@]}"; do
    case "$phase" in
      release|perf|sanitize|tsan|fuzz) ;;
      *) say "unknown test phase '$phase' (phases: ${TEST_PHASES_ALL[*]})"; return 2 ;;
    esac
  done
  for phase in "${phases[@]}"; do
    say "test phase: $phase"
    "test_phase_$phase"
  done
}

case "${1:-build}" in
  demo)  shift; run_demo "$@" ;;
  deps)  install_dependencies ;;
  packages) printf '%s\n' "${DEBIAN_PACKAGES[@]}" ;;
  build) install_dependencies; configure_and_build ;;
  install) shift; run_install "$@" ;;
  package) run_package ;;
  test)  install_dependencies; run_test_phases ;;
  test-release|test-perf|test-sanitize|test-tsan|test-fuzz)
         install_dependencies; HAZARD_TEST_PHASES="${1#test-}" run_test_phases ;;
  -h|--help|help) sed -n '2,30p' "$0" ;;
  *) say "unknown job '$1' (try: demo, test, test-release, test-perf, test-sanitize, test-tsan, test-fuzz, build, install, package, deps, packages)"; exit 2 ;;
esac
