#!/usr/bin/env bash
# Hardware cost by synthesis: every variant of the RTL twin (rtl/) synthesized by yosys
# to a generic gate library (yosys's simple gates: NOT, AND, NAND, OR, NOR, XOR, XNOR, ANDNOT,
# ORNOT, MUX, and flip-flops), flattened. Per variant: cells, flip-flops, the transistor estimate
# of `stat -tech cmos`, and the critical path's depth in gates (`ltp -noff`: the longest path
# between flip-flops and pins). Flip-flops with an enable or a synchronous reset are split into a
# plain flip-flop and its multiplexer logic before mapping (dffunmap), so that `stat -tech cmos`,
# which has no transistor count for them, counts every cell. The clocked designs' paths of each
# kind (register to register, strobe to register, register to outputs) are measured apart (paths.csv). UA 22802's ROM is synthesized as logic and, separately, counted
# as memory bits (the case table read as a memory by yosys's proc_rom), also at every size of the
# accuracy study's fraction-bit sweep; the square-and-multiply designs also at other P words (the
# generated formats of sqmul_word/p<F>/ first on the include path). The shading pipeline
# (rtl/pipeline/) unit by unit and whole, with each evaluator, its paths of each kind measured as
# well; with --extra the cell unit, its column buffers kept out of the logic (black boxes) and
# counted as memory bits (read as memories by proc), as UA 22802's ROM. Writes, in the output folder:
#   synth.csv, synth.md   one row per variant, beside our hand count (out/hw_cost.csv when
#                         scripts/run.sh's accuracy step wrote it) - scripts/synth/summarize.py;
#                         synth.md ends with the squared-quadratic device's comparison table and
#                         the square-and-multiply designs' table, then the shading pipeline's
#                         units beside its whole top
#   paths.csv             the depth of each measured path of the clocked designs
#   memories.csv          the memories alone (frame buffer, band buffer at 512 and 1024, walker
#                         store): bits counted, not mapped, beside the format tables' words x bits
#   ys/<variant>.ys       the yosys script of each variant (rerun one: yosys -s ys/<variant>.ys)
#   logs/<variant>.log    yosys's log
# Usage: scripts/synth.sh [--build DIR] [--out DIR] [--jobs N] [--only REGEX] [--extra]
#   --build  the configured build tree holding generated/rtl (default build/): the widths
#            (shading_formats.vh), the term tables (interp_terms.vh) and the ROMs (ua22802_a_rom.v,
#            rom_sweep/) are generated there when CMake configures with Verilator installed
#   --out    default out/synth;  --jobs  yosys runs in parallel (default 2)
#   --only   synthesize only the variants whose name matches (grep -E), e.g. 'rom_f6|horner'
#   --extra  also the coefficient unit with the exact /3 (a generic divider: about 3 CPU minutes)
#            and the cell unit (12 forward-difference channels for any m: about a CPU minute)
# Exit status: 0 done, 1 a yosys run failed, 2 bad usage or missing inputs; 3 yosys not installed.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
build=build out=out/synth jobs=2 only=. extra=0
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --extra) extra=1; shift ;;
    *) echo "usage: scripts/synth.sh [--build DIR] [--out DIR] [--jobs N] [--only REGEX] [--extra]" >&2; exit 2 ;;
  esac
done
if ! command -v yosys > /dev/null; then
  echo "synth: yosys is not installed (Debian: apt-get install yosys; scripts/setup.sh does): skipped" >&2
  exit 3
fi
gen=$(cd "$build" 2> /dev/null && pwd)/generated/rtl
for f in shading_formats.vh interp_terms.vh ua22802_a_rom.v rom_sweep/ua22802_a_rom_f6.v sqmul_word/p16/shading_formats.vh; do
  if [ ! -f "$gen/$f" ]; then
    echo "synth: $gen/$f is missing: configure $build with Verilator installed (cmake/verilator.cmake generates it)" >&2
    exit 2
  fi
done
mkdir -p "$out/ys" "$out/logs"
out=$(cd "$out" && pwd)

# A constant from the generated header (e.g. the rom_matched generator's node-32 wires).
macro() { sed -n "s/^\`define $1 //p" "$gen/shading_formats.vh"; }
# A constant from the generated term tables (e.g. the pipeline's job-register widths).
term() { sed -n "s/^\`define $1 //p" "$gen/interp_terms.vh"; }

rtl_sources="$(ls "$root"/rtl/blocks/*.v "$root"/rtl/specular/*.v "$root"/rtl/ua60553/*.v "$root"/rtl/ua22802/*.v \
  "$root"/rtl/tuned/*.v "$root"/rtl/interp/*.v "$root"/rtl/squared/*.v "$root"/rtl/sqmul/*.v | tr '\n' ' ') $gen/ua22802_a_rom.v"
includes="-I$gen -I$root/rtl/squared -I$root/rtl/sqmul"
# The shading pipeline's units read rtl/pipeline/ too (only they: the other rows' scripts stay as they were).
pipe_sources="$rtl_sources $(ls "$root"/rtl/pipeline/*.v | tr '\n' ' ')"
gates="AND,NAND,OR,NOR,XOR,XNOR,ANDNOT,ORNOT,MUX"

# variant <name> <top> <yosys commands before hierarchy> <hierarchy options> [sources] [commands after]
variant() {
  local name=$1 top=$2 pre=$3 hier=$4 sources=${5:-$rtl_sources} post=${6:-}
  echo "$name" | grep -Eq -- "$only" || return 0
  cat > "$out/ys/$name.ys" << EOF
# $name: generated by scripts/synth.sh
read_verilog $includes $sources
$pre
hierarchy -check -top $top $hier
synth -flatten -top $top -noabc
dffunmap
abc -fast -g $gates
opt_clean
tee -o $out/logs/$name.stat stat -tech cmos
tee -o $out/logs/$name.ltp ltp -noff
$post
EOF
  echo "$name"
}
# path <variant> <label> <from> <to>: yosys commands that write logs/<variant>.path.<label>.ltp,
# the depth in gates of the longest path from the flip-flop output net <from> to the D pins of the
# flip-flops that drive net <to> (after dffunmap's enable multiplexers) or, for <to> = pin:<name>,
# to that pin: the forward cone of <from> through combinational cells meets the backward cone of
# <to>, each net with its aliases (%a), and ltp counts the cells selected.
path() {
  local v=$1 label=$2 from=$3 to=$4
  local bwd="w:$to %a %ci1 %ci1:+[D] %cie*"
  case "$to" in pin:*) bwd="w:${to#pin:} %a %cie*" ;; esac
  printf 'select -set fwd w:%s %%a %%coe*\nselect -set bwd %s\ntee -o %s/logs/%s.path.%s.ltp ltp -noff @fwd @bwd %%i\n' \
    "$from" "$bwd" "$out" "$v" "$label"
}
# ram_bits <name> <top> <hierarchy options>: the design's memories (rtl/blocks/ram.v's arrays, read
# by proc), their bits counted, not mapped.
ram_bits() {
  local name=$1 top=$2 hier=$3
  echo "$name" | grep -Eq -- "$only" || return 0
  cat > "$out/ys/$name.ys" << EOF
# $name: generated by scripts/synth.sh (the memories as memories, not mapped)
read_verilog $includes $pipe_sources
hierarchy -check -top $top $hier
proc
flatten
opt_clean
tee -o $out/logs/$name.stat stat
EOF
  echo "$name"
}
# resynth_keep <top> <hierarchy options> <selection>: yosys commands that synthesize <top> again as
# variant() does, with the selected nets kept (not merged into the logic around them), for a path
# measurement only (the variant's counts come from its first synthesis).
resynth_keep() {
  printf 'design -reset\nread_verilog %s %s\nhierarchy -check -top %s %s\nsetattr -set keep 1 %s\n' \
    "$includes" "$rtl_sources" "$1" "$2" "$3"
  printf 'synth -flatten -top %s -noabc\ndffunmap\nabc -fast -g %s\nopt_clean\n' "$1" "$gates"
}
# cut_block <in> <out>: yosys commands that delete the cells between two kept nets (a block), so
# that a path measured next goes around it. Only after resynth_keep: the netlist is broken.
cut_block() {
  printf 'delete w:%s %%a %%coe* w:%s %%a %%cie* %%i c:* %%i\n' "$1" "$2"
}
# rom_bits <name> <module file>: the ROM read as a memory (proc_rom), its bits counted.
rom_bits() {
  local name=$1 file=$2
  echo "$name" | grep -Eq -- "$only" || return 0
  cat > "$out/ys/$name.ys" << EOF
# $name: generated by scripts/synth.sh (the case table as a memory, not mapped)
read_verilog $file
proc
opt_clean
tee -o $out/logs/$name.stat stat
EOF
  echo "$name"
}

{
  # The specular devices (Fig. 1 datapath + generator), saturating ADD11 unless "as patented".
  variant ua22802 specular_device "" "-chparam AGEN 1 -chparam SATURATE 1"
  # The same with the ROM kept out of the logic (a black box, its bits counted by rom_f6_bits).
  variant ua22802_rom_as_memory specular_device "read_verilog -lib $gen/ua22802_a_rom.v" \
    "-chparam AGEN 1 -chparam SATURATE 1" "$(echo "$rtl_sources" | sed "s#$gen/ua22802_a_rom.v##")"
  variant ua60553_patent specular_device "" "-chparam AGEN 0 -chparam SATURATE 0"
  variant ua60553_saturate specular_device "" "-chparam AGEN 0 -chparam SATURATE 1"
  variant tuned_minimax specular_device "" "-chparam AGEN 2 -chparam SATURATE 1"
  variant tuned_rom_matched specular_device \
    "chparam -set K31 $(macro TUNED_ROM_MATCHED_K31) -set K32 $(macro TUNED_ROM_MATCHED_K32) a_gen_tuned" \
    "-chparam AGEN 2 -chparam SATURATE 1"
  # The generators of a alone: where the designs differ.
  variant gen_rom a_gen_rom "" ""
  variant gen_linear a_gen_linear "" ""
  variant gen_tuned_minimax a_gen_tuned "" ""
  # The interpolation paper's units.
  variant coef_c1_shift_add coef_unit_cubic "" "-chparam SET 0 -chparam DIV 0"
  # The exact /3 is described by its function (blocks/const_div.h), which yosys builds as a general
  # array divider: minutes of synthesis for a cost no designer would pay. Only with --extra.
  if [ "$extra" = 1 ]; then variant coef_c1_exact coef_unit_cubic "" "-chparam SET 0 -chparam DIV 1"; fi
  variant coef_c2_shift_add coef_unit_cubic "" "-chparam SET 1 -chparam DIV 0"
  variant horner_unit horner_unit "" ""
  # The squared-quadratic device (ours) in both modes, and the two designs it is compared with
  # (saturating): the series squaring stage and the square-and-multiply baseline. Their paths:
  # the loop through the iterated multiplier (one clock), the strobe-to-register paths into it
  # (RG1, RG2 -> RG_SQ / RG_P: at worst 2.5 clocks after strobe 17 fell, as the request crosses the
  # synchroniser's two flip-flops and the load latches at the falling edge after the taking rising
  # edge), the result register to the outputs, and the baseline's select of MX_B into RG_P (half a
  # clock: it switches at a rising edge, RG_P latches at the falling edge).
  for m in saturate wrap; do
    sat=1; [ $m = wrap ] && sat=0
    variant "squared_$m" squared_device "" "-chparam SATURATE $sat" "$rtl_sources" \
      "$(path squared_$m loop sq.rg_sq.q sq.rg_sq.q; path squared_$m rg2_to_load rg2.q sq.rg_sq.q
         path squared_$m rg1_to_load rg1.q sq.rg_sq.q; path squared_$m rg1_to_ctrl rg1.q sq.ctl_sq.left
         path squared_$m to_outputs sq.rg_sq.q pin:out25_r)"
  done
  variant squared_series squared_series_device "" "-chparam SATURATE 1" "$rtl_sources" \
    "$(path squared_series rg2_to_outputs rg2.q pin:out25_r; path squared_series rg1_to_outputs rg1.q pin:out25_r)"
  variant sqmul_saturate sqmul_device "" "-chparam SATURATE 1" "$rtl_sources" \
    "$(path sqmul_saturate loop stage.rg_p.q stage.rg_p.q; path sqmul_saturate rg2_to_multiply rg2.q stage.rg_p.q
       path sqmul_saturate rg1_to_ctrl rg1.q stage.ctl.bits; path sqmul_saturate to_outputs stage.rg_p.q pin:out25_r
       path sqmul_saturate sel_to_multiply stage.mx_b_sel stage.rg_p.q
       # The load path alone (RG2 -> clamp -> MX_P -> RG_P, around the multiplier): synthesized
       # again with the multiplier's input and output kept as nets, so that its cells can be left out.
       resynth_keep sqmul_device "-chparam SATURATE 1" "sqmul_stage/w:mx_b_operand sqmul_stage/w:mul_p_product"
       cut_block stage.mx_b_operand stage.mul_p_product
       path sqmul_saturate rg2_to_load rg2.q stage.rg_p.q)"
  # The right-to-left square-and-multiply design: a squarer and a multiplier written in one clock
  # per bit of n. Its register-to-register paths (each a whole clock: RG_X -> MUL_X -> MX_X -> RG_X,
  # RG_P -> MUL_P -> MX_P -> RG_P, RG_X -> MUL_P -> RG_P), the load RG2 -> clamp -> MX_X -> RG_X
  # (2.5 clocks after the strobe at worst, through its own synchroniser sync17, as the baseline's;
  # no multiplier on it), RG1 -> controller, RG_P -> outputs.
  r2l=sqmul_r2l_saturate
  variant $r2l sqmul_r2l_device "" "-chparam SATURATE 1" "$rtl_sources" \
    "$(path $r2l loop stage.rg_p.q stage.rg_p.q; path $r2l loop_x stage.rg_x.q stage.rg_x.q
       path $r2l x_to_p stage.rg_x.q stage.rg_p.q; path $r2l rg2_to_load rg2.q stage.rg_x.q
       path $r2l rg1_to_ctrl rg1.q stage.ctl.bits; path $r2l to_outputs stage.rg_p.q pin:out25_r)"
  # Both square-and-multiply designs at other P words (the word-length study, studies/accuracy):
  # the formats of sqmul_word/p<F>/ found first on the include path, the same RTL.
  for f in 15 16 17 20; do
    includes="-I$gen/sqmul_word/p$f -I$gen -I$root/rtl/squared -I$root/rtl/sqmul" \
      variant "sqmul_p$f" sqmul_device "" "-chparam SATURATE 1" "$rtl_sources" \
      "$(path sqmul_p$f loop stage.rg_p.q stage.rg_p.q; path sqmul_p$f rg2_to_multiply rg2.q stage.rg_p.q
         path sqmul_p$f sel_to_multiply stage.mx_b_sel stage.rg_p.q; path sqmul_p$f to_outputs stage.rg_p.q pin:out25_r)"
  done
  for f in 16; do
    includes="-I$gen/sqmul_word/p$f -I$gen -I$root/rtl/squared -I$root/rtl/sqmul" \
      variant "sqmul_r2l_p$f" sqmul_r2l_device "" "-chparam SATURATE 1" "$rtl_sources" \
      "$(path sqmul_r2l_p$f loop stage.rg_p.q stage.rg_p.q; path sqmul_r2l_p$f loop_x stage.rg_x.q stage.rg_x.q
         path sqmul_r2l_p$f x_to_p stage.rg_x.q stage.rg_p.q; path sqmul_r2l_p$f to_outputs stage.rg_p.q pin:out25_r)"
  done
  # The shading pipeline (modules/pipeline, its RTL twin in rtl/pipeline/) unit by unit as the top
  # uses them (SET 0, DIV 0: the cubic's case 1 with the shift-and-add /3; the square-and-multiply
  # device, clocked), and the whole top with each evaluator: Horner, and forward differences for any
  # m per interval. The top has three of each channel (R, G, B) and one of each controller.
  pipe_len_w=$(term PIPELINE_PINS_LEN_W) pipe_m_w=$(term PIPELINE_PINS_M_W)
  variant pipe_sample_channel sample_channel "" "-chparam SET 0 -chparam DIV 0" "$pipe_sources"
  variant coef_quad coef_unit_quad "" "" "$pipe_sources"
  variant pipe_sample_ctrl sample_ctrl "" \
    "-chparam FD_M 0 -chparam CLOCKED 1 -chparam CARRY 0 -chparam LEN_W $pipe_len_w -chparam M_W $pipe_m_w" "$pipe_sources"
  variant pipe_horner_channel horner_channel "" "" "$pipe_sources"
  variant pipe_fd_channel_m4 fd_channel "" "-chparam FIXED_M 4" "$pipe_sources"
  variant pipe_fd_channel_var fd_channel "" "-chparam FIXED_M 0" "$pipe_sources"
  variant pipe_horner_pixel_ctrl horner_pixel_ctrl "" "" "$pipe_sources"
  variant pipe_fd_pixel_ctrl fd_pixel_ctrl "" "" "$pipe_sources"
  # The whole top's paths, channel R's (G and B are its copies): into a sample register from N.L
  # (RG_NL -> MX_NL -> the diffuse multiplier -> the adders -> MX_CARRY -> I1) and from the
  # device's result (RG_P -> its colour multiplier -> the colour adder -> I1); from the coefficient
  # units' registers through the coefficient networks into the evaluator's registers; the
  # evaluator's own loop; the evaluator to the pixel pins (the clamp).
  pipe_paths() {  # <variant> <the evaluator's registers>
    path "$1" nl_to_sample rg_nl1.q smp_r.rg_i1.q; path "$1" specular_to_sample dev.stage.rg_p.q smp_r.rg_i1.q
    path "$1" coef_to_eval "smp_r.coef_*.rg_i*.q" "$2"; path "$1" eval_loop "$2" "$2"
    path "$1" eval_to_pixels "$2" pin:px_r
  }
  variant pipeline_horner shading_pipeline "" \
    "-chparam EVAL 0 -chparam SET 0 -chparam DIV 0 -chparam CARRY 0 -chparam SATURATE 1" "$pipe_sources" \
    "$(pipe_paths pipeline_horner evaluator.horner_r.horner.rg.q)"
  variant pipeline_fd_var shading_pipeline "" \
    "-chparam EVAL 1 -chparam FD_M 0 -chparam SET 0 -chparam DIV 0 -chparam CARRY 0 -chparam SATURATE 1" "$pipe_sources" \
    "$(pipe_paths pipeline_fd_var "evaluator.fd_r.any_m.fd.rg_*.q")"
  # The cell unit (ours, beside the pipeline on its pixel stream): its nine column buffers (three
  # channels, three lattice columns: rtl/blocks/ram.v) black boxes, their bits counted apart.
  if [ "$extra" = 1 ]; then
    variant cell_unit cell_unit "read_verilog -lib $root/rtl/blocks/ram.v" "" \
      "$(echo "$pipe_sources" | sed "s#$root/rtl/blocks/ram.v##")"
    ram_bits cell_unit_bits cell_unit ""
  fi
  # A per-pixel Phong shader's operations, each priced as the library block that performs it (an
  # estimate, not a built design: modules/pipeline/README.md, "A per-pixel Phong shader, estimated"):
  # a multiplier of signed components at the device's cosine resolution (sign + SPEC_COS_FRAC fraction
  # bits), an adder at the pipeline's stepping width (INTERP_COEF_W), and one stage of a restoring
  # array divider or square root (an inverter bank, a subtractor one wire wider, a multiplexer), of
  # which such an array has one stage per quotient or root bit (scripts/phong_estimate.py).
  pw=$(( $(macro SPEC_COS_W) + 1 )) pf=$(macro SPEC_COS_FRAC) aw=$(macro INTERP_COEF_W)
  variant "phong_mul_$pw" mul "" \
    "-chparam WA $pw -chparam WB $pw -chparam WP $pw -chparam DROP $pf -chparam ASIGNED 1 -chparam BSIGNED 1"
  # The same multiplier at the stepping width: positions (Q E - U_P) and set-ups need more than a
  # component's bits, so the estimate is given at both.
  variant "phong_mul_$aw" mul "" \
    "-chparam WA $aw -chparam WB $aw -chparam WP $aw -chparam DROP $pf -chparam ASIGNED 1 -chparam BSIGNED 1"
  variant "phong_add_$aw" adder "" "-chparam WA $aw -chparam WB $aw -chparam WS $aw -chparam ASIGNED 1 -chparam BSIGNED 1"
  variant "phong_stage_inv_$((pw + 1))" inverter_bank "" "-chparam WIN $((pw + 1)) -chparam WOUT $((pw + 1))"
  variant "phong_stage_sub_$((pw + 1))" adder "" "-chparam WA $((pw + 1)) -chparam WB $((pw + 1)) -chparam WS $((pw + 1))"
  variant "phong_stage_mux_$pw" mux "" "-chparam W $pw -chparam N 2 -chparam SW 1"
  # The memories alone (ours): the frame buffer and the cells' band buffer at 512 and 1024, the
  # walker's slots; read as memories by proc, their bits counted (summarize.py: memories.csv, each
  # against the words x bits of the format tables).
  for size in 512 1024; do
    ram_bits "mem_frame_buffer_${size}_bits" frame_buffer "-chparam WIDTH $size -chparam HEIGHT $size"
    ram_bits "mem_band_buffer_${size}_bits" band_buffer "-chparam WIDTH $size"
  done
  ram_bits mem_walker_store_bits walker_store ""
  # The ROM alone at the fraction-bit sweep's sizes (F = 2..10; the device's is F = 6).
  for rom in $(ls "$gen"/rom_sweep/ua22802_a_rom_f*.v | sort -V); do
    f=$(basename "$rom" .v | sed 's/.*_f//')
    variant "rom_f$f" "ua22802_a_rom_f$f" "" "" "$rom"
    rom_bits "rom_f${f}_bits" "$rom"
  done
} > "$out/variants.txt"

echo "synth: $(wc -l < "$out/variants.txt") yosys runs, $jobs at a time, logs in $out/logs"
start=$(date +%s)
status=0
# shellcheck disable=SC2016
xargs -P "$jobs" -I{} sh -c 'yosys -q -l "$1/logs/$2.log" -s "$1/ys/$2.ys" > /dev/null 2>&1 || { echo "synth: $2 FAILED (log: $1/logs/$2.log)" >&2; exit 1; }' \
  sh "$out" {} < "$out/variants.txt" || status=1
echo "synth: yosys took $(( $(date +%s) - start )) s"
hand=""
[ -f "$root/out/hw_cost.csv" ] && hand="--hand $root/out/hw_cost.csv"
# shellcheck disable=SC2086
/usr/bin/python3 "$root/scripts/synth/summarize.py" --out "$out" --formats "$gen/shading_formats.vh" \
  --terms "$gen/interp_terms.vh" $hand || status=1
exit $status
