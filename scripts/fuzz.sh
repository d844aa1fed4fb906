#!/usr/bin/env bash
# Coverage-guided fuzzing (docs/fuzzing.md): builds the fuzz targets of fuzz/ with Debian's clang
# and libFuzzer (-fsanitize=fuzzer,address,undefined) in build-fuzz/, then runs each for SECONDS
# (default 60) from its committed corpus, niced. New inputs go to build-fuzz/corpus/<target>/, never
# into the source tree; a crash is saved as build-fuzz/artifacts/<target>/crash-* and ends that
# target's run. Prints per target the executions, libFuzzer's coverage (cov: edges, ft: features)
# and the crashes; exits 1 if any target crashed.
#   scripts/fuzz.sh [SECONDS] [TARGET...]     e.g. scripts/fuzz.sh 600 fuzz_tlm
#   scripts/fuzz.sh --runs N [TARGET...]       stops each target after N executions instead (the
#                                              long runs: scripts/fuzz.sh --runs 1000000 fuzz_tlm)
# A crash becomes a regression test: copy it to fuzz/corpus/<target>/crash-<what> (ctest then runs
# it as fuzz.<target>.regress.<what>), fix the cause, commit both.
set -euo pipefail
cd "$(dirname "$0")/.."
limit=(-max_total_time="${1:-60}")
if [ "${1:-}" = --runs ]; then
  [[ "${2:-}" =~ ^[1-9][0-9]*$ ]] || { echo "fuzz: --runs needs a positive count" >&2; exit 2; }
  limit=(-runs="$2")
  shift 2
else
  shift || true
fi
all=(fuzz_obj fuzz_tlm fuzz_vcd fuzz_options)
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=("${all[@]}")
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
scripts/setup.sh fuzz
cxx=$(command -v clang++-14 || command -v clang++ || true)
if [ -z "$cxx" ]; then
  echo "fuzz: needs clang (Debian: clang-14 and libclang-rt-14-dev; scripts/setup.sh fuzz installs them)" >&2
  exit 2
fi
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
[ -f build-fuzz/CMakeCache.txt ] ||
  nice cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
       -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link" -DSHADING_SANITIZE=ON \
       -DSHADING_FUZZ=ON "${launcher[@]}" >/dev/null
nice cmake --build build-fuzz -j 2 --target "${targets[@]}"
# As scripts/test.sh --sanitize: QuickThreads' stack switches defeat ASan's fake stacks.
# leak_check_at_exit=0: libFuzzer checks for leaks after each input that grew the heap; the check at
# exit, reached from a SystemC target with the kernel's coroutine stacks still allocated, reported
# libFuzzer's own corpus buffers as leaked (an empty "crash" file, no input behind it).
export ASAN_OPTIONS=detect_leaks=1:leak_check_at_exit=0:detect_stack_use_after_return=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
printf '%-14s %12s %8s %8s %8s %s\n' target executions exec/s cov ft crashes
for t in "${targets[@]}"; do
  work=build-fuzz/corpus/$t art=build-fuzz/artifacts/$t/ log=build-fuzz/logs/$t.log
  mkdir -p "$work" "$art" build-fuzz/logs
  case $t in
    fuzz_obj) extra=(-max_len=8192) ;;
    fuzz_options) extra=(-max_len=4096 -close_fd_mask=1) ;;  # CLI11's --help text on stdout
    *) extra=(-max_len=4096) ;;
  esac
  rc=0
  nice build-fuzz/bin/"$t" "${limit[@]}" -timeout=30 -rss_limit_mb=4096 -print_final_stats=1 \
       -artifact_prefix="$art" "${extra[@]}" "$work" "fuzz/corpus/$t" >"$log" 2>&1 || rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  crashes=$(find "$art" -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
  printf '%-14s %12s %8s %8s %8s %s\n' "$t" "${execs:-?}" "${rate:-?}" "${cov:-?}" "${ft:-?}" "$crashes"
  if [ "$rc" -ne 0 ] || [ "$crashes" -ne 0 ]; then
    status=1
    echo "  $t: exit $rc; see $log and $art" >&2
  fi
done
exit $status
