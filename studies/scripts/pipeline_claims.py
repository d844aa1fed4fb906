#!/usr/bin/env python3
"""Summarise the claims sweep of render_pipeline (--sweep --grid claims): each policy's worst case and
median over scenes x light directions x n, per image size and device, against both baselines.

Usage: studies/scripts/pipeline_claims.py OUT.md CSV [CSV ...]

The CSVs may be the shards of one sweep (--shard I/N, or the one-configuration CSVs of --emit-jobs):
rows are merged by their `config` column (a configuration present twice must agree) and sorted.
Writes OUT.md (one table per size and device) and OUT.md's stem + "_merged.csv"; prints the tables.
Standard library only.
"""
import csv
import statistics
import sys
from collections import defaultdict


def merge(paths):
    header, rows = None, {}
    for p in paths:
        with open(p, newline="") as f:
            r = csv.reader(f)
            h = next(r)
            if header is None:
                header = h
            elif h != header:
                sys.exit(f"pipeline_claims: {p}: another CSV header")
            for row in r:
                key = int(row[0])
                if key in rows and rows[key] != row:
                    sys.exit(f"pipeline_claims: configuration {key} differs between the CSVs")
                rows[key] = row
    return header, [rows[k] for k in sorted(rows)]


def policy(r):
    ln = f"fixed m={r['m']}" if r["length"] == "fixed" else f"{r['length']} tol {r['length_tol']}"
    deg = r["degree"] + (f" {r['degree_tol']}" if r["degree"] in ("adaptive", "geometry") else "")
    split = ", split at check" if r.get("split") == "1" else ""
    split += ", carry" if r.get("carry") == "1" else ""
    return f"{ln}, {deg}{split}, {r['eval']}"


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = sys.argv[1]
    header, raw = merge(sys.argv[2:])
    rows = [dict(zip(header, r)) for r in raw]
    stem = out[:-3] if out.endswith(".md") else out
    with open(stem + "_merged.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(raw)
    groups = defaultdict(list)
    for r in rows:
        groups[(int(r["size"]), r["device"], policy(r), r["geometry_side"])].append(r)
    lines = [f"# Claims sweep: {len(rows)} configurations", ""]
    lines.append("Worst case and median over scenes x light directions x n of each policy. NMSE interp: hardware "
                 "vs per-pixel shading through the same device; NMSE total: vs Phong with exact cos^n; ratios: "
                 "the baseline's long operations per pixel / the hardware path's (higher is better, worst = "
                 "lowest). `hw` = a hardware geometry side can run the policy as it stands.")
    for size, dev in sorted({(k[0], k[1]) for k in groups}):
        scenes = sorted({r["scene"] for k, g in groups.items() if k[:2] == (size, dev) for r in g})
        ns = sorted({int(r["n"]) for k, g in groups.items() if k[:2] == (size, dev) for r in g})
        lights = sorted({r["light"] for k, g in groups.items() if k[:2] == (size, dev) for r in g})
        lines += ["", f"## {size}x{size}, device {dev} (scenes {', '.join(scenes)}; n {', '.join(map(str, ns))}; "
                  f"lights {', '.join(lights)})", "",
                  "| policy | hw | cases | NMSE interp worst / median | NMSE total worst / median | "
                  "÷ Phong worst / median | ÷ scan-line Phong worst / median | largest error interp worst / median "
                  "(pixels > 16 levels, worst) |",
                  "|---|---|---|---|---|---|---|---|"]
        for key in sorted(k for k in groups if k[:2] == (size, dev)):
            g = groups[key]

            def col(name, worst):
                v = [float(r[name]) for r in g]
                return f"{worst(v):.2e} / {statistics.median(v):.2e}" if "nmse" in name else \
                    f"{worst(v):.2f} / {statistics.median(v):.2f}"
            over = max(int(r["px_over_16_interp"]) for r in g)
            lines.append(f"| {key[2]} | {key[3]} | {len(g)} | {col('nmse_interp', max)} | {col('nmse_phong', max)} | "
                         f"{col('ratio_long', min)} | {col('ratio_long_scanline', min)} | "
                         f"{col('max_interp', max)} ({over}) |")
    text = "\n".join(lines) + "\n"
    with open(out, "w") as f:
        f.write(text)
    print(text)
    print(f"pipeline_claims: wrote {out} and {stem}_merged.csv")


if __name__ == "__main__":
    main()
