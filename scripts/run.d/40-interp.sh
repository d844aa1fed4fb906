#!/usr/bin/env bash
# The interpolation paper's interpolation hardware: the coefficient units, the iterative Horner unit, the
# forward-difference evaluator and the raster-line interpolator joining them, each over one raster
# line (VCDs in traces/, views traces/*.gtkw),
# the per-pixel and /3 CSVs and their plots in $SHADING_OUT. Summary rows go to $SHADING_SUMMARY.
# (The tests check that every signal a view names exists in its bench's VCD.)
set -euo pipefail
cd "$(dirname "$0")/../.."
mkdir -p traces "$SHADING_OUT"
"$SHADING_BIN/interp_coef_tb" --vcd traces/interp_coef --csv "$SHADING_OUT/interp_div3.csv"
"$SHADING_BIN/interp_horner_tb" --vcd traces/interp_horner --csv "$SHADING_OUT/interp_horner.csv"
"$SHADING_BIN/interp_fd_tb" --vcd traces/interp_fd --csv "$SHADING_OUT/interp_fd.csv"
# The longest supported interval (64 pixels) through the forward differences, no VCD.
"$SHADING_BIN/interp_fd_tb" --m 6 --no-vcd
"$SHADING_BIN/interp_line_tb" --vcd traces/interp_line
# The interpolation paper's NMSE claim per interval length, and the adaptive degree (golden models).
"$SHADING_BIN/interp_study" --csv "$SHADING_OUT/interp_nmse.csv"
/usr/bin/python3 scripts/plot_interp.py "$SHADING_OUT"
