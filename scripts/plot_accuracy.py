#!/usr/bin/python3
"""Plots of the accuracy study (run with /usr/bin/python3; reads the CSVs accuracy_study and
head_study wrote).

fig2_quadratic.png  the quadratic-BRDF paper's Fig. 2: cos^n against the quadratic for one n (a),
                    and the relative error along cos gamma (b), with the devices' bit-accurate curves.
fig3_max_rel_error.png  the paper's Fig. 3: the largest relative error where cos^n >= 0.56 against
                    n, every method and device on one chart, log scale, with the paper's 4 % and
                    the 1 % target.
fig3_nmse.png       the NMSE over cos in [0, 1] (uniform) against n.
head_nmse.png       (a) the NMSE of each law over the distribution of cos = N.H on the head against
                    n; (b) the device reference's image against exact Phong (head_study: every
                    device at the exponents sweep, the squared device and the baseline at every n).
squared_fit.png     the squared-quadratic device's fit (head_study): relative error against n for
                    the bend's shifts and the word lengths, the image NMSE against n for the bends,
                    and the trade-off between the two criteria.
Usage: plot_accuracy.py <dir with the CSVs>  (PNGs are written beside them)
"""
import csv
import os
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
    "squared": "squared-quadratic device (ours)",
    "squared_law": "squared-quadratic law (ours, real)",
    "sqmul": "square-and-multiply, Q1.18",
    "trial_inflection": "trial law n'\u2208[2,4), inflection a (real)",
    "trial_fitted": "trial law n'\u2208[2,4), a fitted on the head (real)",
    "schlick": "Schlick",
    "lyon": "Lyon, power 2^floor(log2 n)",
    "lyon_g4": "Lyon, power 4",
    "cosk": "(cos k\u03b3)^(n/k) as printed",
    "cosk_k2": "(cos k\u03b3)^(n/k\u00b2) re-derived",
}
STYLE = {
    "quad_exact": dict(color="black", lw=2.2),
    "rom": dict(color="tab:blue", lw=1.2, ls="--"),
    "patent": dict(color="tab:red", lw=1.2),
    "minimax": dict(color="tab:green", lw=1.2),
    "rom_matched": dict(color="tab:olive", lw=1.2, ls="-."),
    "squared": dict(color="magenta", lw=1.6),
    "squared_law": dict(color="darkmagenta", lw=1.0, ls=":"),
    "sqmul": dict(color="tab:cyan", lw=1.4),
    "trial_inflection": dict(color="tab:brown", lw=1.0, ls="--"),
    "trial_fitted": dict(color="tab:pink", lw=1.0),
    "schlick": dict(color="tab:purple", lw=1.0),
    "lyon": dict(color="teal", lw=1.0),
    "lyon_g4": dict(color="teal", lw=1.0, ls="--"),
    "cosk": dict(color="tab:gray", lw=1.0, ls=":"),
    "cosk_k2": dict(color="tab:orange", lw=1.0),
}
DEVICES = ["rom", "patent", "minimax", "rom_matched", "squared", "sqmul"]
BENDS = {"f": "a = f (no bend)", "s1": "s = 1", "s2": "s = 2 (the device)", "s3": "s = 3", "s2s3": "3/8 (s = 2 and 3)"}
FRACS = {f"q{q}": f"Q1.{q}" + (" (the device)" if q == 18 else "") for q in range(16, 21)}


def read(path):
    """Columns as float arrays (empty cells: NaN), or as lists of strings where not numeric."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    out = {}
    for k in rows[0]:
        try:
            out[k] = np.array([float(r[k]) if r[k] != "" else np.nan for r in rows])
        except ValueError:
            out[k] = [r[k] for r in rows]
    return out


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def plot_paper(out, acc, fig2):
    n2 = int(fig2["n"][0])
    c, exact = fig2["cos"], fig2["exact"]
    fig, (ax_a, ax_b) = plt.subplots(2, 1, figsize=(8, 9))
    ax_a.plot(c, exact, label=f"cos^{n2} \u03b3", color="black", lw=2.5, alpha=0.4)
    curves = ("quad_exact", "rom", "patent", "minimax", "rom_matched", "squared")
    for m in curves:
        ax_a.plot(c, fig2[m], label=LABELS[m], **STYLE[m])
    ax_a.axhline(0.56, color="gray", lw=0.6, ls=":")
    ax_a.set_xlabel("cos \u03b3")
    ax_a.set_ylabel("BRDF")
    ax_a.set_title(f"a) cos^n \u03b3 and its approximations, n = {n2} (the quadratic-BRDF paper, Fig. 2a)")
    ax_a.set_ylim(-0.05, 1.05)
    ax_a.legend(fontsize=8)
    mask = exact >= 0.56
    for m in curves:
        ax_b.plot(c[mask], 100 * (fig2[m][mask] - exact[mask]) / exact[mask], label=LABELS[m], **STYLE[m])
    ax_b.set_xlabel("cos \u03b3 (region cos^n \u03b3 \u2265 0.56)")
    ax_b.set_ylabel("relative error, %")
    ax_b.set_title("b) relative error (the paper's Fig. 2b)")
    ax_b.axhline(0, color="gray", lw=0.6)
    ax_b.legend(fontsize=8)
    save(fig, f"{out}/fig2_quadratic.png")

    n = acc["n"]
    fig, ax = plt.subplots(figsize=(11, 6.5))
    for m in LABELS:
        ax.semilogy(n, 100 * np.maximum(acc[f"maxrel056_{m}"], 1e-5), label=LABELS[m], **STYLE[m])
    ax.axhline(4, color="k", lw=0.8, ls="--", label="the paper's 4 %")
    ax.axhline(1, color="k", lw=0.8, ls="-.", label="target: 1 %")
    ax.axvline(512, color="k", lw=0.5, ls=":")
    ax.set_xlabel("n")
    ax.set_ylabel("max relative error where cos^n \u2265 0.56, %")
    ax.set_title("Largest relative error above 0.56 against n (the paper's Fig. 3, extended to n = 1000)")
    ax.set_xlim(1, n[-1])
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    ax.grid(True, which="both", alpha=0.3)
    save(fig, f"{out}/fig3_max_rel_error.png")

    fig, ax = plt.subplots(figsize=(11, 6.5))
    for m in LABELS:
        ax.semilogy(n, np.maximum(acc[f"nmse_{m}"], 1e-16), label=LABELS[m], **STYLE[m])
    ax.set_xlabel("n")
    ax.set_ylabel("NMSE over cos \u03b3 \u2208 [0, 1] (32769 Q1.15 codes)")
    ax.set_title("Normalised mean squared error against n, cos uniform in [0, 1]")
    ax.set_xlim(1, n[-1])
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    ax.grid(True, which="both", alpha=0.3)
    save(fig, f"{out}/fig3_nmse.png")


def plot_head(out, acc):
    n = acc["n"]
    table = f"{out}/head_device_table.csv"
    scan = f"{out}/head_scan.csv"
    panels = 2 if os.path.exists(table) else 1
    fig, axes = plt.subplots(panels, 1, figsize=(11, 5.5 * panels), squeeze=False)
    ax = axes[0][0]
    for m in LABELS:
        ax.loglog(n, np.maximum(acc[f"hnmse_{m}"], 1e-13), label=LABELS[m], **STYLE[m])
    ax.set_ylim(1e-12, 2)
    ax.set_xlabel("n (0 drawn as 1e-13)")
    ax.set_ylabel("NMSE over the head's N.H distribution")
    ax.set_title("a) NMSE of each law over the distribution of cos = N.H on the head (512\u00d7512, N.L > 0)")
    ax.set_xlim(1, n[-1])
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    ax.grid(True, which="both", alpha=0.3)
    if panels == 2:
        ax = axes[1][0]
        t = read(table)
        ids = t["device"]
        for d in DEVICES + ["squared_law", "trial_inflection", "trial_fitted"]:
            sel = [i for i, x in enumerate(ids) if x == d]
            if not sel:
                continue
            dots = d in ("squared", "sqmul", "squared_law")  # drawn as lines over every n below
            style = {k: v for k, v in STYLE[d].items() if k != "ls"}
            ax.loglog(t["n"][sel], t["image_nmse"][sel], marker="o" if d in DEVICES else "^", ms=4,
                      ls="none" if dots else STYLE[d].get("ls", "-"), label=LABELS[d] + " (exponents sweep)", **style)
        if os.path.exists(scan):
            s = read(scan)
            ax.loglog(s["n"], s["image_nmse_s2"], label=LABELS["squared"] + ", every n", **STYLE["squared"])
            ax.loglog(s["n"], s["image_nmse_sqmul"], label=LABELS["sqmul"] + ", every n", **STYLE["sqmul"])
        ax.axhline(1e-5, color="k", lw=0.8, ls="--", label="target: 1e-5 (n = 2..500)")
        ax.axhline(1e-6, color="k", lw=0.8, ls="-.", label="target: 1e-6 (n = 20)")
        ax.set_xlabel("n")
        ax.set_ylabel("image NMSE against exact Phong")
        ax.set_title("b) The device reference's image against exact Phong, head 512\u00d7512")
        ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
        ax.grid(True, which="both", alpha=0.3)
    save(fig, f"{out}/head_nmse.png")


def plot_fit(out):
    fit_path, rel_path, scan_path = (f"{out}/squared_fit.csv", f"{out}/squared_fit_maxrel.csv", f"{out}/head_scan.csv")
    if not (os.path.exists(fit_path) and os.path.exists(rel_path)):
        return False
    fit, rel = read(fit_path), read(rel_path)
    scan = read(scan_path) if os.path.exists(scan_path) else None
    colors = dict(f="tab:gray", s1="tab:blue", s2="magenta", s3="tab:green", s2s3="tab:orange",
                  q16="tab:red", q17="tab:orange", q18="magenta", q19="tab:green", q20="tab:blue")
    fig, axes = plt.subplots(2, 2, figsize=(14, 10))
    ax = axes[0][0]
    for v, label in BENDS.items():
        ax.loglog(rel["n"], 100 * rel[f"maxrel056_{v}"], label=label, color=colors[v], lw=1.8 if v == "s2" else 0.9)
    ax.axhline(1, color="k", lw=0.8, ls="--", label="target: 1 %")
    ax.set_title("a) bend a = f + f(1-f)/2^(k+s): worst rel. error above 0.56")
    ax.set_xlabel("n")
    ax.set_ylabel("%")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    ax = axes[0][1]
    for v, label in FRACS.items():
        ax.semilogy(rel["n"], 100 * rel[f"maxrel056_{v}"], label=label, color=colors[v], lw=1.8 if v == "q18" else 0.9)
    ax.axhline(1, color="k", lw=0.8, ls="--", label="target: 1 %")
    ax.set_title("b) q / square word's fraction bits (s = 2): worst rel. error above 0.56")
    ax.set_xlabel("n")
    ax.set_ylabel("%")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    ax = axes[1][0]
    ns = [int(k[len("image_nmse_n"):]) for k in fit if k.startswith("image_nmse_n")]
    for i, v in enumerate(fit["variant"]):
        if v not in BENDS:
            continue
        if scan is not None:
            ax.loglog(scan["n"], scan[f"image_nmse_{v}"], color=colors[v], lw=1.6 if v == "s2" else 0.8, label=BENDS[v])
        ax.loglog(ns, [fit[f"image_nmse_n{n}"][i] for n in ns], "o", color=colors[v], ms=4)
    ax.axhline(1e-5, color="k", lw=0.8, ls="--", label="target: 1e-5")
    ax.axhline(1e-6, color="k", lw=0.8, ls="-.", label="target at n = 20: 1e-6")
    ax.set_title("c) bend: head image NMSE vs exact Phong (line: every n; dots: sweep)")
    ax.set_xlabel("n")
    ax.set_ylabel("image NMSE")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    ax = axes[1][1]
    names = dict(BENDS, s2="s = 2, Q1.18 (the device)", q16="Q1.16", q17="Q1.17", q18="Q1.18-Q1.20", q19="", q20="")
    for i, v in enumerate(fit["variant"]):
        x, y = 100 * fit["worst_maxrel056_1_1000"][i], fit["worst_image_nmse_2_500"][i]
        bend = v in BENDS
        ax.loglog(x, y, "o" if bend else "s", color=colors[v], ms=8 if bend else 6, mfc=colors[v] if bend else "none")
        if bend and scan is not None:  # the worst over every n in 2..500 (n = 3 for each)
            ax.loglog(x, fit["scan_worst_image_nmse_2_500"][i], "x", color=colors[v], ms=8)
            ax.plot([x, x], [y, fit["scan_worst_image_nmse_2_500"][i]], color=colors[v], lw=0.6, ls=":")
        if names[v]:
            ax.annotate(names[v], (x, y), textcoords="offset points", xytext=(6, 4 if bend else -12), fontsize=8)
    ax.axvline(1, color="k", lw=0.8, ls="--")
    ax.axhline(1e-5, color="k", lw=0.8, ls="--")
    ax.set_title("d) trade-off: worst rel. error (n \u2264 1000) against worst image NMSE, n = 2..500\n"
                 "(dots: the sweep's 8 n, x: every n; filled: bends, open: word lengths)")
    ax.set_xlabel("worst relative error above 0.56, %")
    ax.set_ylabel("worst image NMSE against exact Phong")
    ax.grid(True, which="both", alpha=0.3)
    save(fig, f"{out}/squared_fit.png")
    return True


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "out"
    acc = read(f"{out}/accuracy.csv")
    plot_paper(out, acc, read(f"{out}/fig2_curve.csv"))
    plot_head(out, acc)
    fit = plot_fit(out)
    print(f"plot_accuracy: wrote {out}/fig2_quadratic.png, fig3_max_rel_error.png, fig3_nmse.png, head_nmse.png"
          + (", squared_fit.png" if fit else " (no head_study CSVs: no squared_fit.png)"))


if __name__ == "__main__":
    main()
