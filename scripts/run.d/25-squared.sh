#!/usr/bin/env bash
# The squared-quadratic device (ours): Fig. 3 with its clock on a sphere's raster line at n = 10,
# 100, 1000 with its VCD (traces/squared.gtkw), then every cos code at six exponents in both
# overflow modes, block level and the fast pin-level model.
set -euo pipefail
"$SHADING_BIN/squared_tb" --vcd traces/squared
"$SHADING_BIN/squared_tb" --sweep --no-vcd --mode saturate
"$SHADING_BIN/squared_tb" --sweep --no-vcd --mode wrap
"$SHADING_BIN/squared_tb" --sweep --no-vcd --abstraction fast
