#!/usr/bin/python3
"""Plots of the accuracy study (run with /usr/bin/python3; reads the CSVs accuracy_study wrote).

fig2_quadratic.png  seed 001, Fig. 2: cos^n against the quadratic for one n (a), and the relative
                    error along cos gamma (b), with the devices' bit-accurate curves.
fig3_max_rel_error.png  seed 001, Fig. 3: the largest relative error where cos^n >= 0.56 against n,
                    every method on one chart, log scale, with seed 001's 4 % line.
fig3_nmse.png       the NMSE over cos in [0, 1] against n.
Usage: plot_accuracy.py <dir with the CSVs>  (PNGs are written beside them)
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

LABELS = {
    "quad_exact": "quadratic, exact a(n) (real)",
    "rom": "UA 22802 ROM device",
    "patent": "UA 60553, patent a = 0.789n + 0.5",
    "minimax": "UA 60553 tuned, a = 0.789n - 0.625, n<2: 0",
    "rom_matched": "UA 60553 tuned, a = 0.789n - 0.570, n<2: 0",
    "schlick": "Schlick",
    "cosk": "(cos k\u03b3)^(n/k) as printed",
    "cosk_k2": "(cos k\u03b3)^(n/k\u00b2) re-derived",
}
STYLE = {
    "quad_exact": dict(color="black", lw=2.2),
    "rom": dict(color="tab:blue", lw=1.2, ls="--"),
    "patent": dict(color="tab:red", lw=1.2),
    "minimax": dict(color="tab:green", lw=1.2),
    "rom_matched": dict(color="tab:olive", lw=1.2, ls="-."),
    "schlick": dict(color="tab:purple", lw=1.0),
    "cosk": dict(color="tab:gray", lw=1.0, ls=":"),
    "cosk_k2": dict(color="tab:orange", lw=1.0),
}


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "out"
    acc = read(f"{out}/accuracy.csv")
    fig2 = read(f"{out}/fig2_curve.csv")
    n2 = int(fig2["n"][0])

    c, exact = fig2["cos"], fig2["exact"]
    fig, (ax_a, ax_b) = plt.subplots(2, 1, figsize=(8, 9))
    ax_a.plot(c, exact, label=f"cos^{n2} \u03b3", color="black", lw=2.5, alpha=0.4)
    for m in ("quad_exact", "rom", "patent", "minimax", "rom_matched"):
        ax_a.plot(c, fig2[m], label=LABELS[m], **STYLE[m])
    ax_a.axhline(0.56, color="gray", lw=0.6, ls=":")
    ax_a.set_xlabel("cos \u03b3")
    ax_a.set_ylabel("BRDF")
    ax_a.set_title(f"a) cos^n \u03b3 and its quadratic approximation, n = {n2} (seed 001, Fig. 2a)")
    ax_a.set_ylim(-0.05, 1.05)
    ax_a.legend(fontsize=8)
    mask = exact >= 0.56
    for m in ("quad_exact", "rom", "patent", "minimax", "rom_matched"):
        ax_b.plot(c[mask], 100 * (fig2[m][mask] - exact[mask]) / exact[mask], label=LABELS[m], **STYLE[m])
    ax_b.set_xlabel("cos \u03b3 (region cos^n \u03b3 \u2265 0.56)")
    ax_b.set_ylabel("relative error, %")
    ax_b.set_title("b) relative error (seed 001, Fig. 2b)")
    ax_b.axhline(0, color="gray", lw=0.6)
    ax_b.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{out}/fig2_quadratic.png", dpi=120)
    plt.close(fig)

    n = acc["n"]
    fig, ax = plt.subplots(figsize=(10, 6))
    for m in LABELS:
        ax.semilogy(n, 100 * np.maximum(acc[f"maxrel056_{m}"], 1e-5), label=LABELS[m], **STYLE[m])
    ax.axhline(4, color="k", lw=0.8, ls="--", label="seed 001: 4 %")
    ax.axvline(512, color="k", lw=0.5, ls=":")
    ax.set_xlabel("n")
    ax.set_ylabel("max relative error where cos^n \u2265 0.56, %")
    ax.set_title("Largest relative error above 0.56 against n (seed 001, Fig. 3, extended to n = 1000)")
    ax.set_xlim(1, 1000)
    ax.legend(fontsize=8, loc="lower right")
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(f"{out}/fig3_max_rel_error.png", dpi=120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(10, 6))
    for m in LABELS:
        ax.semilogy(n, acc[f"nmse_{m}"], label=LABELS[m], **STYLE[m])
    ax.set_xlabel("n")
    ax.set_ylabel("NMSE over cos \u03b3 \u2208 [0, 1] (32769 Q1.15 codes)")
    ax.set_title("Normalised mean squared error against n")
    ax.set_xlim(1, 1000)
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(f"{out}/fig3_nmse.png", dpi=120)
    plt.close(fig)
    print(f"plot_accuracy: wrote {out}/fig2_quadratic.png, fig3_max_rel_error.png, fig3_nmse.png")


if __name__ == "__main__":
    main()
