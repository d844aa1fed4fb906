#!/usr/bin/python3
"""Simulation speed of every model: runs build/bin/perf_models (Google Benchmark; each
SystemC case in its own process) and prints one table: model, rate, ratio to its golden model, the
speed target set for it where there is one, and whether it is met. Markdown with --markdown (the README's
"Simulation speed" section quotes it).

  scripts/bench.py [--build DIR] [--quick] [--filter REGEX] [--min-time S] [--json FILE] [--markdown]

Floor rows (floor/*: the harnesses with nothing inside, testbenches/perf/perf_floor.cpp) bound
what any model in that harness can reach; an unmet target whose harness has a floor gets a
footnote with it.

Exit status: 0 when the program ran clean (no mismatch, no failed case), whatever the targets say;
1 otherwise. Targets are reported, not enforced: speed depends on the machine.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def fmt_rate(v):
    if v >= 1e6:
        return f"{v / 1e6:.3g}·10⁶"
    if v >= 1e3:
        return f"{v:,.0f}".replace(",", " ")
    return f"{v:.3g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap.add_argument("--build", default=os.path.join(root, "build"), help="build folder (default build/)")
    ap.add_argument("--quick", action="store_true", help="tiny runs (a smoke test, figures meaningless)")
    ap.add_argument("--filter", default="", help="--benchmark_filter for perf_models")
    ap.add_argument("--min-time", default="", help="--benchmark_min_time per case, seconds (default 0.5)")
    ap.add_argument("--json", default="", help="keep perf_models' JSON here")
    ap.add_argument("--markdown", action="store_true", help="print the table as Markdown")
    a = ap.parse_args()

    prog = os.path.join(a.build, "bin", "perf_models")
    if not os.access(prog, os.X_OK):
        sys.exit(f"{prog} not found: build it first (cmake --build {a.build} --target perf_models)")
    out = a.json or tempfile.mkstemp(suffix=".json")[1]
    cmd = [prog, f"--benchmark_out={out}", "--benchmark_out_format=json"]
    if a.quick:
        cmd.append("--quick")
    if a.filter:
        cmd.append(f"--benchmark_filter={a.filter}")
    min_time = a.min_time or ("" if a.quick else "0.5")
    if min_time:
        cmd.append(f"--benchmark_min_time={min_time}")
    env = dict(os.environ, SYSTEMC_DISABLE_COPYRIGHT_MESSAGE="1")
    print("running:", " ".join(cmd[:1] + cmd[2:]), file=sys.stderr)
    rc = subprocess.call(cmd, env=env, stdout=sys.stderr)
    with open(out) as f:
        data = json.load(f)
    if not a.json:
        os.remove(out)

    for b in data["benchmarks"]:  # the suffixes Google Benchmark adds to a proxy's name
        b["name"] = b["name"].replace("/iterations:1", "").replace("/manual_time", "")
    rows = {b["name"]: b for b in data["benchmarks"]}

    def rate(name):
        b = rows.get(name)
        if not b or b.get("error_occurred"):
            return None
        return b.get("items_per_second")

    # The speed targets: (row, measured, goal text, met).
    targets = {}

    def target(name, value, goal, ok):
        targets[name] = (goal, ok, value)

    if rate("sc/ua60553/delays"):
        r = rate("sc/ua60553/delays")
        target("sc/ua60553/delays", r, "≥ 1.5·10⁶ ev/s (block level)", r >= 1.5e6)
    vl = rate("verilator/ua60553")
    for fast in ("sc/ua60553_fast/delays", "sc/ua60553_fast/no_delays"):
        if rate(fast):
            r = rate(fast)
            goal, ok = "≥ 4·10⁶ ev/s", r >= 4e6
            if vl:
                goal += f" and ≥ Verilator ({r / vl:.2f}×)"
                ok = ok and r >= vl
            else:
                goal += " (Verilator row missing)"
            target(fast, r, goal, ok)
    for hn in ("sc/interp_horner", "sc/interp_horner_fast"):
        h = rows.get(hn)
        if h and not h.get("error_occurred") and "clocks_per_second" in h:
            c = h["clocks_per_second"]
            target(hn, c, f"≥ 1.5·10⁶ clocks/s ({fmt_rate(c)} clocks/s)", c >= 1.5e6)
    for p in ("sc/pipeline_head/fd", "sc/pipeline_head/horner", "sc/pipeline_head/fd_fast",
              "sc/pipeline_head/horner_fast"):
        if rate(p):
            target(p, rate(p), "≥ 250 000 px/s", rate(p) >= 250000)
    for name in rows:
        if name.endswith("/traced"):
            base = name[: -len("/traced")]
            if rate(name) and rate(base):
                slow = rate(base) / rate(name)
                target(name, rate(name), f"≤ 5× untraced ({slow:.2f}×)", slow <= 5)

    # The floor under each target's harness (perf_floor.cpp): the rate of the harness alone, in the
    # target's own measure (clocks per second for the Horner unit).
    def floor_text(name):
        if name.startswith("sc/ua60553"):
            f, c = rate("floor/specular_harness"), rate("floor/sc_clock")
            if not f:
                return None
            t = f"floor {fmt_rate(f)} ev/s: the specular harness around a null device (`floor/specular_harness`)"
            if c:
                t += f"; its sc_clock alone {fmt_rate(c)} cycles/s (`floor/sc_clock`)"
            return t
        if name.startswith("sc/interp_horner") and not name.endswith("/traced"):
            f = rate("floor/horner_bench")
            if f:
                return (f"floor {fmt_rate(f)} clocks/s: the Horner bench's clock and processes with no work "
                        "(`floor/horner_bench`)")
        return None

    head = ["model", "rate /s", "unit", "ratio to golden", "target", "met?"]
    table = []
    notes = []  # footnotes: the floors under unmet targets
    marks = "¹²³⁴⁵⁶⁷⁸⁹"
    for b in data["benchmarks"]:
        name = b["name"]
        label = b.get("label", "")
        unit = label.split(";")[0] if label else ""
        if b.get("error_occurred"):
            table.append([name, "FAILED", unit, "", b.get("error_message", "")[:60], "no"])
            continue
        r = b.get("items_per_second", 0.0)
        ratio = b.get("vs_golden")
        ratio_s = f"1/{1 / ratio:.0f}" if ratio and ratio < 0.2 else (f"{ratio:.2f}" if ratio else "—")
        goal, ok, _ = targets.get(name, ("", None, None))
        met = "" if ok is None else ("yes" if ok else "no")
        if ok is False and floor_text(name):
            note = floor_text(name)
            if note not in notes:
                notes.append(note)
            met += marks[notes.index(note) % len(marks)]
        mism = b.get("mismatches", 0)
        if name.startswith("floor/"):
            ratio_s = "—"  # a harness with a null device: its outputs are not results
        elif mism:
            met = f"{int(mism)} MISMATCHES"
        table.append([name, fmt_rate(r), unit, ratio_s, goal, met])

    if a.markdown:
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
        for row in table:
            print("| " + " | ".join(f"`{c}`" if i == 0 else c for i, c in enumerate(row)) + " |")
    else:
        w = [max(len(str(r[i])) for r in table + [head]) for i in range(len(head))]
        print("  ".join(h.ljust(w[i]) for i, h in enumerate(head)))
        for row in table:
            print("  ".join(str(c).ljust(w[i]) for i, c in enumerate(row)))
    if notes:
        print()
        for i, n in enumerate(notes):
            print(f"{marks[i % len(marks)]} {n}" + ("  " if a.markdown and i + 1 < len(notes) else ""))
    ctx = data.get("context", {})
    print(f"\n{ctx.get('num_cpus', '?')} CPUs at {ctx.get('mhz_per_cpu', '?')} MHz, "
          f"{ctx.get('library_build_type', '')} Google Benchmark, {ctx.get('date', '')}")
    return 0 if rc == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
