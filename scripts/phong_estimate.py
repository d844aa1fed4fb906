#!/usr/bin/env python3
"""A per-pixel Phong shader priced from the project's block library, beside the shading pipeline: an
ESTIMATE, not a built design (modules/pipeline/README.md, "A per-pixel Phong shader, estimated").

Phong 1975 with the square-and-multiply device (the race's `phong1975_device`) does per pixel the
operations render_race counts by kind (race_ops.csv: multiplications, divisions, square roots,
additions; the device's own operations apart, as device samples). Each kind is priced as the
synthesized block that performs it (out/synth/synth.csv, rows phong_*: scripts/synth.sh):
  mul   phong_mul_<W>      a signed W x W multiplier (W = sign + the device's cosine fraction bits)
  add   phong_add_<A>      a signed A-bit adder (the pipeline's stepping width)
  div   a restoring array divider: one stage per quotient bit, each an inverter bank, a subtractor
        and a multiplexer (rows phong_stage_inv_<W+1>, phong_stage_sub_<W+1>, phong_stage_mux_<W>)
  sqrt  a restoring array square root, priced as the divider's array (its stages are no wider)
  the device: its own row (sqmul_saturate), one sample per its clocks per sample
Comparisons (with 0: sign tests) are not priced, nor the registers between units (a lower bound).
Delays: the SystemC delay model's (modules/core/comb_delay.h: the multiplier, the adder, the
multiplexer, the inverter), the array's the sum of its stages'.

Both designs run at the pipeline's clock (timing_report's 50 % duty period). Phong takes a pixel a
clock: one unit per operation a pixel (an average count: units shared by set-ups and run starts), an
array longer than the clock split into stages; as many devices as its clocks per sample times the
device samples a pixel. The pipeline: its synthesized top (pipeline_fd_var, pipeline_horner) at its
clocks a pixel (render_pipeline's report.json, the race's frozen lines), plus its geometry side (the
planner's operations, race_ops.csv `lines,geometry`) priced as Phong's, units for the operations
a clock. Area x time a pixel = area x clock x clocks a pixel. Errors: the race's total NMSE against
exact Phong (race.csv; the pipeline's report for each evaluator).

  scripts/phong_estimate.py [--race out/race] [--synth out/synth] [--timing out/timing_report.txt]
                            [--fd out/pipeline/race_fd/report.json] [--horner out/pipeline/race_horner/report.json]
"""
import argparse
import csv
import json
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "synth"))
from summarize import CLOCKS  # noqa: E402  (the square-and-multiply device's clocks per sample)

KINDS = ("mul", "div", "sqrt", "add")
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def delays_ns(path):
    """delay_default's block delays (ns) from modules/core/comb_delay.h."""
    out = {}
    with open(path) as f:
        for m in re.finditer(r"sc_time (\w+)\{(\d+), sc_core::SC_PS\}", f.read()):
            out[m.group(1)] = int(m.group(2)) / 1000.0
    return out


def synth_rows(path):
    """{variant: (transistors, depth in gates)} of synth.csv."""
    with open(path) as f:
        return {r["variant"]: (int(r["transistors"]), int(r["depth_gates"])) for r in csv.DictReader(f)}


def rows_by_prefix(rows, prefix):
    """The rows named <prefix><width>: [(width, transistors, depth)], narrowest first."""
    return sorted((int(v[len(prefix):]), t, d) for v, (t, d) in rows.items() if re.fullmatch(re.escape(prefix) + r"\d+", v))


def row_by_prefix(rows, prefix):
    """The one row named <prefix><width>: (width, transistors, depth)."""
    hits = rows_by_prefix(rows, prefix)
    if len(hits) != 1:
        raise SystemExit("phong_estimate: want one synth row %s<width>, found %d" % (prefix, len(hits)))
    return hits[0]


def units(rows, dl, mul_width=None):
    """Each kind's unit, the multiplier of mul_width bits (None: the narrowest): {kind: (name,
    transistors, depth in gates, delay in ns)}."""
    muls = rows_by_prefix(rows, "phong_mul_")
    if not muls:
        raise SystemExit("phong_estimate: no synth row phong_mul_<width>")
    wm, tm, dm = next(m for m in muls if mul_width in (None, m[0]))
    wa, ta, da = row_by_prefix(rows, "phong_add_")
    _, ti, di = row_by_prefix(rows, "phong_stage_inv_")
    ws, tsub, dsub = row_by_prefix(rows, "phong_stage_sub_")
    stages, tmux, dmux = row_by_prefix(rows, "phong_stage_mux_")
    stage_ns = dl["inverter"] + dl["adder"] + dl["mux"]
    array = (stages * (ti + tsub + tmux), stages * (di + dsub + dmux), stages * stage_ns)
    return {
        "mul": ("%d x %d multiplier" % (wm, wm), tm, dm, dl["multiplier"]),
        "add": ("%d-bit adder" % wa, ta, da, dl["adder"]),
        "div": ("array divider, %d stages of %d bits" % (stages, ws),) + array,
        "sqrt": ("array square root, as the divider",) + array,
    }


def estimate(phong, geometry, unit, device, clock_ns, pipelines):
    """The estimate's arithmetic, in plain numbers (phong_estimate_test.py checks it by hand).
    phong, geometry: {kind: operations a pixel}, phong also "samples" (device samples a pixel);
    unit: {kind: (name, transistors, depth, ns)}; device: (transistors, clocks per sample);
    pipelines: {name: (top transistors, clocks a pixel)}. Returns {design: (area, clocks a pixel,
    ns a pixel, area x ns a pixel)}."""
    out = {}
    area = sum(phong[k] * unit[k][1] for k in KINDS) + phong["samples"] * device[1] * device[0]
    out["phong"] = (area, 1.0, clock_ns, area * clock_ns)
    for name, (top, clocks) in pipelines.items():
        area = top + sum(geometry[k] / clocks * unit[k][1] for k in KINDS)
        out[name] = (area, clocks, clocks * clock_ns, area * clocks * clock_ns)
    return out


def read_ops(path):
    """race_ops.csv: {(scheme, part): {kind: count, pixels, samples}}."""
    with open(path) as f:
        return {(r["scheme"], r["part"]): {k: int(v) for k, v in r.items() if k not in ("scheme", "part")}
                for r in csv.DictReader(f)}


def pipeline_period(path, evaluator):
    """timing_report's 50 % duty period (ns) of shading_pipeline<sqmul_device, evaluator>."""
    with open(path) as f:
        text = f.read()
    m = re.search(r"shading_pipeline<sqmul_device, %s>.*?shortest period: 50 %% duty ([\d.]+) ns" % evaluator, text, re.S)
    if not m:
        raise SystemExit("phong_estimate: no period of shading_pipeline<sqmul_device, %s> in %s" % (evaluator, path))
    return float(m.group(1))


def report_clocks(path):
    """render_pipeline's report.json: (clocks a pixel of the simulation, total NMSE)."""
    with open(path) as f:
        j = json.load(f)
    return j["clocks_per_pixel"]["sim"], j["errors"]["total"]["image"]["nmse"]


def grouped(v):
    """An integer with its thousands apart, as the pages write them: 1 005 569."""
    return "{:,}".format(int(round(v))).replace(",", " ")


def print_tables(phong, geometry, rows, dl, device, clock, pipes, errors):
    """The page's two tables: the units, and the designs at each multiplier width."""
    widths = [m[0] for m in rows_by_prefix(rows, "phong_mul_")]
    us = [units(rows, dl, w) for w in widths]
    alt = lambda k, i, f: f(us[0][k][i]) + "".join(" (%s)" % f(u[k][i]) for u in us[1:])  # noqa: E731
    print("| unit (an estimate) | a pixel: Phong / the lines' geometry side | transistors | depth (gates) | delay |")
    print("|---|---|---|---|---|")
    print("| multiplier %s | %.2f / %.2f | %s | %s | %.1f ns |" % (
        " (".join("%d × %d" % (w, w) for w in widths) + ")" * (len(widths) - 1), phong["mul"], geometry["mul"],
        alt("mul", 1, grouped), alt("mul", 2, str), us[0]["mul"][3]))
    print("| %s; square root the same array | %.2f, %.2f / %.2f, %.2f | %s | %d | %.1f ns |" % (
        us[0]["div"][0], phong["div"], phong["sqrt"], geometry["div"], geometry["sqrt"], grouped(us[0]["div"][1]),
        us[0]["div"][2], us[0]["div"][3]))
    print("| %s | %.2f / %.2f | %s | %d | %.1f ns |" % (
        us[0]["add"][0], phong["add"], geometry["add"], grouped(us[0]["add"][1]), us[0]["add"][2], us[0]["add"][3]))
    print("| the device (`sqmul_saturate`) | %.3f samples / in the top | %s | %d | %d clocks a sample |\n" % (
        phong["samples"], grouped(device[0]), rows["sqmul_saturate"][1], device[1]))
    est = [estimate(phong, geometry, u, device, clock, pipes) for u in us]
    what = {"phong": "Phong 1975, a pixel a clock, %.1f devices" % (phong["samples"] * device[1]),
            "pipeline_fd_var": "pipeline, forward differences, + geometry side",
            "pipeline_horner": "pipeline, Horner, + geometry side"}
    w = " / ".join(str(x) for x in widths)
    print("| design (an estimate, at %.1f ns) | transistors, %s-bit multipliers | clocks / px | ns / px | "
          "transistor·ms / px, %s | total NMSE |" % (clock, w, w))
    print("|---|---|---|---|---|---|")
    for d in est[0]:
        print("| %s | %s | %.3f | %.1f | %s | %.2e |" % (
            what[d], " / ".join(grouped(e[d][0]) for e in est), est[0][d][1], est[0][d][2],
            " / ".join("%.1f" % (e[d][3] / 1e6) for e in est), errors[d]))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--race", default="out/race")
    ap.add_argument("--synth", default="out/synth")
    ap.add_argument("--timing", default="out/timing_report.txt", help="build/bin/timing_report's output")
    ap.add_argument("--fd", default="out/pipeline/race_fd/report.json")
    ap.add_argument("--horner", default="out/pipeline/race_horner/report.json")
    a = ap.parse_args()
    ops = read_ops(os.path.join(a.race, "race_ops.csv"))
    with open(os.path.join(a.race, "race.csv")) as f:
        race = {r["scheme"]: r for r in csv.DictReader(f) if r["frozen"] == "1"}
    with open(os.path.join(a.race, "race.md")) as f:
        n = int(re.search(r"n = (\d+)", f.readline()).group(1))
    rows = synth_rows(os.path.join(a.synth, "synth.csv"))
    dl = delays_ns(os.path.join(ROOT, "modules/core/comb_delay.h"))
    unit = units(rows, dl)
    shader, dev, geo = ops[("phong1975_device", "shader")], ops[("phong1975_device", "device")], ops[("lines", "geometry")]
    px = shader["pixels"]
    phong = {k: shader[k] / px for k in KINDS}
    phong["samples"] = dev["samples"] / px
    geometry = {k: geo[k] / geo["pixels"] for k in KINDS}
    device = (rows["sqmul_saturate"][0], CLOCKS["sqmul_saturate"](n))
    clock = pipeline_period(a.timing, "fd")
    if pipeline_period(a.timing, "horner") != clock:
        raise SystemExit("phong_estimate: the two evaluators' periods differ; one clock is assumed")
    fd, horner = report_clocks(a.fd), report_clocks(a.horner)
    pipes = {"pipeline_fd_var": (rows["pipeline_fd_var"][0], fd[0]),
             "pipeline_horner": (rows["pipeline_horner"][0], horner[0])}
    print_tables(phong, geometry, rows, dl, device, clock, pipes,
                 {"phong": float(race["phong1975_device"]["nmse_frame_buffer"]), "pipeline_fd_var": fd[1],
                  "pipeline_horner": horner[1]})
    stage = ops[("lines", "sample_stage")]
    ratios = []
    for m in rows_by_prefix(rows, "phong_mul_"):
        e = estimate(phong, geometry, units(rows, dl, m[0]), device, clock, pipes)
        ratios.append("%.2f" % (e["phong"][3] / e["pipeline_fd_var"][3]))
    print("\nThe head at %d pixels, n = %d; the race's lines: total NMSE %s (race.csv). Phong's area x time over the "
          "forward-difference pipeline's: %s (by multiplier width); the pipeline's top alone: %.1f transistor-ms a pixel, "
          "its sample stage %.3f samples a pixel." % (
              px, n, race["lines"]["nmse_frame_buffer"], " / ".join(ratios),
              pipes["pipeline_fd_var"][0] * fd[0] * clock / 1e6, stage["samples"] / stage["pixels"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
