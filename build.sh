#!/usr/bin/env bash
# HazardSensor build driver. Installs what is missing, builds, and runs the job you name.
#
#   ./build.sh demo [WARP] [--seed=N] [--moosdb=lite|real]
#                       install dependencies, build the programs, run the Jake mission headless;
#                       ends with the score table and the picture's path (missions/jake/launch.sh)
#   ./build.sh test     install dependencies, build (warnings as errors), run every test
#   ./build.sh build    install dependencies and build only
#   ./build.sh deps     install dependencies only
#   ./build.sh packages print the Debian packages it needs, one a line (for .ci/run)
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
  python3 python3-venv
  librsvg2-bin
  libcpp-httplib-dev chromium
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

case "${1:-build}" in
  demo)  shift; run_demo "$@" ;;
  deps)  install_dependencies ;;
  packages) printf '%s\n' "${DEBIAN_PACKAGES[@]}" ;;
  build) install_dependencies; configure_and_build ;;
  test)  install_dependencies; configure_and_build; run_tests ;;
  -h|--help|help) sed -n '2,12p' "$0" ;;
  *) say "unknown job '$1' (try: demo, test, build, deps, packages)"; exit 2 ;;
esac
