#!/usr/bin/env python3
"""Each policy's distance from the optimum plan over a claims sweep (render_pipeline --sweep --grid
claims): for every configuration of the sweep's CSV, the optimum plan (yardstick_study --length
optimal, studies/yardsticks) with the same scene, size, light, n, device, evaluator, sample set,
interval lengths and carry, at the
configuration's own interpolation NMSE; the gap is the configuration's long operations over the
optimum's. Per size and device, each policy's worst (largest) and median gap, and the optimum's own
ratio against the scan-line Phong. The optimum minimises geometry points, not the Horner unit's
multiplications by t: through the Horner unit the gap is an approximation.

Usage: studies/scripts/pipeline_gap.py OUT.md CSV [CSV ...] [--jobs N] [--bin PATH] [--data-dir DIR]
                               [--device D] [--size S]
--bin: yardstick_study (default $SHADING_BIN/yardstick_study, SHADING_BIN default build/bin).

Writes OUT.md and OUT.md's stem + "_rows.csv" (one row per configuration). Standard library only.
Exit 0 on success, 1 if a render failed, 2 on bad usage.
"""
import argparse
import concurrent.futures
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pipeline_claims import merge, policy  # noqa: E402  (the same merge and policy labels)

# render_pipeline in $SHADING_BIN, else in build/bin of this source tree.
BIN_DIR = os.environ.get("SHADING_BIN") or os.path.join(
    os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "build", "bin")


def optimum_args(r, data_dir):
    a = ["--scene", r["scene"], "--size", r["size"], "--n", r["n"], "--device", r["device"], "--mode", r["mode"],
         "--eval", r["eval"], "--set", r["set"], "--m-min", r["m_min"], "--m-max", r["m_max"],
         "--length", "optimal", "--optimal-nmse", r["nmse_interp"], "--no-sim", "--no-images", "--md", "",
         "--json", "report.json"]
    if r.get("light", "default") != "default":
        a += ["--light", r["light"].replace(":", ",")]
    a.append("--carry-samples" if r.get("carry") == "1" else "--no-carry-samples")
    if data_dir:
        a += ["--data-dir", data_dir]
    return a


def run_one(binary, r, data_dir):
    with tempfile.TemporaryDirectory() as out:
        cmd = [binary] + optimum_args(r, data_dir) + ["--out", out]
        p = subprocess.run(cmd, capture_output=True, text=True,
                           env=dict(os.environ, SYSTEMC_DISABLE_COPYRIGHT_MESSAGE="1"))
        if p.returncode != 0:
            return None, " ".join(cmd) + "\n" + p.stderr.strip()
        with open(os.path.join(out, "report.json")) as f:
            j = json.load(f)
    ops = j["ops_per_pixel"]
    return {"optimum_long_per_px": ops["hardware"]["total"]["long"],
            "optimum_ratio_scanline": ops["scanline_phong_long_over_hardware_long"],
            "optimum_points_bound_per_px": j["plan"]["optimum"]["points_bound_per_pixel"]}, None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out_md")
    ap.add_argument("csv", nargs="+")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--bin", default=os.path.join(BIN_DIR, "yardstick_study"),
                    help="yardstick_study, which renders the optimum")
    ap.add_argument("--data-dir", default="")
    ap.add_argument("--device", default="", help="only this device's rows")
    ap.add_argument("--size", default="", help="only this size's rows")
    try:
        a = ap.parse_args()
    except SystemExit as e:
        sys.exit(2 if e.code else 0)
    if a.jobs < 1:
        sys.exit("pipeline_gap: --jobs must be at least 1")
    header, raw = merge(a.csv)
    rows = [dict(zip(header, r)) for r in raw]
    rows = [r for r in rows if (not a.device or r["device"] == a.device) and (not a.size or r["size"] == a.size)]
    if not rows:
        sys.exit("pipeline_gap: no configuration left (check --device and --size)")
    failed = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as ex:
        futures = [ex.submit(run_one, a.bin, r, a.data_dir) for r in rows]
        for r, fut in zip(rows, futures):
            res, err = fut.result()
            if res is None:
                failed.append(err)
                continue
            r.update(res)
            r["gap"] = float(r["long_per_px"]) / res["optimum_long_per_px"]
    if failed:
        print(f"pipeline_gap: {len(failed)} render(s) failed; the first:\n{failed[0]}", file=sys.stderr)
        sys.exit(1)
    stem = os.path.splitext(a.out_md)[0]
    keys = list(header) + ["optimum_long_per_px", "optimum_ratio_scanline", "optimum_points_bound_per_px", "gap"]
    with open(stem + "_rows.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    groups = {}
    for r in rows:
        groups.setdefault((int(r["size"]), r["device"]), {}).setdefault(policy(r), []).append(r)
    lines = ["# Each policy against the optimum plan at its own interpolation NMSE", "",
             "Gap = the policy's long operations over the optimum's (same scene, light, n, device, evaluator,",
             "carry), worst and median over the sweep's scenes x lights x n; the optimum's own ratio against",
             "the scan-line Phong beside it. Rows from `studies/scripts/pipeline_gap.py` over "
             + ", ".join(os.path.basename(p) for p in a.csv) + ".", ""]
    for (size, device), pols in sorted(groups.items()):
        lines += [f"## {device}, {size}x{size}", "",
                  "| policy | configs | gap worst | gap median | optimum × scan-line (worst / median) |",
                  "|---|---|---|---|---|"]
        for name, rs in sorted(pols.items(), key=lambda kv: statistics.median(r["gap"] for r in kv[1])):
            gaps = [r["gap"] for r in rs]
            opt = [r["optimum_ratio_scanline"] for r in rs]
            lines.append(f"| {name} | {len(rs)} | {max(gaps):.2f} | {statistics.median(gaps):.2f} | "
                         f"{min(opt):.2f} / {statistics.median(opt):.2f} |")
        lines.append("")
    text = "\n".join(lines)
    with open(a.out_md, "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()
