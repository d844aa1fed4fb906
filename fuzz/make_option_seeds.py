#!/usr/bin/env python3
"""Writes fuzz_options' hand-written seeds (fuzz/corpus/fuzz_options/<program>_<what>): per program, a
few command lines from its ctest entries and its documented examples, encoded as fuzz_options.cpp
decodes its input (first byte: the program's index in its table, then the arguments, each ended by
a NUL byte). Rerun after changing that table; the files are committed."""
import os

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "fuzz_options")
# fuzz_options.cpp's table, in its order.
PROGRAMS = ["interp_coef_tb", "ua60553_tb", "interp_fd_tb", "ua22802_tb", "interp_horner_tb", "squared_tb",
            "interp_line_tb", "interp_study", "soak_pipeline", "render_reference", "bench_specular_tlm",
            "accuracy_study", "generator_search", "head_study", "render_pipeline", "bench_line_tlm",
            "components_study", "edge_study", "two_line_study", "cell_study", "render_cells", "sqmul_tb"]
BENCH = {  # what every bench's ctest entries pass (cmake/shading.cmake, shading_add_bench)
    "default": "--no-vcd",
    "inject": "--no-vcd --inject-mismatch 3",
    "inject256": "--random 300 --inject-mismatch 0 --inject-count 256",
    "usage": "--no-such-option",
}
SEEDS = {
    "interp_coef_tb": {"csv": "--csv out/interp_div3.csv --extra-sets 2000 --no-vcd", "random": "--random 3000 --seed 1",
                       "m9": "--m 9"},
    "ua60553_tb": {"sweep": "--sweep --no-vcd", "random": "--random 3000 --seed 7 --generator minimax --mode wrap",
                   "fast": "--random 3000 --seed 1 --abstraction fast --zero-delays", "timing": "--t-low-ns 7.5 --t-high-ns 2 --n 10 --n 1000"},
    "interp_fd_tb": {"csv": "--m 6 --csv out/interp_fd.csv", "random": "--random 3000 --seed 7 --m 6 --jobs 2"},
    "ua22802_tb": {"random": "--random 3000 --seed 1 --mode wrap", "fast": "--abstraction fast --pixels 8 --n 0 --n 1023"},
    "interp_horner_tb": {"gap": "--random 3000 --seed 7 --gap 2", "fast": "--abstraction fast --csv out/h.csv --width 64"},
    "squared_tb": {"sweep": "--sweep --no-vcd", "fast": "--random 3000 --abstraction fast --mode wrap",
                   "clk": "--clk-ns 2.5 --scene-pixels 4 --n 1,3"},
    "sqmul_tb": {"sweep": "--sweep --no-vcd", "fast": "--random 3000 --abstraction fast --mode wrap",
                 "clk": "--clk-ns 2.5 --scene-pixels 4 --n 1,3"},
    "interp_line_tb": {"exact": "--case 2 --div3 exact --m 4 --no-vcd", "random": "--random 3000 --seed 7 --div3 SHIFT-ADD"},
    "interp_study": {"short": "--csv interp_study_smoke.csv --width 64", "usage": "--width not-a-number"},
    "soak_pipeline": {"short": "--renders 2 --size 8", "usage": "--renders 1"},
    "render_reference": {"head": "--size 64 --out out/scene_test", "compare": "--size 64 --n 20 --compare patent,squared",
                         "bad_compare": "--size 64 --compare patent,teapot", "scales": "--error-scale 2 --depth-step 0.5 --mode wrap"},
    "bench_specular_tlm": {"smoke": "--lt-pixels 100000 --pin-pixels 2000",
                           "squared": "--device squared --lt-pixels 100000 --pin-pixels 2000", "usage": "--lt-pixels many"},
    "accuracy_study": {"short": "--n-max 12 --size 64 --out .", "fig2": "--fig2-n 500 --n-max 20", "usage": "--n-max 0"},
    "generator_search": {"short": "--csv generator_search_smoke.csv --keep 0.03", "usage": "--keep not-a-number"},
    "head_study": {"short": "--size 64 --n 2,20 --scan-max 30 --out .", "usage": "--size 64 --n 1001 --out ."},
    "render_pipeline": {"head48": "--scene head --size 48 --sim --out out/p",
                        "sweep": "--sweep --grid claims --scenes sphere torus --lights 0,30 --ns 20 --sizes 24 --device squared --jobs 2 --shard 1/2",
                        "adaptive": "--length adaptive --m-min 2 --m-max 5 --length-tol 0.5 --degree adaptive --no-exact-fallback --above-slack 2 --lit-guard",
                        "geometry": "--length geometry --lobe-tol 2 --eval fd --set case2 --div3 exact --unit scratch --abstraction fast",
                        "n": "--n ten", "available": "--sim-available"},
    "bench_line_tlm": {"smoke": "--lt-pixels 200000 --pin-pixels 8192", "burst": "--lt-pixels 64000 --pin-pixels 3200 --burst 1",
                       "usage": "--lt-pixels 12x"},
    "components_study": {"short": "--size 48 --tol-sum 1,2 --tol-diffuse 1 --tol-specular 1,2 --m-max-specular 4",
                         "scene": "--scene torus --device patent --nmse 1e-4", "usage": "--m-max-diffuse 7"},
    "edge_study": {"short": "--size 48 --spacing 2,4", "scene": "--scene sphere --device ua22802 --spacing 64",
                   "usage": "--spacing 3"},
    "two_line_study": {"short": "--size 48 --tol-one 1,2 --tol-even 1 --tol-odd 1,2 --tol-mid 1",
                       "scene": "--scene torus --device patent --nmse 1e-4 --m-max 6 --above-slack -1 --walk-edges --perfect-decisions", "empty": "--tol-odd=",
                       "usage": "--m-max 7"},
    "cell_study": {"short": "--size 48 --tol 1,2",
                   "scene": "--scene sphere --light 35,20 --n 100 --device patent --nmse 1e-4 --d2-factor 6 --d3-factor 2 --fallback-tol 2 --line-tol 1 --cell-max 64 --m-max 6 --walk-edges --perfect-decisions",
                   "empty": "--tol=", "nan": "--d3-factor nan", "light": "--light 10", "usage": "--cell-max 48"},
    "render_cells": {"short": "--size 96 --tol 1",
                     "scene": "--scene torus --light 35,20 --n 100 --device patent --size 1024 --tol 2 --walk-edges",
                     "nan": "--tol nan", "light": "--light 10", "usage": "--size 8"},
}


def write(name, program, line):
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(bytes([PROGRAMS.index(program)]) + b"".join(a.encode() + b"\0" for a in line.split()))


os.makedirs(OUT, exist_ok=True)
for p in PROGRAMS:
    if p.endswith("_tb"):
        for what, line in BENCH.items():
            write(f"{p}_{what}", p, line)
    for what, line in SEEDS[p].items():
        write(f"{p}_{what}", p, line)
    write(f"{p}_help", p, "--help")
# Lines that once failed the target (a ctest entry each, fuzz/CMakeLists.txt): "nan" passed CLI11's
# numeric checks, which compare.
write("crash-nan_positive", "ua60553_tb", "--t-low-ns nan")
write("crash-nan_range", "squared_tb", "--clk-ns NaN")
write("crash-nan_tolerance", "render_pipeline", "--length adaptive --length-tol nan")
print("wrote the seeds of", len(PROGRAMS), "programs to", OUT)
