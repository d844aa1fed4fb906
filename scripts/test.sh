#!/usr/bin/env bash
# Build, then run the whole test suite through ctest (each GoogleTest test in its own process).
# Extra arguments go to ctest, e.g. scripts/test.sh -R UA60553Device
set -euo pipefail
cd "$(dirname "$0")/.."
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)" "$@"
