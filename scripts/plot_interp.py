#!/usr/bin/env python3
"""Plots of the interpolation paper's interpolation units (scripts/run.d/40-interp.sh runs this).

  plot_interp.py OUT_DIR
reads OUT_DIR/interp_horner.csv, interp_fd.csv (unit,variant,pixel,t,exact,value,error) and
interp_div3.csv (interval,first_pixel,case,coef,real,shift_add,exact_div,rel_err_*), writes
  interp_error.png - exact intensity and each unit's interpolation along the raster line, and the
                     error of each unit/variant against the exact intensity;
  interp_div3.png  - relative error of A and C caused by the shift-and-add division by 3;
and, when OUT_DIR/interp_nmse.csv exists (interp_study),
  interp_nmse.png  - NMSE of the line against the interval length N, every variant and the
                     adaptive degree, with the interpolation paper's 1e-4.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "out"
    rows = read(os.path.join(out, "interp_horner.csv")) + read(os.path.join(out, "interp_fd.csv"))
    series = {}
    exact = {}
    for r in rows:
        key = (r["unit"], r["variant"])
        series.setdefault(key, []).append((int(r["pixel"]), float(r["value"]), float(r["error"])))
        exact[int(r["pixel"])] = float(r["exact"])

    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(11, 8), sharex=True)
    px = sorted(exact)
    ax1.plot(px, [exact[p] for p in px], "k-", lw=2, label="exact intensity")
    for (unit, var), pts in sorted(series.items()):
        if unit != "horner":
            continue
        pts.sort()
        ax1.plot([p for p, _, _ in pts], [v for _, v, _ in pts], lw=1, label=f"Horner {var}")
    ax1.set_ylabel("intensity (0..255)")
    ax1.legend(fontsize=8)
    ax1.set_title("Interpolation along one raster line (samples Q8.8, coefficients Q16.16)")
    for (unit, var), pts in sorted(series.items()):
        pts.sort()
        style = "-" if unit == "horner" else ":"
        ax2.plot([p for p, _, _ in pts], [e for _, _, e in pts], style, lw=1, label=f"{unit} {var}")
    ax2.axhline(0, color="k", lw=0.5)
    ax2.set_xlabel("pixel")
    ax2.set_ylabel("interpolated - exact")
    ax2.legend(fontsize=7, ncol=2)
    # Interval boundaries from the pixels whose t is 0.
    for r in rows:
        if r["unit"] == "horner" and r["variant"] == "cubic1_exactdiv" and float(r["t"]) == 0.0:
            for ax in (ax1, ax2):
                ax.axvline(int(r["pixel"]), color="0.8", lw=0.5, zorder=0)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "interp_error.png"), dpi=110)

    d = read(os.path.join(out, "interp_div3.csv"))
    fig, ax = plt.subplots(figsize=(9, 4.5))
    for case in ("1", "2"):
        for coef, marker in (("A", "o"), ("C", "s")):
            sel = [r for r in d if r["case"] == case and r["coef"] == coef]
            ax.plot([int(r["interval"]) for r in sel], [100 * float(r["rel_err_shift_add"]) for r in sel],
                    marker, label=f"case {case} {coef}, shift-and-add /3")
            ax.plot([int(r["interval"]) for r in sel], [100 * float(r["rel_err_exact_div"]) for r in sel],
                    marker, mfc="none", label=f"case {case} {coef}, exact /3 (floor)")
    ax.axhline(0.79, color="r", ls="--", lw=1, label="the interpolation paper's claim 0.79 %")
    ax.axhline(100 / 128, color="k", ls=":", lw=1, label="1/128 = 0.78125 %")
    ax.set_xlabel("interval of the raster line")
    ax.set_ylabel("relative error of the coefficient (%)")
    ax.set_title("Division by 3 as 1/2 - 1/8 - 1/32 - 1/128: error in A and C")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "interp_div3.png"), dpi=110)

    nmse_path = os.path.join(out, "interp_nmse.csv")
    if os.path.exists(nmse_path):
        rows = read(nmse_path)
        fig, ax = plt.subplots(figsize=(9, 5))
        curves = {}
        for r in rows:
            key = r["variant"] if r["variant"] != "adaptive" else f"adaptive, tau = {r['tau']}"
            if r["variant"] == "adaptive" and r["tau"] not in ("2", "32"):
                continue
            curves.setdefault(key, []).append((int(r["N"]), float(r["nmse"])))
        for key, pts in curves.items():
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-" if "adaptive" not in key else "s--",
                      label=key)
        ax.axhline(1e-4, color="r", ls="--", lw=1, label="the interpolation paper: NMSE <= 1e-4")
        ax.set_xscale("log", base=2)
        ax.set_xlabel("interval length N (pixels)")
        ax.set_ylabel("NMSE against the exact intensity")
        ax.set_title("The interpolation paper's NMSE claim along one raster line with a highlight")
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "interp_nmse.png"), dpi=110)


if __name__ == "__main__":
    main()
