#!/usr/bin/env bash
# The scene side of the shading system: the head scan rendered at 512x512 by the two per-pixel
# references (Phong with exact cos^n, and the specular term through each device's golden model) in
# both overflow modes; PNGs in $SHADING_OUT/scene/<device>_<mode>/, one summary row per run (samples = covered
# pixels) with the device image's NMSE against Phong and the counted long operations per pixel of Phong.
set -euo pipefail
cd "$(dirname "$0")/../.."
for dev in patent minimax rom_matched ua22802 squared sqmul; do
  for mode in saturate wrap; do
    out="$SHADING_OUT/scene/${dev}_${mode}"
    log=$("$SHADING_BIN/render_reference" --scene head --size 512 --device "$dev" --mode "$mode" --out "$out")
    nmse=$(sed -n 's/^device vs Phong: NMSE \([^,]*\), largest error \([^ ]*\).*/\1/p' <<<"$log")
    maxe=$(sed -n 's/^device vs Phong: NMSE [^,]*, largest error \([^ ]*\).*/\1/p' <<<"$log")
    covered=$(sed -n 's/.* \([0-9]*\) pixels covered.*/\1/p' <<<"$log")
    phong_long=$(awk '/^Phong reference/{p=1} p && $1=="total"{print $NF; exit}' <<<"$log")
    [ -n "$nmse" ] && [ -n "$covered" ] && [ -n "$phong_long" ] || { echo "60-scene: unexpected output of render_reference" >&2; exit 1; }
    printf 'scene_head\t%s_%s_512\t%s\t-\t%s\t-\tNMSE device vs Phong (max error %s levels); Phong %s long ops/pixel\n' \
      "$dev" "$mode" "$covered" "$nmse" "$maxe" "$phong_long" >> "$SHADING_SUMMARY"
  done
done
# The README's comparison at n = 20: Phong, the patent's device and the squared-quadratic device
# (ours), with both error maps at one scale (data/readme/squared_head_512_n20.png).
"$SHADING_BIN/render_reference" --scene head --size 512 --n 20 --device squared --compare patent,squared \
  --error-scale 8 --out "$SHADING_OUT/scene/compare_n20" >/dev/null
