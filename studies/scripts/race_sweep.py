#!/usr/bin/env python3
"""The race (render_race: Phong 1975, Gouraud, Bishop-Weimer, Lyon, the interpolation paper's lines and
the cells, src/golden_pipeline/race.h) over the claims sweep's scenes x lights x n at one size, every
scheme at the frozen configuration (never tuned per case). Per scheme: its long operations against
Phong 1975's (worst and median over the cases), its total NMSE against exact Phong (worst and
median), the cases it meets NMSE <= 1e-5 and <= 1e-4; per error level, how many cases each scheme is
the cheapest meeting it; one row per case.

Usage: studies/scripts/race_sweep.py OUT.md [--size 512] [--jobs N] [--scenes head sphere torus [X.obj ...]]
                                    [--lights -40,25 35,20 10,60] [--ns 5 20 100 500] [--device sqmul]
                                    [--bin PATH] [--data-dir DIR]
A negative azimuth reads as an option to argparse: give it alone as --lights=-40,25.
Standard library only. Exit 0 on success, 1 if a run failed, 2 on bad usage.
"""
import argparse
import concurrent.futures
import csv
import os
import statistics
import subprocess
import sys
import tempfile

# render_race (a program of the default build) in $SHADING_BIN, else in build/bin of this source tree.
BIN_DIR = os.environ.get("SHADING_BIN") or os.path.join(
    os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "build", "bin")
LEVELS = (1e-5, 1e-4)


def run(args, tmp, scene, light, n):
    out = os.path.join(tmp, f"{os.path.basename(scene)}_{light}_{n}")
    cmd = [args.bin, "--scene", scene, f"--light={light}", "--n", str(n), "--size", str(args.size), "--device",
           args.device, "--no-sim", "--out", out]
    if args.data_dir:
        cmd += ["--data-dir", args.data_dir]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}: exit {p.returncode}: {p.stderr.strip()}")
    with open(os.path.join(out, "race.csv"), newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["frozen"] == "1"]
    return {r["scheme"]: {"ops": float(r["long_ops"]), "times": float(r["times_phong1975"]),
                          "nmse": float(r["nmse_frame_buffer"]), "max": float(r["max_error_levels"])} for r in rows}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out")
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--scenes", nargs="+", default=["head", "sphere", "torus"])
    ap.add_argument("--lights", nargs="+", default=["-40,25", "35,20", "10,60"])
    ap.add_argument("--ns", nargs="+", type=int, default=[5, 20, 100, 500])
    ap.add_argument("--device", default="sqmul")
    ap.add_argument("--bin", default=os.path.join(BIN_DIR, "render_race"))
    ap.add_argument("--data-dir", default="")
    args = ap.parse_args()
    if not os.path.exists(args.bin):
        print(f"race_sweep: {args.bin} not found (scripts/build.sh render_race)", file=sys.stderr)
        return 2
    cases = [(s, l, n) for s in args.scenes for l in args.lights for n in args.ns]
    results = {}
    with tempfile.TemporaryDirectory() as tmp, concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = {pool.submit(run, args, tmp, *c): c for c in cases}
        for fut in concurrent.futures.as_completed(futures):
            try:
                results[futures[fut]] = fut.result()
            except RuntimeError as e:
                print(f"race_sweep: {e}", file=sys.stderr)
                return 1
    schemes = list(results[cases[0]].keys())
    lines = [f"# The race over {len(cases)} cases at {args.size}: scenes {' '.join(args.scenes)}; lights "
             f"{' '.join(args.lights)}; n {' '.join(map(str, args.ns))}; device {args.device}; the frozen configuration",
             "", "`studies/scripts/race_sweep.py " + " ".join(sys.argv[1:]) + "`", "",
             "| scheme | x Phong 1975, worst / median | NMSE, worst / median | cases within 1e-5 | within 1e-4 |"
             " cheapest within 1e-5 | cheapest within 1e-4 |", "|---|---|---|---|---|---|---|"]
    cheapest = {lv: {} for lv in LEVELS}
    for c in cases:
        for lv in LEVELS:
            ok = [(results[c][s]["ops"], s) for s in schemes if results[c][s]["nmse"] <= lv]
            if ok:
                best = min(ok)[1]
                cheapest[lv][best] = cheapest[lv].get(best, 0) + 1
    for s in schemes:
        times = [results[c][s]["times"] for c in cases]
        nmse = [results[c][s]["nmse"] for c in cases]
        within = [sum(1 for v in nmse if v <= lv) for lv in LEVELS]
        lines.append(f"| {s} | {min(times):.2f} / {statistics.median(times):.2f} | {max(nmse):.2e} / "
                     f"{statistics.median(nmse):.2e} | {within[0]} | {within[1]} | {cheapest[LEVELS[0]].get(s, 0)} | "
                     f"{cheapest[LEVELS[1]].get(s, 0)} |")
    lines += ["", "Per case: each scheme's long operations a pixel and total NMSE against exact Phong.", "",
              "| scene | light | n | " + " | ".join(schemes) + " |", "|---|---|---|" + "---|" * len(schemes)]
    for c in cases:
        cells = [f"{results[c][s]['ops']:.1f} / {results[c][s]['nmse']:.1e}" for s in schemes]
        lines.append(f"| {os.path.basename(c[0])} | {c[1]} | {c[2]} | " + " | ".join(cells) + " |")
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines[:len(schemes) + 6]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
