#!/usr/bin/env bash
# The installed package, as a user's platform sees it (ctest package.install_and_consume):
#   1. cmake --install <build> into a temporary prefix; no absolute source or build path, nor the
#      prefix itself, may appear in it; then the tree is moved elsewhere (it must be relocatable);
#   2. configure, build and run testbenches/example/installed against the moved tree with
#      find_package(shading) (CMAKE_PREFIX_PATH=<prefix> only): the pin-level consumer (UA 60553 and
#      the squared-quadratic device) and the TLM virtual platform, which reads the installed head
#      scan through SHADING_DATA_DIR;
#   3. build and run one file with `pkg-config --cflags --libs shading` (PKG_CONFIG_PATH=<prefix>/...)
#      and check shading-scene.pc's libraries and data directory.
# Usage: scripts/check_package.sh [build-dir]   (default: build). Everything temporary is removed.
# CXX and SHADING_CXX_LAUNCHER (e.g. ccache) are taken from the environment (ctest sets them), and
# SHADING_SYSTEMC_PREFIX when the build used an Accellera SystemC (docs/systemc-versions.md): the
# consumer then finds it there, as a user would, through CMAKE_PREFIX_PATH and PKG_CONFIG_PATH.
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-$src/build}" && pwd)"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/shading-package.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
stage="$tmp/stage"    # where cmake --install writes
prefix="$tmp/prefix"  # where the tree is moved to and used from
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1

echo "== install $build -> $stage"
cmake --install "$build" --prefix "$stage" >"$tmp/install.log"
for f in lib/cmake/shading/shadingConfig.cmake lib/cmake/shading/shadingConfigVersion.cmake \
         lib/cmake/shading/shadingTargets.cmake lib/cmake/shading/shadingSceneTargets.cmake \
         lib/pkgconfig/shading.pc lib/pkgconfig/shading-scene.pc lib/libshading_golden.a lib/libshading_floor.a \
         lib/libshading_scene.a lib/libshading_pipeline.a \
         include/shading/ua60553/ua60553.h include/shading/golden/interp_golden.h \
         include/shading/formats/fixed_point.h include/shading/ua22802_a_rom.h \
         include/shading/tlm/tlm_target_base.h include/shading/tlm/specular_tlm.h \
         include/shading/squared/squared.h include/shading/squared/squared_device.h \
         include/shading/squared/squared_fast.h include/shading/squared/squaring_stage.h \
         include/shading/sqmul/sqmul.h include/shading/sqmul/sqmul_device.h include/shading/sqmul/sqmul_fast.h \
         include/shading/sqmul/sqmul_stage.h include/shading/sqmul/sqmul_ctrl.h include/shading/sqmul/sqmul_count.h \
         include/shading/blocks/saturator.h \
         include/shading/blocks/lzc.h include/shading/blocks/barrel_shifter.h include/shading/blocks/and_gate.h \
         include/shading/monitors/load_checker.h include/shading/monitors/phase_checker.h \
         include/shading/formats/squared_formats.h include/shading/formats/sqmul_formats.h \
         include/shading/arith/squared_arith.h include/shading/arith/sqmul_arith.h \
         include/shading/arith/specular_arith.h include/shading/arith/pipeline_arith.h \
         include/shading/scene/world.h include/shading/golden_pipeline/pipeline.h \
         include/shading/pipeline/shading_pipeline.h \
         share/shading/data/head/lee_perry_smith_head.obj share/shading/data/head/README.md; do
  [ -e "$stage/$f" ] || { echo "check_package: $f not installed" >&2; exit 1; }
done
# Each layer keeps its own folder (docs/layers.md): the golden pipeline's headers are not mixed
# into the SystemC pipeline's.
[ ! -e "$stage/include/shading/pipeline/pipeline.h" ] ||
  { echo "check_package: include/shading/pipeline/ holds the golden pipeline's pipeline.h" >&2; exit 1; }
# Every device's bit-exact function is in libshading_floor, the checks' extras in libshading_golden
# (their sources are globbed at configure time).
for lib_sym in floor:golden_ua60553 floor:golden_ua22802 floor:golden_ua60553_tuned floor:golden_squared \
               floor:golden_sqmul golden:interp::golden_horner_steps; do
  lib="${lib_sym%%:*}" sym="${lib_sym#*:}"
  grep -qF " T shading::$sym(" <<<"$(nm -C "$stage/lib/libshading_$lib.a")" \
    || { echo "check_package: libshading_$lib.a does not define shading::$sym" >&2; exit 1; }
done
# The head scan's licence (CC BY 3.0) travels with it.
grep -q "Lee Perry-Smith" "$stage/share/shading/data/head/README.md" \
  || { echo "check_package: the head scan's attribution is missing" >&2; exit 1; }
# Relocatable: nothing installed may name the source tree, the build tree or the prefix itself;
# and the tree is used from elsewhere than where it was installed.
for p in "$src" "$build" "$stage"; do
  if grep -rIl --fixed-strings "$p" "$stage"; then
    echo "check_package: the files above contain the absolute path $p" >&2
    exit 1
  fi
done
mv "$stage" "$prefix"
echo "== moved to $prefix"

launcher=()
[ -n "${SHADING_CXX_LAUNCHER:-}" ] && launcher=("$SHADING_CXX_LAUNCHER")
cxx="${CXX:-c++}"
search="$prefix"
if [ -n "${SHADING_SYSTEMC_PREFIX:-}" ]; then
  search="$prefix;$SHADING_SYSTEMC_PREFIX"
  sc_libdir="$(dirname "$(find "$SHADING_SYSTEMC_PREFIX" -name 'libsystemc.so' -print -quit)")"
  export PKG_CONFIG_PATH="$sc_libdir/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
  export LD_LIBRARY_PATH="$sc_libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
fi

echo "== find_package(shading): testbenches/example/installed"
cmake -S "$src/testbenches/example/installed" -B "$tmp/consumer" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$search" -DCMAKE_CXX_COMPILER="$cxx" \
      ${SHADING_CXX_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER="$SHADING_CXX_LAUNCHER"} >"$tmp/configure.log" \
  || { cat "$tmp/configure.log"; exit 1; }
cmake --build "$tmp/consumer" -j2
"$tmp/consumer/consumer"
"$tmp/consumer/virtual_platform"

echo "== pkg-config --cflags --libs shading"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
[ "$(pkg-config --modversion shading)" = "$(sed -n 's/^Version: //p' "$prefix/lib/pkgconfig/shading.pc")" ]
[ "$(pkg-config --modversion shading-scene)" = "$(pkg-config --modversion shading)" ]
# shading-scene.pc: its libraries exist where it says, before shading's; its data directory holds the head.
scene_libs="$(pkg-config --libs shading-scene)"
case "$scene_libs" in *-lshading_pipeline*-lshading_scene*-lshading_golden*) ;;
  *) echo "check_package: pkg-config --libs shading-scene: $scene_libs" >&2; exit 1 ;; esac
[ -e "$(pkg-config --variable=datadir shading-scene)/data/head/lee_perry_smith_head.obj" ] \
  || { echo "check_package: shading-scene.pc's datadir has no head scan" >&2; exit 1; }
# shellcheck disable=SC2046  # pkg-config's output is meant to be split into words
"${launcher[@]}" "$cxx" -std=c++17 -O1 "$src/testbenches/example/installed/pkgconfig_check.cpp" \
  $(pkg-config --cflags --libs shading) -o "$tmp/pkgconfig_check"
"$tmp/pkgconfig_check"
echo "check_package: ok"
