#!/usr/bin/env bash
# Hardware cost by synthesis (scripts/synth.sh): every RTL variant through yosys to a generic gate
# library - cells, transistors, critical-path depth, the ROM as logic and as memory bits - into
# out/synth/ (synth.md, synth.csv), one summary row per variant. Skipped with a message when yosys
# is not installed or the build has no generated RTL (Verilator missing when CMake configured).
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${SHADING_OUT:-out}
if ! command -v yosys > /dev/null; then
  echo "80-synth: yosys is not installed: hardware cost by synthesis skipped (scripts/setup.sh installs it)"
  exit 0
fi
if [ ! -f build/generated/rtl/interp_terms.vh ]; then
  echo "80-synth: build/ has no generated RTL (Verilator was missing when CMake configured): synthesis skipped"
  exit 0
fi
scripts/synth.sh --build build --out "$out/synth" --jobs 2
if [ -n "${SHADING_SUMMARY:-}" ]; then
  /usr/bin/python3 - "$out/synth/synth.csv" >> "$SHADING_SUMMARY" << 'PY'
import csv, sys
for r in csv.DictReader(open(sys.argv[1])):
    note = "cells %s (%s flip-flops), %s transistors, depth %s gates" % (
        r["cells"], r["flip_flops"], r["transistors"], r["depth_gates"])
    if r["memory_bits"]:
        note += ", ROM as memory %s bits" % r["memory_bits"]
    print("\t".join(["synth", r["variant"], "-", "-", "-", "-", note]))
PY
fi
