#!/usr/bin/env bash
# Configure (Release) and build into build/. A second run reuses the build.
# scripts/build.sh: the model, its tests and the programs (SHADING_BUILD_STUDIES=OFF).
# scripts/build.sh --studies: the studies too (studies/, SHADING_BUILD_STUDIES=ON), what scripts/run.sh
# runs. Either sets the option on an existing build/ as well, re-configuring only when it changes.
# scripts/build.sh [--studies] TARGET...: only those targets (and what they need), as scripts/run.sh
# builds the programs its steps run and not the test suites.
set -euo pipefail
cd "$(dirname "$0")/.."
studies=OFF
targets=()
for arg in "$@"; do
  case "$arg" in
    --studies) studies=ON ;;
    -*) echo "usage: scripts/build.sh [--studies] [TARGET...]" >&2; exit 2 ;;
    *) targets+=(--target "$arg") ;;
  esac
done
scripts/setup.sh
launcher=()
# Ninja rather than make: the default build took 548 s from an empty folder against 602 s with make
# (1 057 against 1 152 CPU s for the same compiles; docs/tests.md). An existing build/ keeps the
# generator it has.
if command -v ninja >/dev/null; then launcher=(-G Ninja); fi
if command -v ccache >/dev/null; then launcher+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
if [ ! -f build/CMakeCache.txt ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSHADING_BUILD_STUDIES="$studies" "${launcher[@]}"
elif ! grep -qx "SHADING_BUILD_STUDIES:BOOL=$studies" build/CMakeCache.txt; then
  cmake -S . -B build -DSHADING_BUILD_STUDIES="$studies"
fi
cmake --build build -j "$(nproc)" "${targets[@]}"
