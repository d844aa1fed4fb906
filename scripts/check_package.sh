#!/usr/bin/env bash
# The installed package, as a user's platform sees it (ctest package.install_and_consume):
#   1. cmake --install <build> into a temporary prefix; no absolute source or build path may appear in it;
#   2. configure, build and run testbenches/example/installed against it with find_package(shading)
#      (CMAKE_PREFIX_PATH=<prefix> only): the pin-level consumer and the TLM virtual platform;
#   3. build and run one file with `pkg-config --cflags --libs shading` (PKG_CONFIG_PATH=<prefix>/...).
# Usage: scripts/check_package.sh [build-dir]   (default: build). Everything temporary is removed.
# CXX and SHADING_CXX_LAUNCHER (e.g. ccache) are taken from the environment (ctest sets them).
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-$src/build}" && pwd)"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/shading-package.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
prefix="$tmp/prefix"
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1

echo "== install $build -> $prefix"
cmake --install "$build" --prefix "$prefix" >"$tmp/install.log"
for f in lib/cmake/shading/shadingConfig.cmake lib/cmake/shading/shadingConfigVersion.cmake \
         lib/cmake/shading/shadingTargets.cmake lib/pkgconfig/shading.pc lib/libshading_golden.a \
         include/shading/ua60553/ua60553.h include/shading/golden/specular_golden.h \
         include/shading/formats/fixed_point.h include/shading/ua22802_a_rom.h; do
  [ -e "$prefix/$f" ] || { echo "check_package: $f not installed" >&2; exit 1; }
done
# Relocatable: nothing installed may name the source tree, the build tree or the prefix itself.
for p in "$src" "$build" "$prefix"; do
  if grep -rIl --fixed-strings "$p" "$prefix"; then
    echo "check_package: the files above contain the absolute path $p" >&2
    exit 1
  fi
done

launcher=()
[ -n "${SHADING_CXX_LAUNCHER:-}" ] && launcher=("$SHADING_CXX_LAUNCHER")
cxx="${CXX:-c++}"

echo "== find_package(shading): testbenches/example/installed"
cmake -S "$src/testbenches/example/installed" -B "$tmp/consumer" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" \
      ${SHADING_CXX_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER="$SHADING_CXX_LAUNCHER"} >"$tmp/configure.log" \
  || { cat "$tmp/configure.log"; exit 1; }
cmake --build "$tmp/consumer" -j2
"$tmp/consumer/consumer"
"$tmp/consumer/virtual_platform"

echo "== pkg-config --cflags --libs shading"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
[ "$(pkg-config --modversion shading)" = "$(sed -n 's/^Version: //p' "$prefix/lib/pkgconfig/shading.pc")" ]
# shellcheck disable=SC2046  # pkg-config's output is meant to be split into words
"${launcher[@]}" "$cxx" -std=c++17 -O1 "$src/testbenches/example/installed/pkgconfig_check.cpp" \
  $(pkg-config --cflags --libs shading) -o "$tmp/pkgconfig_check"
"$tmp/pkgconfig_check"
echo "check_package: ok"
