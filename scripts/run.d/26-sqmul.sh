#!/usr/bin/env bash
# The square-and-multiply device (ours): Fig. 3 with its clock on a sphere's raster line at n = 10,
# 100, 1000 with its VCD (traces/sqmul.gtkw), then every cos code at six exponents in both overflow
# modes, block level and the fast pin-level model.
set -euo pipefail
"$SHADING_BIN/sqmul_tb" --vcd traces/sqmul
"$SHADING_BIN/sqmul_tb" --sweep --no-vcd --mode saturate
"$SHADING_BIN/sqmul_tb" --sweep --no-vcd --mode wrap
"$SHADING_BIN/sqmul_tb" --sweep --no-vcd --abstraction fast
