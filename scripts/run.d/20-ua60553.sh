#!/usr/bin/env bash
# UA 60553: the Fig. 3 replay on a sphere's raster line with its VCD, then every cos code at
# five exponents in both overflow modes (no VCD: 164k pixels would make it huge).
set -euo pipefail
"$SHADING_BIN/ua60553_tb" --vcd traces/ua60553
"$SHADING_BIN/ua60553_tb" --sweep --no-vcd --mode saturate
"$SHADING_BIN/ua60553_tb" --sweep --no-vcd --mode wrap
