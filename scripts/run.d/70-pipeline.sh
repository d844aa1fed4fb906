#!/usr/bin/env bash
# The interpolation paper's shading system on the head scan at 512x512 (render_pipeline): the program's
# default plan (fixed 16-pixel intervals, cubic, Horner unit) with UA 60553 with the patent's constants,
# adaptive length and degree through the Horner unit and through the forward differences (also at
# 1024x1024), and the interpolation paper's zone policy, each through the golden model and the SystemC
# pipeline (which must agree bit for bit), PNGs and report.md/report.json in $SHADING_OUT/pipeline/<case>/.
# The sweeps over policies, evaluators, devices and n are the pipeline study's (studies/pipeline/README.md
# gives their commands), not run here.
# One summary row per render: samples = covered pixels, mismatches = SystemC vs golden, max_error =
# the interpolation's NMSE (vs per-pixel shading through the same device), cycles_per_pixel =
# simulated clocks per pixel. The default plan runs twice: block level and the fast pin-level
# abstraction (--abstraction fast). Every render names its device (--device), so that the rows the
# pages quote stay those of the device they name whatever the program's default.
set -euo pipefail
cd "$(dirname "$0")/../.."
bin="$SHADING_BIN/render_pipeline"
out="$SHADING_OUT/pipeline"
size=512
mkdir -p "$out"
# The SystemC pipeline runs beside the golden model when this build has it (it always should; a
# build without it renders golden-only and says so in the rows).
sim=--sim
"$bin" --sim-available || { sim=--no-sim; echo "70-pipeline: no SystemC pipeline in this build: golden model only" >&2; }

summary() {  # case folder -> one row from its report.json
  /usr/bin/python3 - "$1" "$2" >> "$SHADING_SUMMARY" <<'EOF'
import json, sys
case, folder = sys.argv[1], sys.argv[2]
j = json.load(open(folder + "/report.json"))
e, ops, sim = j["errors"], j["ops_per_pixel"], j["sim"]
hw, ph = ops["hardware"]["total"]["long"], ops["phong"]["total"]["long"]
cpp = sim["clocks_per_pixel"] if sim["ran"] else j["clocks_per_pixel"]["hardware_ops"]
note = (f"NMSE vs per-pixel device {e['interpolation']['image']['nmse']:.2e} (max {e['interpolation']['image']['max_abs']:.1f} lv), "
        f"vs Phong {e['total']['image']['nmse']:.2e}, device vs Phong {e['brdf']['image']['nmse']:.2e}; "
        f"long ops/pixel {hw:.1f} vs Phong {ph:.1f} ({ops['phong_long_over_hardware_long']:.2f}x), "
        f"vs scan-line Phong {ops['phong_scanline']['total']['long']:.1f} "
        f"({ops['scanline_phong_long_over_hardware_long']:.2f}x)")
if sim["ran"]:
    note += (f"; sim ({sim.get('abstraction', 'block')}) {sim['pixels_per_second']:.0f} px/s wall, "
             f"{sim.get('pixels_per_cpu_second', 0):.0f} px per CPU second")
else:
    note += "; golden only"
print("\t".join(["pipeline_head", case, str(j["plan"]["pixels"]), str(sim["mismatches"]) if sim["ran"] else "-",
                 f"{e['interpolation']['image']['nmse']:.3e}", f"{cpp:.3f}", note]))
EOF
}

render() {  # case, then render_pipeline's options
  local case=$1
  shift
  "$bin" --scene head --size "$size" "$sim" --out "$out/$case" "$@"
  summary "${case%_1024}_${size}" "$out/$case"
}

render default --device patent
# The same through the fast pin-level pipeline (modules/pipeline/shading_pipeline_fast.h: the same pins
# and timing, one process; bit-exact against the golden frame too): the simulator's speed.
render default_fast --device patent --abstraction fast
render adaptive --length adaptive --degree adaptive --device minimax
render adaptive_fd --device patent --length adaptive --degree adaptive --eval fd
# The same at 1024x1024, where our target is met (NMSE <= 1e-5 with >= 3x fewer long operations).
size=1024 render adaptive_fd_1024 --device patent --length adaptive --degree adaptive --eval fd
# The squared-quadratic device (ours) at n = 20: the image within NMSE 1e-5 of exact Phong at
# 2x fewer long operations than the counted Phong (modules/squared/README.md).
render squared_fd --device squared --n 20 --length adaptive --length-tol 0.9 --degree adaptive --degree-tol 0.25 --eval fd
# The interpolation paper's own policy: quadratic in its zones 2, 4, 7, cubic elsewhere, one interval length.
render zones --degree zones --m 3 --device ua22802

