#!/usr/bin/env bash
# Builds, outside this tree, the original programs docs/validation.md measures: MOOSDB and
# libMOOS from core-moos, pAntler/pLogger/pShare and MOOSGeodesy from the MOOS tree bundled with
# MOOS-IvP, and the MOOS-IvP programs of the Jake mission, the original uFldHazardSensor among
# them. Nothing of it is needed by CI or by the rest of the build.
#
#   bench/validation/build_original.sh --core-moos=SRC --moos-ivp=SRC --out=DIR [--jobs=N]
#
# --core-moos  a core-moos source tree (the public repository themoos/core-moos)
# --moos-ivp   a MOOS-IvP source tree at a revision that still holds ivp/src/uFldHazardSensor
#              (its MOOS_Dec3120 folder provides MOOSEssentials and MOOSGeodesy)
# --out        where the build folders go; the programs end in DIR/bin
# GUI programs are not built (no FLTK needed). With ccache on PATH, set
# CMAKE_CXX_COMPILER_LAUNCHER=ccache to reuse earlier compilations.
set -euo pipefail
core="" ivp="" out="" jobs=2
for arg in "$@"; do
  case "$arg" in
    --core-moos=*) core="$(cd "${arg#*=}" && pwd)" ;;
    --moos-ivp=*)  ivp="$(cd "${arg#*=}" && pwd)" ;;
    --out=*)       out="${arg#*=}" ;;
    --jobs=*)      jobs="${arg#*=}" ;;
    -h|--help)     sed -n '2,16p' "$0"; exit 0 ;;
    *) echo "build_original.sh: unknown argument '$arg' (see --help)" >&2; exit 2 ;;
  esac
done
[[ -f "$core/Core/libMOOS/CMakeLists.txt" ]] || { echo "build_original.sh: --core-moos is not a core-moos tree" >&2; exit 2; }
[[ -d "$ivp/ivp/src/uFldHazardSensor" ]] || { echo "build_original.sh: --moos-ivp has no ivp/src/uFldHazardSensor" >&2; exit 2; }
[[ -d "$ivp/MOOS_Dec3120/MOOSEssentials" ]] || { echo "build_original.sh: --moos-ivp has no MOOS_Dec3120/MOOSEssentials" >&2; exit 2; }
[[ -n "$out" ]] || { echo "build_original.sh: --out=DIR is required" >&2; exit 2; }
mkdir -p "$out"
out="$(cd "$out" && pwd)"
flags="-fPIC -O2 -w"   # third-party code: its warnings are not ours to fix
mkdir -p "$out/core" "$out/essentials" "$out/geodesy" "$out/ivp" "$out/bin"

(cd "$out/core" &&
 cmake -DENABLE_EXPORT=OFF -DUSE_ASYNC_COMMS=ON -DTIME_WARP_AGGLOMERATION_CONSTANT=0.4 \
   -DCMAKE_BUILD_TYPE=Release -DCMAKE_RUNTIME_OUTPUT_DIRECTORY="$out/bin" \
   -DCMAKE_CXX_FLAGS="$flags" "$core" >cmake.log &&
 nice make -j"$jobs" MOOS MOOSDB >make.log)
(cd "$out/essentials" &&
 cmake -DMOOS_DIR="$out/core" -DCMAKE_BUILD_TYPE=Release -DCMAKE_RUNTIME_OUTPUT_DIRECTORY="$out/bin" \
   -DCMAKE_CXX_FLAGS="$flags" "$ivp/MOOS_Dec3120/MOOSEssentials" >cmake.log &&
 nice make -j"$jobs" pAntler pLogger pShare >make.log)
(cd "$out/geodesy" &&
 cmake -DENABLE_EXPORT=ON -DCMAKE_EXPORT_NO_PACKAGE_REGISTRY=ON -DCMAKE_BUILD_TYPE=Release \
   -DCMAKE_CXX_FLAGS="$flags" "$ivp/MOOS_Dec3120/MOOSGeodesy" >cmake.log &&
 nice make -j"$jobs" >make.log)
(cd "$out/ivp" &&
 cmake -DMOOS_DIR="$out/core" -DMOOSGeodesy_DIR="$out/geodesy" -DIVP_BUILD_GUI_CODE=OFF \
   -DCMAKE_EXPORT_NO_PACKAGE_REGISTRY=ON -DIVP_LIB_DIRECTORY="$out/ivp/lib" \
   -DIVP_BIN_DIRECTORY="$out/bin" -DCMAKE_CXX_FLAGS="$flags -fpermissive" -DUSE_UTM=ON \
   "$ivp/ivp/src" >cmake.log)
for target in uFldHazardSensor nsplug uPokeDB uFldHazardMetric uFldHazardMgr pNodeReporter \
              uSimMarine pMarinePID uFldNodeBroker uFldShoreBroker pHostInfo uFldMessageHandler \
              uProcessWatch uFldNodeComms pHelmIvP; do
  echo "building $target" >&2
  (cd "$out/ivp" && nice make -j"$jobs" "$target" >>make.log)
done
echo "The programs are in $out/bin"
