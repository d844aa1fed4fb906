#!/usr/bin/env bash
# The long random differential run: >= 10^7 random stimuli per model through the SystemC device
# against its golden model (the --random mode of every testbench program), in parallel processes
# (default 2), each a chunk with its own seed. Not run by CI: it takes tens of minutes on 2 cores.
# Writes out/random_long.tsv (model, samples, mismatches, seconds spent simulating summed over the chunks,
# samples per second of one process; a chunk of 10^5 stimuli or more is split over the bench's own
# processes, one per core, and counts its wall time) and exits non-zero if any chunk failed.
#
#   scripts/random_long.sh                      10^7 per model, build/bin, 2 processes
#   N=1000000 JOBS=4 SHADING_BIN=build-x/bin scripts/random_long.sh
#   MODELS='interp_(fd|line)' scripts/random_long.sh   only the models whose name matches (grep -E)
set -euo pipefail
cd "$(dirname "$0")/.."
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
bin=${SHADING_BIN:-$PWD/build/bin}
n=${N:-10000000}
jobs=${JOBS:-2}
chunks=4  # per model: chunk k runs n/4 stimuli with seed 1000 + k
per=$(( (n + chunks - 1) / chunks ))
mkdir -p out
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# model <TAB> program and options (a specular model's chunks alternate the two overflow modes).
{
  for gen in patent minimax rom_matched; do
    printf 'ua60553_%s\tua60553_tb --generator %s --mode MODE\n' "$gen" "$gen"
  done
  printf 'ua22802\tua22802_tb --mode MODE\n'
  printf 'squared\tsquared_tb --mode MODE\n'
  printf 'squared_fast\tsquared_tb --abstraction fast --mode MODE\n'
  printf 'sqmul\tsqmul_tb --mode MODE\n'
  printf 'sqmul_fast\tsqmul_tb --abstraction fast --mode MODE\n'
  printf 'interp_fd_m6\tinterp_fd_tb --m 6\n'
  printf 'interp_line\tinterp_line_tb --case CASE --div3 DIV\n'  # chunks: both sample sets x both /3
  printf 'interp_horner\tinterp_horner_tb\n'
  printf 'interp_coef\tinterp_coef_tb\n'  # the slowest per sample: five units, every input changing
} | grep -E "^(${MODELS:-.*})"$'\t' > "$work/models"

: > "$work/jobs"
while IFS=$'\t' read -r model cmd; do
  for k in $(seq 0 $((chunks - 1))); do
    mode=$([ $((k % 2)) -eq 0 ] && echo saturate || echo wrap)
    div=$([ "$k" -lt 2 ] && echo shift-add || echo exact)
    c=${cmd/MODE/$mode}; c=${c/CASE/$((k % 2 + 1))}; c=${c/DIV/$div}
    printf '%s\t%s\t%s\n' "$model" "$k" "$c --random $per --seed $((1000 + k))" >> "$work/jobs"
  done
done < "$work/models"

# Each job: its program's last lines in $work/<model>.<k>.log, its exit status in .rc.
run_job() {
  local model=$1 k=$2 cmd=$3
  # shellcheck disable=SC2086
  nice -n 5 "$bin"/$cmd --summary "" > "$work/$model.$k.log" 2>&1
  echo $? > "$work/$model.$k.rc"
  echo "random_long: $model chunk $k: $(grep ' random (' "$work/$model.$k.log" | tail -1)"
}
export -f run_job
export bin work
start=$(date +%s)
tr '\t' '\n' < "$work/jobs" | xargs -d '\n' -n 3 -P "$jobs" bash -c 'run_job "$0" "$1" "$2"' || true

status=0
printf 'model\tsamples\tmismatches\tsim_seconds\tsamples_per_second\tchunks_failed\n' > out/random_long.tsv
while IFS=$'\t' read -r model cmd; do
  samples=0; mism=0; secs=0; failed=0
  for k in $(seq 0 $((chunks - 1))); do
    line=$(grep ' random (' "$work/$model.$k.log" | tail -1 || true)
    # "<bench> random (<case>): S samples, M mismatches, R <unit>/s (W s simulated, seed X)", or with
    # the chunk split over processes "..., P processes, R <unit>/s summed over the processes, W s wall"
    s=$(sed -E 's/.*: ([0-9]+) samples.*/\1/' <<<"$line"); m=$(sed -E 's/.* ([0-9]+) mismatches.*/\1/' <<<"$line")
    # one process: "(W s simulated, seed X)"; a chunk split over processes (--jobs): ", W s wall"
    w=$(sed -nE 's/.*\(([0-9.]+) s simulated.*/\1/p; s/.*, ([0-9.]+) s wall.*/\1/p' <<<"$line")
    if [ -z "$line" ] || [ "$(cat "$work/$model.$k.rc")" != 0 ]; then failed=$((failed + 1)); fi
    [ -n "$line" ] && samples=$((samples + s)) && mism=$((mism + m)) && secs=$(echo "$secs + $w" | bc -l)
  done
  rate=$(echo "if ($secs > 0) $samples / $secs else 0" | bc -l)
  printf '%s\t%d\t%d\t%.1f\t%.0f\t%d\n' "$model" "$samples" "$mism" "$secs" "$rate" "$failed" >> out/random_long.tsv
  [ "$failed" -eq 0 ] && [ "$mism" -eq 0 ] || status=1
done < "$work/models"
echo "random_long: $(( $(date +%s) - start )) s wall, $jobs processes"
column -t -s $'\t' out/random_long.tsv
exit $status
