#!/usr/bin/env bash
# The race (render_race, docs/race.md) on the head scan at 512x512, n = 20: every scheme at the frozen
# configuration against exact Phong, the cells' frame in SystemC against their golden model; race.md,
# race.csv and race_sheet.png in $SHADING_OUT/race/. One summary row per scheme (samples = covered
# pixels; mismatches = the cells' SystemC frame against golden, on the cells' row; max_error = the total
# NMSE against exact Phong) with its long operations a pixel and the ratio to Phong 1975.
set -euo pipefail
cd "$(dirname "$0")/../.."
out="$SHADING_OUT/race"
log=$("$SHADING_BIN/render_race" --scene head --size 512 --n 20 --out "$out")
pixels=$(sed -n 's/^# The race: .*, \([0-9]*\) pixels$/\1/p' <<<"$log")
differ=$(sed -n 's/.* the golden model.s (\([0-9]*\) pixels differ.*/\1/p' <<<"$log")
[ -n "$pixels" ] && [ -n "$differ" ] || { echo "75-race: unexpected output of render_race" >&2; exit 1; }
/usr/bin/python3 - "$out/race.csv" "$pixels" "$differ" >> "$SHADING_SUMMARY" <<'PY'
import csv, sys
path, pixels, differ = sys.argv[1], sys.argv[2], sys.argv[3]
for r in csv.DictReader(open(path, newline="")):
    mism = differ if r["scheme"] == "cells" else "-"
    print(f"race_head\t{r['scheme']}_512\t{pixels}\t{mism}\t{float(r['nmse_frame_buffer']):.3e}\t-\t"
          f"total NMSE vs exact Phong; {float(r['long_ops']):.2f} long ops/pixel, {float(r['times_phong1975']):.2f}x Phong 1975, "
          f"state {r['state_bits']} bits")
PY
