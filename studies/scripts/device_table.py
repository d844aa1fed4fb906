#!/usr/bin/python3
"""The specular devices side by side, one row each (docs/devices.md), from the outputs of three
commands, none of whose figures it computes itself:
  scripts/synth.sh --build build --out out/synth   synth.csv (transistors, flip-flops, ROM bits) and
                                                   clock_bounds.csv (the clock bound derived from the
                                                   measured paths, clocks and time per sample)
  build/bin/accuracy_study --out out               accuracy_summary.csv (worst relative error where
                                                   cos^n >= 0.56 and >= 0.1, n in [1, 1000])
  build/bin/head_study --out out                   head_device_table.csv (the head at 512, the device
                                                   reference against exact Phong, NMSE at n = 20)
Writes the table as Markdown to stdout and to <out>/device_table.md.
  /usr/bin/python3 studies/scripts/device_table.py --synth out/synth --out out
"""
import argparse
import csv
import os
import sys

# Each device: its synthesis variant, its id in the accuracy and head studies, its --device name.
DEVICES = [
    ("UA 60553, the patent's a(n) (saturating ADD11, the model's default)", "ua60553_saturate", "patent", "patent"),
    ("UA 60553 with the minimax generator of a(n) (ours)", "tuned_minimax", "minimax", "minimax"),
    ("UA 22802, the ROM prototype (ROM as logic)", "ua22802", "rom", "ua22802"),
    ("squared-quadratic (ours), one squarer iterated", "squared_saturate", "squared", "squared"),
    ("square-and-multiply (ours), one multiplier over n's bits", "sqmul_saturate", "sqmul", "sqmul"),
]
GATE_NS = 0.1  # one gate level at the model's default delays (docs/timing.md)


def read_csv(path):
    if not os.path.exists(path):
        sys.exit("device_table: %s is missing (see the commands in this script's header)" % path)
    with open(path, newline="") as f:
        return list(csv.reader(f))


def by_key(rows, key_col):
    head = rows[0]
    return head, {r[key_col]: r for r in rows[1:]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--synth", default="out/synth", help="scripts/synth.sh's --out")
    ap.add_argument("--out", default="out", help="accuracy_study's and head_study's --out")
    a = ap.parse_args()

    sh, synth = by_key(read_csv(os.path.join(a.synth, "synth.csv")), 0)
    bh, bounds = by_key(read_csv(os.path.join(a.synth, "clock_bounds.csv")), 0)
    acc_rows = read_csv(os.path.join(a.out, "accuracy_summary.csv"))
    ah = acc_rows[0]
    acc = {r[0]: r for r in acc_rows[1:]}
    head_rows = read_csv(os.path.join(a.out, "head_device_table.csv"))
    hh = head_rows[0]
    head = {r[0]: r for r in head_rows[1:] if r[hh.index("n")] == "20"}
    s = {k: sh.index(k) for k in ("transistors", "flip_flops", "hand_rom_bits")}
    b = {k: bh.index(k) for k in bh}
    # accuracy_summary.csv repeats "at_n": each worst is followed by its n.
    i056, i010 = ah.index("worst_maxrel056_1_1000"), ah.index("worst_maxrel010_1_1000")
    ref = float(synth["ua60553_saturate"][s["transistors"]])

    lines = ["| device (`--device`) | transistors (× UA 60553 saturating) | clock bound, gate delays (set by) | "
             "clocks per sample: worst / n = 20 / mean | time per sample, gate delays: worst / n = 20 / mean | "
             "samples per µs at 0.1 ns a gate (mean n) | worst rel. error, cos^n ≥ 0.56 (n) | same, ≥ 0.1 (n) | "
             "head NMSE vs exact Phong, n = 20 | state bits: flip-flops; ROM |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for label, variant, study_id, device in DEVICES:
        if variant not in synth or study_id not in acc or study_id not in head:
            sys.exit("device_table: no figures for %s (synthesis %s, study id %s)" % (label, variant, study_id))
        r = synth[variant]
        t = float(r[s["transistors"]])
        rom = r[s["hand_rom_bits"]] if device == "ua22802" else "0"
        if variant in bounds:
            q = bounds[variant]
            clk = "%s (%s, %s gates)" % (q[b["clock_bound"]], q[b["set_by"]], q[b["set_by_gates"]])
            clocks = "%s / %s / %s" % (q[b["clocks_worst"]], q[b["clocks_n20"]], q[b["clocks_mean"]])
            tps = "%s / %s / %s" % (q[b["time_worst"]], q[b["time_n20"]], q[b["time_mean"]])
            per_us = 1000.0 / (float(q[b["time_mean"]]) * GATE_NS)
        else:  # Fig. 3: no clock; one sample per strobe 17 cycle, which must cover the whole depth
            depth = r[sh.index("depth_gates")]
            clk = "— (strobe to output %s)" % depth
            clocks = "— (one strobe 17 cycle)"
            tps = "%s (every n)" % depth
            per_us = 1000.0 / (float(depth) * GATE_NS)
        e = acc[study_id]
        lines.append("| %s (`%s`) | %s (%.2f) | %s | %s | %s | %.1f | %.3f %% (%s) | %.2f %% (%s) | %.2e | %s; %s |" % (
            label, device, r[s["transistors"]], t / ref, clk, clocks, tps, per_us,
            100 * float(e[i056]), e[i056 + 1], 100 * float(e[i010]), e[i010 + 1],
            float(head[study_id][hh.index("image_nmse")]), r[s["flip_flops"]], rom))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(a.out, "device_table.md"), "w") as f:
        f.write(text)
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
