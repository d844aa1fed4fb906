#!/usr/bin/env bash
# UA 22802 (ROM prototype) testbench with its VCD, then the accuracy study of the quadratic BRDF and
# the squared-quadratic law (CSV), the search for the best ROM-free a(n), the head per device and n
# with the squared-quadratic device's fit (head_study), and the plots (PNG). Uses SHADING_BIN,
# SHADING_OUT and SHADING_SUMMARY (scripts/run.sh).
set -euo pipefail
cd "$(dirname "$0")/../.."
mkdir -p traces "$SHADING_OUT"
"$SHADING_BIN/ua22802_tb" --vcd traces/ua22802
"$SHADING_BIN/generator_search" --csv "$SHADING_OUT/generator_search.csv"
"$SHADING_BIN/accuracy_study" --out "$SHADING_OUT"
"$SHADING_BIN/head_study" --out "$SHADING_OUT"
/usr/bin/python3 scripts/plot_accuracy.py "$SHADING_OUT"
