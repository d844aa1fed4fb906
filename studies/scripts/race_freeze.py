#!/usr/bin/env python3
"""How the race's frozen configuration (src/golden_pipeline/race.cpp: frozen_race_config) was chosen, run
again: on the head at 512, n = 20, the scene's light and the square-and-multiply device only, each
adaptive scheme's setting on a grid, and per scheme the largest setting meeting its rule: total NMSE
<= 1e-5 against exact Phong for the lines (length tolerance) and the cells (T); no pixel more than 4
levels off for the split fast Phong (its budget). Prints the grid and the choice; the frozen values
are then written into race.cpp by hand and never re-tuned per case.

Usage: studies/scripts/race_freeze.py [--jobs N] [--bin PATH] [--data-dir DIR]
Standard library only. Exit 0 on success, 1 if a run failed.
"""
import argparse
import concurrent.futures
import csv
import os
import subprocess
import sys
import tempfile

BIN_DIR = os.environ.get("SHADING_BIN") or os.path.join(
    os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "build", "bin")
CELLS = [round(0.6 + 0.05 * i, 2) for i in range(13)]      # 0.60 .. 1.20
LINES = [round(1.5 + 0.05 * i, 2) for i in range(13)]      # 1.50 .. 2.10
BUDGETS = [1, 2, 4, 8, 16, 32, 64]


def run(args, tmp, i):
    out = os.path.join(tmp, str(i))
    cmd = [args.bin, "--scene", "head", "--size", "512", "--n", "20", "--device", "sqmul", "--no-sim", "--out", out]
    if i < len(CELLS):
        cmd += ["--cells-tol", str(CELLS[i]), "--line-tol", str(LINES[i])]
    if i < len(BUDGETS):
        cmd += ["--fast-phong-budget", str(BUDGETS[i])]
    if args.data_dir:
        cmd += ["--data-dir", args.data_dir]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}: exit {p.returncode}: {p.stderr.strip()}")
    with open(os.path.join(out, "race.csv"), newline="") as f:
        return {r["scheme"]: r for r in csv.DictReader(f) if r["frozen"] == "0"}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--bin", default=os.path.join(BIN_DIR, "render_race"))
    ap.add_argument("--data-dir", default="")
    args = ap.parse_args()
    n = max(len(CELLS), len(BUDGETS))
    with tempfile.TemporaryDirectory() as tmp, concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        try:
            res = list(pool.map(lambda i: run(args, tmp, i), range(n)))
        except RuntimeError as e:
            print(f"race_freeze: {e}", file=sys.stderr)
            return 1
    rules = [("cells", CELLS, lambda r: float(r["nmse_frame_buffer"]) <= 1e-5, "total NMSE <= 1e-5"),
             ("lines", LINES, lambda r: float(r["nmse_frame_buffer"]) <= 1e-5, "total NMSE <= 1e-5"),
             ("fast_phong_split", BUDGETS, lambda r: int(r["pixels_over_4"]) == 0, "no pixel > 4 levels off")]
    for scheme, grid, ok, rule in rules:
        print(f"{scheme} ({rule}):")
        best = None
        for i, v in enumerate(grid):
            r = res[i][scheme]
            print(f"  {v:>6}: {float(r['long_ops']):6.2f} long ops / px, NMSE {float(r['nmse_frame_buffer']):.3e}, "
                  f"largest {float(r['max_error_levels']):.2f} levels, {r['pixels_over_4']} pixels > 4 levels"
                  + ("  ok" if ok(r) else ""))
            if ok(r):
                best = v
        print(f"  chosen: {best}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
