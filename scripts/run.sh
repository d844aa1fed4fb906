#!/usr/bin/env bash
# The main job: install what is missing (as root), configure, build in Release the programs the steps
# run (scripts/build.sh --studies with their targets: run.d/30 and 40 run study programs; the test
# suites are scripts/test.sh's), run every testbench and study, then print one summary table and
# how long each phase took. Each step is a script in scripts/run.d/,
# run in name order; each appends rows to out/summary.tsv:
#   bench <TAB> case <TAB> samples <TAB> mismatches <TAB> max_error <TAB> cycles_per_pixel <TAB> note
# VCDs go to traces/, CSV and PNG results to out/. Every testbench program takes the same options
# (testbenches/options/bench_options.h: --vcd, --no-vcd, --summary, --mode, --seed, --random N) and
# exits non-zero on any mismatch or unexpected SystemC report, which fails its step here.
# run.d/50-random.sh is a short random differential run per model; the long one (>= 10^7 per
# model) is scripts/random_long.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
start=$SECONDS
took() { echo "run.sh: $1 took $(( (SECONDS - $2) / 60 )) min $(( (SECONDS - $2) % 60 )) s"; }
scripts/setup.sh plots  # matplotlib for the figures of run.d/30, 40 and 70
took setup "$start"
# The programs the steps run (every $SHADING_BIN/<program> they name), not the test suites
# (scripts/test.sh builds and runs those).
t=$SECONDS
mapfile -t programs < <(grep -oh 'SHADING_BIN/[a-z0-9_]*' scripts/run.d/*.sh | sed 's|SHADING_BIN/||' | sort -u)
scripts/build.sh --studies "${programs[@]}"
took build "$t"
mkdir -p out traces
export SHADING_BIN="$PWD/build/bin" SHADING_OUT="$PWD/out" SHADING_SUMMARY="$PWD/out/summary.tsv"
printf 'bench\tcase\tsamples\tmismatches\tmax_error\tcycles_per_pixel\tnote\n' > "$SHADING_SUMMARY"
status=0
for step in scripts/run.d/*.sh; do
  echo "== ${step}"
  t=$SECONDS
  if ! bash "$step"; then
    echo "run: ${step} FAILED" >&2
    status=1
  fi
  took "$(basename "$step")" "$t"
done
took "setup, build and steps" "$start"
echo
echo "Summary (out/summary.tsv):"
column -t -s $'\t' "$SHADING_SUMMARY"
exit $status
