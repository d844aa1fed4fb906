#!/usr/bin/env bash
# Build, then run the whole test suite through ctest (each GoogleTest test in its own process), and
# print how long the build and the tests took.
# Extra arguments go to ctest, e.g. scripts/test.sh -R UA60553Device
# scripts/test.sh [--sanitize] [--studies] [ctest args]:
#   --sanitize  the same suite (bench short runs included) built in build-asan/ with AddressSanitizer
#               (leak checking on) and UndefinedBehaviorSanitizer; any finding fails its test; the RTL
#               is not verilated there (SHADING_VERILATE=OFF: Verilator's models are not our code, the
#               normal run co-simulates them), its tests report skipped;
#   --studies   the studies (studies/, SHADING_BUILD_STUDIES=ON) built and tested too; without it the
#               build is the model, its tests and the programs (the option is set either way, so an
#               existing build follows it).
set -euo pipefail
cd "$(dirname "$0")/.."
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
start=$SECONDS
took() { echo "test.sh: $1 took $(( (SECONDS - $2) / 60 )) min $(( (SECONDS - $2) % 60 )) s"; }
sanitize=0
studies=OFF
while [ $# -gt 0 ]; do
  case "$1" in
    --sanitize) sanitize=1 ;;
    --studies) studies=ON ;;
    *) break ;;
  esac
  shift
done
# --no-tests=error: a filter or a configuration that registers nothing fails instead of passing.
if [ "$sanitize" = 0 ]; then
  if [ "$studies" = ON ]; then scripts/build.sh --studies; else scripts/build.sh; fi
  took build "$start"
  t=$SECONDS
  rc=0
  ctest --test-dir build --output-on-failure --no-tests=error -j "$(nproc)" "$@" || rc=$?
  took tests "$t"; took "build and tests" "$start"
  exit "$rc"
fi
scripts/setup.sh
launcher=()
if command -v ninja >/dev/null; then launcher=(-G Ninja); fi  # as scripts/build.sh
if command -v ccache >/dev/null; then launcher+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
# -O0 -g1: stacks with file and line (-g1 keeps the line tables only: full debug information made
# one test's instrumented compile 38 % slower); -O0 took 16 % less compile CPU than -Og and the
# suite 40 s longer, 53 s less in all (docs/tests.md); asserts stay on.
if [ ! -f build-asan/CMakeCache.txt ]; then
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O0 -g1" \
        -DSHADING_SANITIZE=ON -DSHADING_VERILATE=OFF -DSHADING_BUILD_STUDIES="$studies" "${launcher[@]}"
elif ! grep -qx "SHADING_BUILD_STUDIES:BOOL=$studies" build-asan/CMakeCache.txt ||
     ! grep -qx "SHADING_VERILATE:BOOL=OFF" build-asan/CMakeCache.txt; then
  cmake -S . -B build-asan -DSHADING_VERILATE=OFF -DSHADING_BUILD_STUDIES="$studies"
fi
cmake --build build-asan -j "$(nproc)"
took "sanitizer build" "$start"
# detect_stack_use_after_return=0: Debian's libsystemc switches between thread stacks with
# QuickThreads (qt_block), which ASan's fake stacks cannot follow; it would report false errors.
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:abort_on_error=0:detect_stack_use_after_return=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# package.install_and_consume left out: it installs this build and links a consumer project built
# without -fsanitize against it (undefined __asan_* symbols); it checks the packaging, which the
# normal run covers, not our code's memory or arithmetic.
t=$SECONDS
rc=0
ctest --test-dir build-asan --output-on-failure --no-tests=error -j "$(nproc)" \
      -E '^package\.install_and_consume$' "$@" || rc=$?
took "sanitizer tests" "$t"; took "sanitizer build and tests" "$start"
exit "$rc"
