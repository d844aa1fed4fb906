#!/usr/bin/env python3
"""The cells (cell_study: a quadtree of biquadratic cells decided from its lattices' differences) over
the claims sweep's scenes x lights x n: per case, the cheapest tolerance on a grid meeting the
interpolation NMSE, its long operations counted in the scheme's own order against the scan-line
Phong, with edges not walked and walked (both sides), through the squared device; with --golden the
bit-accurate cells (src/golden_pipeline/cells.h) instead of the real-valued emulation. The decision factors stay at cell_study's
defaults, chosen on the head at 512 with its default light and n = 20: the sweep says whether they
hold elsewhere. Per mode the worst and median ratio, per scene the lowest and highest, and how many
cases reach 3x; one row per case.

A grid, not a bisection: the NMSE is not monotone in the tolerance. A case no grid point brings
within the NMSE has no ratio (counted apart).

Usage: studies/scripts/cell_claims.py OUT.md [--size 512] [--nmse 1e-5] [--jobs N] [--scenes head sphere torus]
                                      [--lights -40,25 35,20 10,60] [--ns 5 20 100 500] [--tols 0.25,...]
                                      [--bin PATH] [--data-dir DIR] [--golden]
A negative azimuth reads as an option to argparse: give it alone as --lights=-40,25.
Standard library only. Exit 0 on success, 1 if a run failed, 2 on bad usage.
"""
import argparse
import concurrent.futures
import os
import re
import statistics
import subprocess
import sys

# cell_study (built with SHADING_BUILD_STUDIES) in $SHADING_BIN, else in build/bin of this source tree.
BIN_DIR = os.environ.get("SHADING_BIN") or os.path.join(
    os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "build", "bin")
TOLS = "0.25,0.35,0.5,0.6,0.7,0.8,0.9,1,1.1,1.2,1.3,1.4,1.7,2,2.5,3,4,6,8"
CHEAPEST = re.compile(r"The cheapest meeting NMSE <= \S+: T = (\S+), (\S+) points / px \(NMSE (\S+)\), counted (\S+) long "
                      r"ops / px in its order: (\S+)x the scan-line Phong")
SCANLINE = re.compile(r"Scan-line Phong: (\S+) long operations per pixel")


def run(args, scene, light, n, walk):
    # The squared device named, not left to cell_study's default: the figures quoted from this script are its.
    cmd = [args.bin, "--scene", scene, f"--light={light}", "--n", str(n), "--size", str(args.size),
           "--device", "squared", "--nmse", str(args.nmse), "--tol", args.tols]
    if args.data_dir:
        cmd += ["--data-dir", args.data_dir]
    if walk:
        cmd.append("--walk-edges")
    if args.golden:
        cmd.append("--golden")
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}: exit {p.returncode}: {p.stderr.strip()}")
    m = CHEAPEST.search(p.stdout)
    s = SCANLINE.search(p.stdout)
    if m is None:
        return {"scanline": float(s.group(1)) if s else None, "ratio": None}
    return {"T": float(m.group(1)), "points": float(m.group(2)), "nmse": float(m.group(3)), "long": float(m.group(4)),
            "ratio": float(m.group(5)), "scanline": float(s.group(1))}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out")
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--nmse", type=float, default=1e-5)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--scenes", nargs="+", default=["head", "sphere", "torus"])
    ap.add_argument("--lights", nargs="+", default=["-40,25", "35,20", "10,60"])
    ap.add_argument("--ns", nargs="+", type=int, default=[5, 20, 100, 500])
    ap.add_argument("--tols", default=TOLS)
    ap.add_argument("--bin", default=os.path.join(BIN_DIR, "cell_study"))
    ap.add_argument("--data-dir", default="")
    ap.add_argument("--golden", action="store_true", help="the bit-accurate cells (cell_study --golden)")
    args = ap.parse_args()
    if not os.access(args.bin, os.X_OK):
        print(f"cell_claims: no {args.bin}: build it first (scripts/build.sh --studies)", file=sys.stderr)
        return 2
    cases = [(s, li, n) for s in args.scenes for li in args.lights for n in args.ns]
    results = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = {pool.submit(run, args, s, li, n, w): (s, li, n, w) for (s, li, n) in cases for w in (False, True)}
        try:
            for f in concurrent.futures.as_completed(futures):
                results[futures[f]] = f.result()
        except RuntimeError as e:
            print(f"cell_claims: {e}", file=sys.stderr)
            return 1
    model = "the bit-accurate cells" if args.golden else "the cells, emulated"
    lines = [f"# {model[0].upper() + model[1:]} over the claims sweep ({args.size}x{args.size}, interpolation NMSE "
             f"<= {args.nmse:g}, squared device, cell_study's default factors)", "",
             "| scene | light | n | T | points / px | NMSE | long ops / px | x scan-line | walked: T | long ops / px | "
             "x scan-line |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for (s, li, n) in cases:
        a, b = results[(s, li, n, False)], results[(s, li, n, True)]
        def cells(r):
            if r["ratio"] is None:
                return ["none", "-", "-", "-", "-"]
            return [f"{r['T']:g}", f"{r['points']:.4f}", f"{r['nmse']:.2e}", f"{r['long']:.2f}", f"{r['ratio']:.2f}"]
        ca, cb = cells(a), cells(b)
        lines.append(f"| {s} | {li} | {n} | " + " | ".join(ca) + " | " + " | ".join([cb[0], cb[3], cb[4]]) + " |")
    lines += ["", "| | not walked: lowest-highest | reach 3x | walked: lowest-highest | reach 3x |", "|---|---|---|---|---|"]
    def summary(keys):
        out = []
        for w in (False, True):
            r = [results[k + (w,)]["ratio"] for k in keys]
            got = [x for x in r if x is not None]
            missing = len(r) - len(got)
            rng = f"{min(got):.2f}-{max(got):.2f}" if got else "-"
            if missing:
                rng += f" ({missing} none)"
            out += [rng, f"{sum(1 for x in got if x >= 3.0)} of {len(r)}"]
        return out
    for s in args.scenes:
        lines.append(f"| {s} | " + " | ".join(summary([(s, li, n) for li in args.lights for n in args.ns])) + " |")
    for w, name in ((False, "not walked"), (True, "walked")):
        got = [results[c + (w,)]["ratio"] for c in cases if results[c + (w,)]["ratio"] is not None]
        if got:
            lines.append("")
            lines.append(f"All {len(cases)} cases, {name}: worst {min(got):.2f}x, median {statistics.median(got):.2f}x.")
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines[-4:]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
