#!/usr/bin/python3
"""Plot of the shading pipeline's sweep (render_pipeline --sweep; scripts/run.d/70-pipeline.sh runs this).

  plot_pipeline.py SWEEP_CSV
reads the CSV (one row per configuration: length and degree policy, evaluator, device, the hardware
image's NMSE against per-pixel shading through the same device and against exact Phong, and the
counted long operations -- multiplications, divisions, square roots -- per pixel), writes beside it
  <stem>.png  - left: the interpolation's NMSE (hardware vs per-pixel device) against long operations
                per pixel; right: the total NMSE (hardware vs Phong). Colour = degree policy, marker =
                length policy and evaluator, one panel row per device. The Pareto front (no other
                configuration both cheaper and more accurate) is joined by a line and listed in
                <stem>_pareto.csv. <stem>_claims.txt (also printed): per device, the cheapest
                configuration meeting NMSE <= 1e-4 and <= 1e-5 against per-pixel shading and <= 1e-4
                against Phong, and the best one at >= 3x fewer long operations than Phong. Our target
                (NMSE <= 1e-5 with Phong's long ops / 3) and the interpolation paper's claim (NMSE <= 1e-4) are drawn
                as lines.
A CSV over several n (render_pipeline --sweep --grid exponents) gives instead <stem>.png with the
errors against n per device (the total against Phong beside the device BRDF's own error) and the
table in <stem>_claims.txt.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"cubic": "tab:blue", "quadratic": "tab:orange", "zones": "tab:green", "adaptive": "tab:purple",
           "geometry": "tab:cyan"}
MARKERS = {("fixed", "horner"): "o", ("fixed", "fd"): "^", ("adaptive", "horner"): "s", ("adaptive", "fd"): "D",
           ("geometry", "horner"): "P", ("geometry", "fd"): "X"}


def label(r):
    if r["length"] == "fixed":
        ln = f"m={r['m']}"
    else:
        ln = f"{r['length']} tol {r['length_tol']}"
    deg = r["degree"] + (f" {r['degree_tol']}" if r["degree"] in ("adaptive", "geometry") else "")
    hw = "" if r.get("geometry_side", "yes") == "yes" else " [host only]"
    return f"{ln}, {deg}, {r['eval']}{hw}"


def pareto(rows, key):
    """Rows not dominated in (long_per_px, key): sorted by cost, each strictly more accurate."""
    front, best = [], float("inf")
    for r in sorted(rows, key=lambda r: (float(r["long_per_px"]), float(r[key]))):
        if float(r[key]) < best:
            front.append(r)
            best = float(r[key])
    return front


def plot_exponents(rows, stem, devices):
    """A sweep over n (--grid exponents): the errors against n per device, and a table of them."""
    fig, axes = plt.subplots(1, 2, figsize=(13, 5))
    table = ["device n nmse_interp nmse_phong nmse_brdf long_per_px ratio_long"]
    for dev in devices:
        sel = sorted((r for r in rows if r["device"] == dev), key=lambda r: int(r["n"]))
        ns = [int(r["n"]) for r in sel]
        line, = axes[1].plot(ns, [float(r["nmse_phong"]) for r in sel], "o-", label=f"{dev}: hardware vs Phong")
        axes[1].plot(ns, [float(r["nmse_brdf"]) for r in sel], ":", color=line.get_color(),
                     label=f"{dev}: device reference vs Phong")
        axes[0].plot(ns, [max(float(r["nmse_interp"]), 1e-12) for r in sel], "o-", color=line.get_color(), label=dev)
        for r in sel:
            table.append(f"{dev} {r['n']} {float(r['nmse_interp']):.2e} {float(r['nmse_phong']):.2e} "
                         f"{float(r['nmse_brdf']):.2e} {float(r['long_per_px']):.1f} {float(r['ratio_long']):.2f}")
    axes[0].axhline(1e-5, color="tab:red", ls="--", lw=1, label="our target 1e-5")
    axes[0].axhline(1e-4, color="tab:brown", ls="--", lw=1, label="the interpolation paper: 1e-4")
    axes[1].axhline(1e-4, color="tab:brown", ls="--", lw=1, label="the interpolation paper: 1e-4")
    axes[0].set_title("interpolation: hardware vs per-pixel device", fontsize=10)
    axes[1].set_title("total: hardware vs exact Phong, and the device BRDF alone", fontsize=10)
    for ax in axes:
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("exponent n")
        ax.set_ylabel("NMSE")
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=7)
    r0 = rows[0]
    fig.suptitle(f"Shading pipeline against n: {r0['scene']} {r0['size']}x{r0['size']}, length {r0['length']}, "
                 f"degree {r0['degree']}, {r0['eval']} (golden model)", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    fig.savefig(stem + ".png", dpi=100)
    with open(stem + "_claims.txt", "w") as f:
        f.write("\n".join(table) + "\n")
    print("\n".join(table))
    print(f"plot_pipeline: wrote {stem}.png and {stem}_claims.txt")


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: plot_pipeline.py SWEEP_CSV")
    path = sys.argv[1]
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_pipeline: {path} has no rows")
    stem = os.path.splitext(path)[0]
    devices = sorted({r["device"] for r in rows})
    if len({r["n"] for r in rows}) > 1:
        return plot_exponents(rows, stem, devices)
    phong_long = float(rows[0]["phong_long_per_px"])
    fig, axes = plt.subplots(len(devices), 2, figsize=(15, 4.6 * len(devices)), squeeze=False)
    fronts = []
    for row_i, dev in enumerate(devices):
        sel = [r for r in rows if r["device"] == dev]
        for col, (key, title) in enumerate((("nmse_interp", "interpolation: hardware vs per-pixel device"),
                                            ("nmse_phong", "total: hardware vs exact Phong"))):
            ax = axes[row_i][col]
            seen = set()
            for r in sel:
                lab_deg = r["degree"]
                lab_len = (r["length"], r["eval"])
                lab = None
                if (lab_deg, lab_len) not in seen:
                    seen.add((lab_deg, lab_len))
                    lab = f"{lab_deg}, {lab_len[0]} length, {lab_len[1]}"
                ax.scatter(float(r["long_per_px"]), max(float(r[key]), 1e-12), c=COLOURS.get(r["degree"], "k"),
                           marker=MARKERS.get(lab_len, "x"), s=28, alpha=0.8, label=lab)
            front = pareto(sel, key)
            ax.plot([float(r["long_per_px"]) for r in front], [max(float(r[key]), 1e-12) for r in front], "k-",
                    lw=1, zorder=0, label="Pareto front")
            for r in front:
                fronts.append((dev, key, r))
            ax.axvline(phong_long, color="0.3", ls=":", lw=1, label=f"Phong {phong_long:.1f} long ops/pixel")
            ax.axvline(phong_long / 3, color="tab:red", ls=":", lw=1, label="Phong / 3")
            if key == "nmse_interp":
                ax.axhline(1e-5, color="tab:red", ls="--", lw=1, label="our target 1e-5")
            ax.axhline(1e-4, color="tab:brown", ls="--", lw=1, label="the interpolation paper: NMSE <= 1e-4")
            if key == "nmse_phong":
                brdf = float(sel[0]["nmse_brdf"])
                ax.axhline(brdf, color="0.5", ls="-.", lw=1, label=f"device BRDF alone {brdf:.1e}")
            ax.set_yscale("log")
            ax.set_xlabel("long operations (mul + div + sqrt) per pixel, counted")
            ax.set_ylabel("NMSE")
            ax.set_title(f"{dev}: {title}", fontsize=10)
            ax.grid(True, which="both", lw=0.3)
            if col == 1:
                ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0))
            else:  # the reference lines only; the markers are explained beside the right panel
                lines = [h for h in ax.get_lines() if not h.get_label().startswith("_")]
                ax.legend(handles=lines, fontsize=7, loc="upper right")
    r0 = rows[0]
    fig.suptitle(f"Shading pipeline sweep: {r0['scene']} {r0['size']}x{r0['size']}, n = {r0['n']}, "
                 f"{len(rows)} configurations (golden model)", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.98))
    fig.savefig(stem + ".png", dpi=100)
    with open(stem + "_pareto.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["device", "measure", "config", "long_per_px", "nmse", "ratio_long"])
        for dev, key, r in fronts:
            w.writerow([dev, key, label(r), r["long_per_px"], r[key], r["ratio_long"]])
    claims = []
    # The claims, per device: the cheapest configuration meeting each error target, and its ratio of
    # Phong's long operations to its own (the interpolation paper's claims NMSE <= 1e-4 at up to 3x fewer; ours 1e-5).
    for dev in devices:
        sel = [r for r in rows if r["device"] == dev]
        for key, target in (("nmse_interp", 1e-4), ("nmse_interp", 1e-5), ("nmse_phong", 1e-4), ("nmse_phong", 1e-5)):
            ok = sorted((r for r in sel if float(r[key]) <= target), key=lambda r: float(r["long_per_px"]))
            what = "vs per-pixel" if key == "nmse_interp" else "vs Phong"
            if ok:
                r = ok[0]
                scan = f", {float(r['ratio_long_scanline']):.2f}x fewer than scan-line Phong" \
                    if "ratio_long_scanline" in r else ""
                claims.append(f"{dev}: NMSE {what} <= {target:g}: cheapest {label(r)}: {float(r['long_per_px']):.1f} long "
                      f"ops/pixel ({float(r['ratio_long']):.2f}x fewer than Phong{scan}), NMSE {float(r[key]):.2e}")
            else:
                best = min(sel, key=lambda r: float(r[key]))
                claims.append(f"{dev}: NMSE {what} <= {target:g}: no configuration (best {float(best[key]):.2e}, {label(best)})")
        tri = [r for r in sel if float(r["ratio_long"]) >= 3.0]
        if tri:
            r = min(tri, key=lambda r: float(r["nmse_interp"]))
            claims.append(f"{dev}: at >= 3x fewer long ops than Phong: best NMSE vs per-pixel {float(r['nmse_interp']):.2e} "
                  f"({label(r)}, {float(r['ratio_long']):.2f}x), vs Phong {float(r['nmse_phong']):.2e}")
        # A geometry-only policy against the best policy at equal NMSE: the cheapest geometry-side
        # configuration at or below the NMSE of each Pareto point, its cost over the point's.
        if any(r.get("geometry_side") == "no" for r in sel):
            hw_rows = [r for r in sel if r.get("geometry_side") == "yes" and r["length"] == "geometry"]
            for r in pareto(sel, "nmse_interp"):
                ok = [h for h in hw_rows if float(h["nmse_interp"]) <= float(r["nmse_interp"])]
                if ok and 1e-6 <= float(r["nmse_interp"]) <= 1e-3:
                    h = min(ok, key=lambda h: float(h["long_per_px"]))
                    claims.append(f"{dev}: at NMSE vs per-pixel <= {float(r['nmse_interp']):.2e} the best is {label(r)} "
                                  f"({float(r['long_per_px']):.1f}); geometry-only {label(h)}: "
                                  f"{float(h['long_per_px']):.1f} ({float(h['long_per_px']) / float(r['long_per_px']):.2f}x)")
    with open(stem + "_claims.txt", "w") as f:
        f.write("\n".join(claims) + "\n")
    print("\n".join(claims))
    print(f"plot_pipeline: wrote {stem}.png, {stem}_pareto.csv and {stem}_claims.txt")


if __name__ == "__main__":
    main()
