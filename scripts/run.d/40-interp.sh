#!/usr/bin/env bash
# Seed 004's interpolation hardware: the coefficient units, the iterative Horner unit and the
# forward-difference evaluator, each over one raster line (VCDs in traces/, views traces/*.gtkw),
# the per-pixel and /3 CSVs and their plots in $SHADING_OUT. Summary rows go to $SHADING_SUMMARY.
set -euo pipefail
cd "$(dirname "$0")/../.."
mkdir -p traces "$SHADING_OUT"
"$SHADING_BIN/interp_coef_tb" --vcd traces/interp_coef --csv "$SHADING_OUT/interp_div3.csv"
"$SHADING_BIN/interp_horner_tb" --vcd traces/interp_horner --csv "$SHADING_OUT/interp_horner.csv"
"$SHADING_BIN/interp_fd_tb" --vcd traces/interp_fd --csv "$SHADING_OUT/interp_fd.csv"
# The longest supported interval (64 pixels) through the forward differences, no VCD.
"$SHADING_BIN/interp_fd_tb" --m 6 --no-vcd
# Seed 004's NMSE claim per interval length, and the adaptive degree (golden models).
"$SHADING_BIN/interp_study" --csv "$SHADING_OUT/interp_nmse.csv"
# Every signal a GTKWave view names must exist in its VCD.
/usr/bin/python3 - <<'PY'
import re, sys
bad = 0
for name in ("interp_coef", "interp_horner", "interp_fd"):
    vcd, scope = set(), []
    with open(f"traces/{name}.vcd") as f:
        for line in f:
            if line.startswith("$enddefinitions"):
                break
            w = line.split()
            if w[:1] == ["$scope"]:
                scope.append(w[2])
            elif w[:1] == ["$upscope"]:
                scope.pop()
            elif w[:1] == ["$var"]:
                vcd.add(".".join(scope + [w[4]]) + (w[5] if w[5].startswith("[") else ""))
    with open(f"traces/{name}.gtkw") as f:
        for line in f:
            line = line.strip()
            if line.startswith("SystemC.") and line not in vcd:
                print(f"{name}.gtkw: {line} is not in traces/{name}.vcd", file=sys.stderr)
                bad += 1
sys.exit(1 if bad else 0)
PY
/usr/bin/python3 scripts/plot_interp.py "$SHADING_OUT"
