#!/usr/bin/env python3
"""Summary of scripts/synth.sh: one row per synthesized variant (cells, flip-flops, transistor
estimate, depth of the critical path in gates, ROM bits read as a memory) beside our hand count by
the cost table's rules (studies/accuracy/accuracy_study.cpp: an array multiplier is WA x WB cells,
a multiplier by a hardwired constant keeps its non-zero rows, an adder counts its output width,
gates of the special case, registers not counted). Writes synth.csv and synth.md to --out.
"""
import argparse
import csv
import glob
import os
import re
import sys


def macros(path):
    """`define NAME value lines of a generated header, values as text."""
    out = {}
    with open(path) as f:
        for line in f:
            m = re.match(r"`define\s+(\w+)\s+(\S+)", line)
            if m:
                out[m.group(1)] = m.group(2)
    return out


def parse_stat(path):
    """Cells, flip-flops, transistors and memory bits from `stat [-tech cmos]` output."""
    r = {"cells": None, "ffs": 0, "transistors": None, "memory_bits": None, "blackboxes": 0}
    if not os.path.exists(path):
        return r
    with open(path) as f:
        for line in f:
            m = re.match(r"\s+Number of cells:\s+(\d+)", line)
            if m:
                r["cells"] = int(m.group(1))
            m = re.match(r"\s+\$_(S?DFF\w*|DFFE\w*|SR\w*|DLATCH\w*)_\s+(\d+)", line)
            if m:
                r["ffs"] += int(m.group(2))
            m = re.match(r"\s+(ua22802_a_rom\w*|ram|\$paramod\S*\\ram)\s+(\d+)", line)
            if m:
                r["blackboxes"] += int(m.group(2))
            m = re.search(r"Estimated number of transistors:\s+(\d+)", line)
            if m:
                r["transistors"] = int(m.group(1))
            m = re.match(r"\s+Number of memory bits:\s+(\d+)", line)
            if m:
                r["memory_bits"] = int(m.group(1))
    return r


def parse_ltp(path):
    if not os.path.exists(path):
        return None
    with open(path) as f:
        m = re.search(r"length=(\d+)", f.read())
    return int(m.group(1)) if m else None


def hand_counts(hw_csv, fmt, terms):
    """Our count per variant by the cost table's rules: (rom bits, mult cells, adder bits, gates)."""
    hand = {}
    if hw_csv and os.path.exists(hw_csv):
        with open(hw_csv) as f:
            for row in csv.DictReader(f):
                hand[row["design"]] = (int(row["rom_bits"]), int(row["total_multiplier_cells"]),
                                       int(row["total_adder_bits"]), int(row["special_case_gates"]))
    rows = {}
    if hand:
        rows["ua22802"] = rows["ua22802_rom_as_memory"] = hand.get("ua22802_rom")
        rows["ua60553_patent"] = rows["ua60553_saturate"] = hand.get("ua60553_patent")
        rows["tuned_minimax"] = hand.get("ua60553_minimax")
        rows["tuned_rom_matched"] = hand.get("ua60553_rom_matched")
    # Generators alone, by the same rules from the header (so they exist without hw_cost.csv too).
    wn, wa = int(fmt["UA60553_N_W"]), int(fmt["UA60553_A_W"])
    k31 = fmt["UA60553_K31"].split("'b")[1]
    words = int(fmt["UA22802_ROM_WORDS"])
    rows["gen_rom"] = (int(fmt["UA22802_ROM_BITS"]), 0, 0, 0)
    rows["gen_linear"] = (0, wn * k31.count("1"), wa, 0)
    tk31 = fmt["TUNED_K31"].split("'b")[1]
    rows["gen_tuned_minimax"] = (0, wn * tk31.count("1"), wa, (wn - int(fmt["TUNED_OR_LO"])) + wa)
    # The interpolation paper's units: network adders (terms - 1 each, sum width), /3 by shift-and-add (3 adders
    # of the coefficient width), Horner's MUL (WC x WT), Sm and the key block's AND gates.
    ws, wc, wt = int(fmt["INTERP_SUM_W"]), int(fmt["INTERP_COEF_W"]), int(fmt["INTERP_T_W"])
    for name, case, div in (("coef_c1_shift_add", 1, "sa"), ("coef_c1_exact", 1, "ex"), ("coef_c2_shift_add", 2, "sa")):
        n = sum(int(terms[f"INTERP_{c}_CASE{case}_N"]) - 1 for c in ("A8", "B", "C3"))
        adder_bits = n * ws + (2 * 3 * wc if div == "sa" else 0)
        rows[name] = (0, 0, adder_bits, 0)
    rows["horner_unit"] = (0, wc * wt, wc, wc)
    a_int = int(fmt["UA22802_A_W"]) - int(fmt["UA22802_A_FRAC"])
    for f in range(2, 11):
        rows[f"rom_f{f}"] = (words * (a_int + f), 0, 0, 0)
    return rows


DESCRIPTIONS = {
    "ua22802": "UA 22802 device, ROM as logic",
    "ua22802_rom_as_memory": "UA 22802 device, ROM as a memory (logic outside the ROM)",
    "ua60553_patent": "UA 60553 as patented (wrapping ADD11)",
    "ua60553_saturate": "UA 60553, saturating ADD11 (the model's default)",
    "tuned_minimax": "UA 60553 tuned, minimax",
    "tuned_rom_matched": "UA 60553 tuned, rom_matched",
    "gen_rom": "generator alone: UA 22802's ROM (F = 6) as logic",
    "gen_linear": "generator alone: UA 60553's MUL6 + ADD15",
    "gen_tuned_minimax": "generator alone: tuned (MUL6 + ADD15 + OR + key)",
    "coef_c1_shift_add": "cubic coefficient unit, case 1, the interpolation paper's shift-and-add /3",
    "coef_c1_exact": "cubic coefficient unit, case 1, exact /3",
    "coef_c2_shift_add": "cubic coefficient unit, case 2, shift-and-add /3",
    "horner_unit": "Horner unit (Fig. 4) with its controller",
    "squared_saturate": "squared-quadratic device (ours), iterative stage, saturating ADD11",
    "squared_wrap": "squared-quadratic device (ours), iterative stage, wrapping ADD11",
    "squared_series": "squared-quadratic device (ours), series stage (9 squarers), saturating",
    "sqmul_saturate": "square-and-multiply baseline (one multiplier over the bits of n), saturating",
    "sqmul_r2l_saturate": "square-and-multiply, right to left (a squarer and a multiplier per bit of n), saturating",
    "pipe_sample_channel": "pipeline: sample channel (diffuse, ambient, colour, I1..I4, E1..E4, cubic case 1 with "
                           "the shift-and-add /3 and quadratic coefficient units)",
    "coef_quad": "quadratic coefficient unit",
    "pipe_sample_ctrl": "pipeline: sample controller (clocked device, no carry)",
    "pipe_horner_channel": "pipeline: Horner channel (degree multiplexers, the Fig. 4 unit with its controller, clamp)",
    "pipe_fd_channel_m4": "pipeline: forward-difference channel, fixed m = 4",
    "pipe_fd_channel_var": "pipeline: forward-difference channel, any m per interval",
    "pipe_horner_pixel_ctrl": "pipeline: pixel controller for Horner",
    "pipe_fd_pixel_ctrl": "pipeline: pixel controller for forward differences",
    "pipeline_horner": "shading pipeline, Horner, square-and-multiply device (saturating)",
    "pipeline_fd_var": "shading pipeline, forward differences for any m, square-and-multiply device (saturating)",
    "cell_unit": "cell unit (ours), column buffers as memory (logic outside them)",
}
# The per-pixel Phong shader's priced blocks (scripts/phong_estimate.py), named with their width.
PHONG_BLOCKS = {
    "mul": "Phong estimate: multiplier, signed %s x %s bits",
    "add": "Phong estimate: adder, signed %s bits",
    "stage_inv": "Phong estimate: divider / square-root stage, inverter bank of %s bits",
    "stage_sub": "Phong estimate: divider / square-root stage, subtractor of %s bits",
    "stage_mux": "Phong estimate: divider / square-root stage, multiplexer of %s bits",
}


def phong_description(name):
    m = re.match(r"phong_(\w+)_(\d+)$", name)
    if not m or m.group(1) not in PHONG_BLOCKS:
        return None
    text = PHONG_BLOCKS[m.group(1)]
    return text % ((m.group(2),) * text.count("%s"))


for _f in range(15, 21):
    DESCRIPTIONS["sqmul_p%d" % _f] = "square-and-multiply baseline at a Q1.%d P word, saturating" % _f
    DESCRIPTIONS["sqmul_r2l_p%d" % _f] = "square-and-multiply, right to left, at a Q1.%d P word, saturating" % _f

# Rising edges of clk from strobe 17's fall to output 29's rise (the synchroniser sync17's two,
# the taking edge, one per step, the done edge) of the clocked designs, as rtl/squared/sq_ctrl.v,
# rtl/sqmul/sqmul_ctrl.v and rtl/sqmul/sqmul_r2l_ctrl.v define them (checked against the golden
# models' counts by test_rtl_sqmul.cpp and test_rtl_squared_variants.cpp): k + 4 = floor(log2 n) + 4, floor(log2 n) + popcount(n) + 3
# and floor(log2 n) + 5 (bit_length is floor(log2 n) + 1). None for the combinational ones.
CLOCKS = {
    "squared_saturate": lambda n: n.bit_length() + 3,
    "squared_wrap": lambda n: n.bit_length() + 3,
    "sqmul_saturate": lambda n: n.bit_length() + bin(n).count("1") + 2,
    # rtl/sqmul/sqmul_r2l_ctrl.v: sync17's two, the taking edge, one per bit of n, the done edge
    # = floor(log2 n) + 5.
    "sqmul_r2l_saturate": lambda n: n.bit_length() + 4,
}

# What bounds the clocked designs' period (50 % duty), in gate delays: each measured path divided
# by the clocks it has. A loop through the iterated multiplier has a whole period (its register
# latches at falling edges), as have the right-to-left design's other register-to-register paths;
# a path that starts at a rising edge (the controller's selects) or ends at one (done, where output
# 29 samples the outputs) half a period; RG2's path into the load 2.5 periods at the least (the
# load latches at the falling edge after the taking edge, the third rising edge after strobe 17
# fell: the first may come just after the strobe), into the baseline's first multiplication 4.5.
PERIOD_SHARE = {
    "loop": 1.0, "loop_x": 1.0, "x_to_p": 1.0, "to_outputs": 0.5, "rg2_to_load": 2.5, "sel_to_multiply": 0.5,
    "rg2_to_multiply": 4.5,
}


def clocks_of(variant):
    """The clocks-per-sample rule of a variant (a word-length row: its design's)."""
    m = re.match(r"(sqmul(?:_r2l)?)_p\d+$", variant)
    return CLOCKS.get(m.group(1) + "_saturate" if m else variant)


def clock_bound(p):
    """The clock period in gate delays (50 % duty, strobe 17 asynchronous to clk; rtl/README.md) and the
    path that sets it: the longest of the measured paths `p`, each over the clocks it has (PERIOD_SHARE)."""
    need = {k: d / PERIOD_SHARE[k] for k, d in p.items() if k in PERIOD_SHARE and d is not None}
    if not need:
        return None, None
    by_path = max(need, key=need.get)
    return need[by_path], by_path

# The designs of the squared-quadratic comparison, in the table's order, and what each path is.
COMPARISON = ("ua60553_saturate", "ua60553_patent", "ua22802", "squared_saturate", "squared_wrap",
              "squared_series", "sqmul_saturate")
PATHS = {
    "loop": "register to register, the clock period: RG_SQ / RG_P -> multiplier (-> MX_B) -> multiplexer -> itself",
    "rg2_to_load": "strobe 17 to register: RG2 -> ... -> RG_SQ / RG_P at the load, 2.5 clocks after the strobe at the "
                   "soonest (the synchroniser's two rising edges, the taking edge, the falling edge after it)",
    "rg1_to_load": "strobe 15 to register: RG1 -> generator -> MUL10 -> ADD11 -> RG_SQ at the load",
    "rg1_to_ctrl": "strobe 15 to register: RG1 -> LZC (-> BSH1) -> the controller, at the taking edge (right to "
                   "left: RG1 -> the controller's bits register, no LZC)",
    "rg2_to_multiply": "RG2 -> clamp -> MX_B -> MUL_P -> MX_P -> RG_P in a multiplication step (4.5 clocks after the "
                       "strobe at the soonest: RG2 is held long before; the select into MX_B is sel_to_multiply)",
    "to_outputs": "result register -> colour multiplier -> output 25, within the done edge's half clock",
    "sel_to_multiply": "the controller's MX_B select (switched at a rising edge) -> MX_B -> MUL_P -> MX_P -> RG_P "
                       "(latched at the falling edge after it: half a clock)",
    "rg2_to_outputs": "strobe 17 to output: RG2 -> Fig. 1 at n' -> 9 squarers -> MUL12 -> output 25",
    "loop_x": "register to register (right to left): RG_X -> MUL_X -> MX_X -> RG_X",
    "x_to_p": "register to register (right to left): RG_X -> MUL_P -> MX_P -> RG_P",
    "rg1_to_outputs": "strobe 15 to output: RG1 -> generator -> MUL10 -> ... -> 9 squarers -> output 25",
    "nl_to_sample": "pipeline, into a sample register: RG_NL1 -> MX_NL -> the diffuse multiplier -> the ambient and "
                    "colour adders -> MX_CARRY -> I1 (channel R)",
    "specular_to_sample": "pipeline, into a sample register: the device's RG_P -> its colour multiplier -> the colour "
                          "adder -> MX_CARRY -> I1 (channel R)",
    "coef_to_eval": "pipeline: the coefficient units' registers -> their networks (/3) -> the degree multiplexers -> "
                    "the evaluator's registers (Horner: MUL, Sm; forward differences: the set-up network) (channel R)",
    "eval_loop": "pipeline: the evaluator's registers to themselves (Horner: RG -> MUL -> Sm -> RG; forward "
                 "differences: the recurrence's adders) (channel R)",
    "eval_to_pixels": "pipeline: the evaluator's registers -> the clamp -> px_r",
}


def read_paths(out, names):
    """The measured paths of every variant of this run ({variant: {label: depth}}), also as paths.csv."""
    paths = {}
    for f in sorted(glob.glob(os.path.join(out, "logs", "*.path.*.ltp"))):
        variant, label = os.path.basename(f)[:-len(".ltp")].split(".path.")
        if variant in names:
            paths.setdefault(variant, {})[label] = parse_ltp(f)
    with open(os.path.join(out, "paths.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["variant", "path", "depth_gates", "what"])
        for v in names:
            for label, depth in paths.get(v, {}).items():
                w.writerow([v, label, depth, PATHS.get(label, "")])
    return paths


def write_comparison(out, by, paths):
    """The squared-quadratic device beside UA 60553, UA 22802 and its two comparison designs:
    transistors, depth, clocks per sample (n in [1, 1000]: worst, at n = 20, mean) and paths."""
    if not all(k in by for k in COMPARISON):
        return
    ref = by["ua60553_saturate"]["transistors"]
    with open(os.path.join(out, "synth.md"), "a") as f:
        f.write("\n## The squared-quadratic device and the designs it is compared with\n\n")
        f.write("Transistors against UA 60553 saturating (%d); clocks per sample: rising edges of clk from strobe "
                "17's fall to output 29's rise, n in [1, 1000] (worst / n = 20 / mean); depth: `ltp -noff` of the "
                "whole design; paths: the longest path of each kind, in gates (paths.csv).\n\n" % ref)
        f.write("| design | transistors | x UA 60553 sat. | cells (flip-flops) | depth (gates) | clocks per sample "
                "| paths (gates) |\n|---|---|---|---|---|---|---|\n")
        for v in COMPARISON:
            r = by[v]
            if v in CLOCKS:
                c = [CLOCKS[v](n) for n in range(1, 1001)]
                clocks = "%d / %d / %.2f" % (max(c), CLOCKS[v](20), sum(c) / len(c))
            else:
                clocks = "none (combinational: Fig. 3)"
            p = "; ".join("%s %s" % (k, d) for k, d in paths.get(v, {}).items()) or "—"
            f.write("| %s | %d | %.2f | %d (%d) | %d | %s | %s |\n" % (
                r["description"], r["transistors"], r["transistors"] / ref, r["cells"], r["flip_flops"],
                r["depth_gates"], clocks, p))
        f.write("\nPaths: %s.\n" % "; ".join("**%s** %s" % (k, v) for k, v in PATHS.items()))
        f.write("\nClock bound (gate delays, 50 %% duty: each path over the clocks it has: %s) and time per "
                "sample (the bound times the clocks per sample: worst / n = 20 / mean over n in [1, 1000]):\n\n"
                "| design | clock bound | set by | time per sample |\n|---|---|---|---|\n" %
                ", ".join("%s %g" % (k, v) for k, v in PERIOD_SHARE.items()))
        for v in COMPARISON:
            if v not in CLOCKS or not paths.get(v):
                continue
            bound, by_path = clock_bound(paths[v])
            c = [CLOCKS[v](n) for n in range(1, 1001)]
            f.write("| %s | %.1f | %s (%d gates) | %.0f / %.0f / %.0f |\n" % (
                v, bound, by_path, paths[v][by_path], bound * max(c), bound * CLOCKS[v](20), bound * sum(c) / len(c)))
    write_clock_bounds(out, paths)


def write_clock_bounds(out, paths):
    """clock_bounds.csv: every clocked variant of this run with measured paths, its clock bound and the
    path that sets it, clocks and time per sample (worst / n = 20 / mean over n in [1, 1000]); the
    device table (studies/scripts/device_table.py) reads it."""
    with open(os.path.join(out, "clock_bounds.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["variant", "clock_bound", "set_by", "set_by_gates", "clocks_worst", "clocks_n20", "clocks_mean",
                    "time_worst", "time_n20", "time_mean"])
        for v in sorted(paths):
            rule = clocks_of(v)
            bound, by_path = clock_bound(paths[v])
            if rule is None or bound is None:
                continue
            c = [rule(n) for n in range(1, 1001)]
            mean = sum(c) / len(c)
            w.writerow([v, "%.0f" % bound, by_path, paths[v][by_path], max(c), rule(20), "%.2f" % mean,
                        "%.0f" % (bound * max(c)), "%.0f" % (bound * rule(20)), "%.0f" % (bound * mean)])


SQMUL_ORDER = ("sqmul_p15", "sqmul_p16", "sqmul_p17", "sqmul_saturate", "sqmul_p20", "sqmul_r2l_p16", "sqmul_r2l_saturate")


def write_sqmul_designs(out, by, paths):
    """The square-and-multiply designs of this run, left to right and right to left, at each P word:
    transistors, flip-flops, paths, the clock bound and the time per sample in gate delays."""
    rows = [v for v in SQMUL_ORDER if v in by]
    if not rows:
        return
    ref = by.get("ua60553_saturate", {}).get("transistors")
    ns = (5, 20, 100, 1000)
    with open(os.path.join(out, "synth.md"), "a") as f:
        f.write("\n## The square-and-multiply designs\n\n")
        f.write("Clock bound in gate delays: the longest measured path over the clocks it has, as in the table "
                "above (strobe 17 asynchronous to clk, 50 %% duty). Clocks per sample at n = %s and the mean over n in "
                "[1, 1000]; time per sample = clock bound x clocks.%s\n\n" % (
                    ", ".join(str(n) for n in ns),
                    " Transistors against UA 60553 saturating (%d, this run)." % ref if ref else ""))
        f.write("| design | transistors | x UA 60553 sat. | cells (flip-flops) | paths (gates) | clock bound | "
                "clocks: %s / mean | time per sample: %s / mean |\n|---|---|---|---|---|---|---|---|\n" % (
                    " / ".join("n = %d" % n for n in ns), " / ".join("n = %d" % n for n in ns)))
        for v in rows:
            r, p, rule = by[v], paths.get(v, {}), clocks_of(v)
            bound, by_path = clock_bound(p)
            c = [rule(n) for n in ns]
            mean = sum(rule(n) for n in range(1, 1001)) / 1000
            times = " / ".join("%.0f" % (bound * k) for k in c) + " / %.0f" % (bound * mean) if bound else "—"
            f.write("| %s | %d | %s | %d (%d) | %s | %s | %s / %.2f | %s |\n" % (
                r["description"], r["transistors"], "%.2f" % (r["transistors"] / ref) if ref else "—", r["cells"],
                r["flip_flops"], "; ".join("%s %s" % (k, d) for k, d in p.items()) or "—",
                "%.1f (%s)" % (bound, by_path) if bound else "—",
                " / ".join(str(k) for k in c), mean, times))



# The pipeline's tops and their units (variant, instances): three sample and three evaluator
# channels, one of each controller, the square-and-multiply device (its own row, sqmul_saturate).
PIPELINE_PARTS = {
    "pipeline_horner": (("pipe_sample_channel", 3), ("pipe_horner_channel", 3), ("pipe_sample_ctrl", 1),
                        ("pipe_horner_pixel_ctrl", 1), ("sqmul_saturate", 1)),
    "pipeline_fd_var": (("pipe_sample_channel", 3), ("pipe_fd_channel_var", 3), ("pipe_sample_ctrl", 1),
                        ("pipe_fd_pixel_ctrl", 1), ("sqmul_saturate", 1)),
}


def write_pipeline(out, by, paths):
    """The shading pipeline's tops beside the sum of their units' rows (each synthesized alone), and
    the tops' paths of each kind (appended to synth.md)."""
    tops = [t for t in PIPELINE_PARTS if t in by]
    if not tops:
        return
    with open(os.path.join(out, "synth.md"), "a") as f:
        f.write("\n## The shading pipeline, unit by unit\n\n")
        f.write("Each unit synthesized alone (its row above) times its instances, beside the whole top. The top adds "
                "its own registers (the job, the descriptor, the frame constants, N.H / N.L of the four samples) and "
                "the sample multiplexers; synthesis of the whole drops what the top leaves unused (without the carry: "
                "rg_last, rg_lnh, rg_lnl, the comparators) and narrows what a unit's driver makes redundant, which free "
                "pins hide from the unit alone (the forward differences' set-up and D3 register, fed by the "
                "coefficient units).\n\n")
        f.write("| top | unit | instances | transistors | flip-flops | depth (gates) |\n|---|---|---|---|---|---|\n")
        for t in tops:
            tr = ff = 0
            complete = True
            for unit, k in PIPELINE_PARTS[t]:
                r = by.get(unit)
                if r is None:
                    complete = False
                    f.write("| %s | %s | %d | — | — | — |\n" % (t, unit, k))
                    continue
                tr += k * r["transistors"]
                ff += k * r["flip_flops"]
                f.write("| %s | %s | %d | %d | %d | %d |\n" % (t, unit, k, r["transistors"], r["flip_flops"],
                                                             r["depth_gates"]))
            r = by[t]
            if complete:
                f.write("| %s | sum of the units | | %d | %d | |\n" % (t, tr, ff))
            f.write("| %s | **the whole top** | 1 | %d | %d | %d |\n" % (t, r["transistors"], r["flip_flops"],
                                                                      r["depth_gates"]))
            if complete:
                f.write("| %s | top - sum | | %+d (%+.1f %%) | %+d | |\n" % (
                    t, r["transistors"] - tr, 100.0 * (r["transistors"] - tr) / tr, r["flip_flops"] - ff))
        f.write("\nPaths of each kind (gates, `ltp -noff` between the nets named, paths.csv): %s.\n" % "; ".join(
            "%s: %s" % (t, ", ".join("%s %s" % (k, d) for k, d in paths.get(t, {}).items()) or "—") for t in tops))


def write_differences(out, by, fmt):
    """Why synthesis and our hand count differ, with this run's numbers (appended to synth.md)."""
    need = ("ua22802", "ua22802_rom_as_memory", "ua60553_patent", "ua60553_saturate", "gen_rom", "gen_linear",
            "rom_f2", "rom_f10")
    if not all(k in by for k in need):
        return
    if by["ua22802_rom_as_memory"]["hand_mult_cells"] == "":
        return  # no hand count (out/hw_cost.csv is written by scripts/run.sh's accuracy step)
    g = lambda k, c="cells": by[k][c]  # noqa: E731
    with open(os.path.join(out, "synth.md"), "a") as f:
        f.write("\n## Where synthesis and our hand count differ\n\n")
        f.write("- **Registers** are not in the hand count (common to every design); synthesis counts them as "
                "flip-flops (%d in each specular device: RG1..RG5).\n" % g("ua60553_patent", "flip_flops"))
        f.write("- **A multiplier by a hardwired constant**: the hand count keeps the constant's non-zero rows "
                "(MUL6: %s cells + ADD15: %s adder bits); synthesis folds the constant into a few adders of "
                "shifted n: the whole generator is %d gates (%d transistors), depth %d.\n" % (
                    by["gen_linear"]["hand_mult_cells"], by["gen_linear"]["hand_adder_bits"], g("gen_linear"),
                    g("gen_linear", "transistors"), g("gen_linear", "depth_gates")))
        f.write("- **The ROM**: the hand count is its %s bits. Built as logic, yosys/ABC minimise the table "
                "as a function of its 10 address wires; a(n) is smooth (nearly 0.787 n - 0.5), so the table "
                "needs %d gates (%d transistors) - %.1f bits per gate - and %d gates deep. From F = 2 to "
                "F = 10 the bits grow %.2fx and the gates %.2fx.\n" % (
                    fmt["UA22802_ROM_BITS"], g("gen_rom"), g("gen_rom", "transistors"),
                    int(fmt["UA22802_ROM_BITS"]) / g("gen_rom"), g("gen_rom", "depth_gates"),
                    by["rom_f10"]["hand_rom_bits"] / by["rom_f2"]["hand_rom_bits"], g("rom_f10") / g("rom_f2")))
        f.write("- **ADD11's clamp** (the model's saturate mode) is not in the hand count: it costs %d gates "
                "over the patent's wrapping adder (%d against %d) and lengthens the path from %d to %d gates.\n" % (
                    g("ua60553_saturate") - g("ua60553_patent"), g("ua60553_saturate"), g("ua60553_patent"),
                    g("ua60553_patent", "depth_gates"), g("ua60553_saturate", "depth_gates")))
        f.write("- **Array multiplier cells and adder bits** become about %.1f gates per multiplier cell in the "
                "shared datapath (UA 22802's logic outside its ROM: %d gates for %s cells and %s adder bits).\n" % (
                    (g("ua22802_rom_as_memory") - g("ua22802_rom_as_memory", "flip_flops"))
                    / by["ua22802_rom_as_memory"]["hand_mult_cells"], g("ua22802_rom_as_memory"),
                    by["ua22802_rom_as_memory"]["hand_mult_cells"], by["ua22802_rom_as_memory"]["hand_adder_bits"]))
        f.write("- **Depth**: the critical path is the cos path RG2 -> MUL7 -> ADD9 -> MUL10 -> ADD11 -> MUL12 in "
                "every device, not the generator (ROM as logic: %d gates; UA 60553's generator: %d), so going "
                "ROM-free does not lengthen it; the devices' depths differ by ABC's mapping, not by design.\n" % (
                    g("gen_rom", "depth_gates"), g("gen_linear", "depth_gates")))


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--out", required=True)
    ap.add_argument("--formats", required=True)
    ap.add_argument("--terms", required=True)
    ap.add_argument("--hand", default=None, help="out/hw_cost.csv of the accuracy study")
    args = ap.parse_args()
    fmt, terms = macros(args.formats), macros(args.terms)
    hand = hand_counts(args.hand, fmt, terms)
    with open(os.path.join(args.out, "variants.txt")) as f:
        names = [line.strip() for line in f if line.strip()]

    rows, failed = [], []
    for name in names:
        if name.endswith("_bits"):
            continue
        st = parse_stat(os.path.join(args.out, "logs", name + ".stat"))
        depth = parse_ltp(os.path.join(args.out, "logs", name + ".ltp"))
        if st["cells"] is None or depth is None:
            failed.append(name)
            continue
        mem = parse_stat(os.path.join(args.out, "logs", name + "_bits.stat"))["memory_bits"]
        if name == "ua22802_rom_as_memory":
            mem = parse_stat(os.path.join(args.out, "logs", "rom_f%s_bits.stat" % fmt["UA22802_A_FRAC"]))["memory_bits"]
        if name.startswith("rom_f"):
            desc = "ROM alone, F = %s fraction bits (%d-bit words)" % (
                name[5:], int(fmt["UA22802_A_W"]) - int(fmt["UA22802_A_FRAC"]) + int(name[5:]))
        else:
            desc = DESCRIPTIONS.get(name) or phong_description(name) or name
        h = hand.get(name)
        cells = st["cells"] - st["blackboxes"]
        rows.append({
            "variant": name, "description": desc,
            "hand_rom_bits": h[0] if h else "", "hand_mult_cells": h[1] if h else "",
            "hand_adder_bits": h[2] if h else "", "hand_gates": h[3] if h else "",
            "cells": cells, "flip_flops": st["ffs"], "comb_cells": cells - st["ffs"],
            "transistors": st["transistors"] if st["transistors"] is not None else "",
            "depth_gates": depth, "memory_bits": mem if mem is not None else "",
        })

    fields = ["variant", "description", "hand_rom_bits", "hand_mult_cells", "hand_adder_bits", "hand_gates",
              "cells", "flip_flops", "comb_cells", "transistors", "depth_gates", "memory_bits"]
    with open(os.path.join(args.out, "synth.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)

    by = {r["variant"]: r for r in rows}
    with open(os.path.join(args.out, "synth.md"), "w") as f:
        f.write("# Hardware cost by synthesis\n\n")
        f.write("yosys `synth -flatten`, then `abc -fast -g AND,NAND,OR,NOR,XOR,XNOR,ANDNOT,ORNOT,MUX` (a generic "
                "gate library) and `stat -tech cmos`; depth = `ltp -noff` (gates on the longest path between "
                "flip-flops and pins). Hand count: our cost table's rules (ROM bits / multiplier cells / adder "
                "bits / gates; registers not counted). Memory bits: the ROM's case table read as a memory "
                "(yosys proc_rom).\n\n")
        f.write("| variant | hand: ROM bits / mult cells / adder bits / gates | cells (flip-flops) | transistors | "
                "depth (gates) | ROM as memory bits |\n|---|---|---|---|---|---|\n")
        for r in rows:
            hand_txt = "%s / %s / %s / %s" % (r["hand_rom_bits"], r["hand_mult_cells"], r["hand_adder_bits"],
                                              r["hand_gates"]) if r["hand_rom_bits"] != "" else "—"
            f.write("| %s | %s | %d (%d) | %s | %d | %s |\n" % (
                r["description"], hand_txt, r["cells"], r["flip_flops"], r["transistors"], r["depth_gates"],
                r["memory_bits"] if r["memory_bits"] != "" else "—"))
        rom, free, mem = by.get("ua22802"), by.get("ua60553_saturate"), by.get("ua22802_rom_as_memory")
        if rom and free and mem and mem["memory_bits"] != "":
            f.write("\nThe patent's claim, in numbers: UA 60553 (saturating) costs %d transistors against UA 22802's "
                    "%d with the ROM built as logic (%.2fx) and %d outside a %d-bit ROM array (at one transistor "
                    "per bit, %d in all: %.2fx). Critical path: %d gates against %d.\n" % (
                        free["transistors"], rom["transistors"], rom["transistors"] / free["transistors"],
                        mem["transistors"], mem["memory_bits"], mem["transistors"] + mem["memory_bits"],
                        (mem["transistors"] + mem["memory_bits"]) / free["transistors"],
                        free["depth_gates"], rom["depth_gates"]))
    write_differences(args.out, by, fmt)
    paths = read_paths(args.out, names)
    write_comparison(args.out, by, paths)
    write_sqmul_designs(args.out, by, paths)
    write_pipeline(args.out, by, paths)
    bad = write_memories(args.out, names, fmt)

    # Every ROM read as a memory must hold exactly words x word bits of the format tables
    # (ua22802_formats.h via shading_formats.vh): the device's ROM (F = 6) is UA22802_ROM_BITS.
    words, a_int = int(fmt["UA22802_ROM_WORDS"]), int(fmt["UA22802_A_W"]) - int(fmt["UA22802_A_FRAC"])
    for name in names:
        m = re.match(r"rom_f(\d+)_bits$", name)
        if not m:
            continue
        frac = int(m.group(1))
        want = int(fmt["UA22802_ROM_BITS"]) if frac == int(fmt["UA22802_A_FRAC"]) else words * (a_int + frac)
        got = parse_stat(os.path.join(args.out, "logs", name + ".stat"))["memory_bits"]
        if got != want:
            bad.append(name)
            print("synth: %s: the ROM read as a memory has %s bits, the format tables say %d" % (name, got, want),
                  file=sys.stderr)
    # The cell unit's memories: rtl/blocks/ram.v's column buffers, each CELL_BUF_DEPTH words of a
    # sample (interp_terms.vh, interp_formats.h), as many as the black boxes in its logic row.
    if "cell_unit_bits" in names and "cell_unit" in by:
        boxes = parse_stat(os.path.join(args.out, "logs", "cell_unit.stat"))["blackboxes"]
        want = boxes * int(terms["CELL_BUF_DEPTH"]) * int(fmt["INTERP_SAMPLE_W"])
        got = by["cell_unit"]["memory_bits"]
        if got != want:
            bad.append("cell_unit_bits")
            print("synth: cell_unit_bits: %s memory bits, %d column buffers of %s words x %s bits say %d" % (
                got, boxes, terms["CELL_BUF_DEPTH"], fmt["INTERP_SAMPLE_W"], want), file=sys.stderr)
    for name in failed:
        print("synth: no result for %s (see logs/%s.log)" % (name, name), file=sys.stderr)
    print("synth: wrote %s/synth.csv and synth.md (%d variants)" % (args.out, len(rows)))
    return 1 if failed or bad else 0


def memory_want(name, fmt):
    """The bits the format tables give a memory row (mem_<what>[_<size>]_bits), or None."""
    m = re.match(r"mem_(frame_buffer|band_buffer)_(\d+)_bits$", name)
    if m:
        pitch = 1 << (int(m.group(2)) - 1).bit_length()
        if m.group(1) == "frame_buffer":
            return pitch * int(m.group(2)) * int(fmt["PIPELINE_FRAME_WORD_W"])
        return int(fmt["PIPELINE_BAND_LINES"]) * pitch * int(fmt["PIPELINE_BAND_WORD_W"])
    if name == "mem_walker_store_bits":
        return (int(fmt["PIPELINE_WALKER_SLOTS"]) << int(fmt["PIPELINE_WALKER_WORD_AW"])) * int(fmt["PIPELINE_WALKER_WORD_W"])
    return None


def write_memories(out, names, fmt):
    """memories.csv and synth.md's last table: each memory row's bits (yosys proc, not mapped), which must
    be the words x bits its format tables give. Returns the rows that differ."""
    rows, bad = [], []
    for name in names:
        want = memory_want(name, fmt)
        if want is None:
            continue
        got = parse_stat(os.path.join(out, "logs", name + ".stat"))["memory_bits"]
        rows.append((name[4:-5], got, want))
        if got != want:
            bad.append(name)
            print("synth: %s: %s memory bits, the format tables say %d" % (name, got, want), file=sys.stderr)
    if not rows:
        return bad
    with open(os.path.join(out, "memories.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["memory", "memory_bits", "format_bits"])
        w.writerows(rows)
    with open(os.path.join(out, "synth.md"), "a") as f:
        f.write("\n## Memories (rtl/blocks/ram.v's arrays read by proc, not mapped)\n\n| memory | bits | the format "
                "tables' words x bits |\n|---|---|---|\n")
        for r in rows:
            f.write("| %s | %s | %d |\n" % r)
    return bad


if __name__ == "__main__":
    sys.exit(main())
