#!/usr/bin/env bash
# A short random differential run per model (a few seconds each): random stimuli streamed through
# the device against its golden model (testbenches/options/bench_options.h, --random). The specular
# devices get random reloads of n and k_s*I between pixels in both overflow modes; the interpolation paper's units
# random samples, interval lengths and degrees, back to back. Rows go to $SHADING_SUMMARY; the
# long run (>= 10^7 per model) is scripts/random_long.sh.
set -euo pipefail
seed=${SHADING_SEED:-1}
for gen in patent minimax rom_matched; do
  for mode in saturate wrap; do
    "$SHADING_BIN/ua60553_tb" --random 200000 --seed "$seed" --generator "$gen" --mode "$mode"
  done
done
for mode in saturate wrap; do
  "$SHADING_BIN/ua22802_tb" --random 200000 --seed "$seed" --mode "$mode"
  "$SHADING_BIN/squared_tb" --random 100000 --seed "$seed" --mode "$mode"
  "$SHADING_BIN/sqmul_tb" --random 100000 --seed "$seed" --mode "$mode"
done
"$SHADING_BIN/interp_coef_tb" --random 20000 --seed "$seed"
"$SHADING_BIN/interp_horner_tb" --random 50000 --seed "$seed"
"$SHADING_BIN/interp_fd_tb" --random 200000 --seed "$seed" --m 6
"$SHADING_BIN/interp_line_tb" --random 200000 --seed "$seed"
