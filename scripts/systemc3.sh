#!/usr/bin/env bash
# The project against Accellera's SystemC 3.0.2 instead of Debian's 2.3.4 (docs/systemc-versions.md).
#   1. Builds SystemC 3.0.2 once from the vendored release into build-systemc3/prefix (C++17, CMake,
#      shared library); a later run reuses it.
#   2. Configures the project in build-systemc3/build with -DSHADING_SYSTEMC_PREFIX=<that prefix>,
#      builds it and runs the suite through ctest.
# Usage: scripts/systemc3.sh [--subset | --ci] [--jobs N] [ctest args...]
#   --subset   build and run only the programs whose tests cover the modules, the TLM wrappers, the VCD
#              writer, the examples and the installed package (their ctest labels, SUBSET below),
#              instead of everything.
#   --ci       what CI runs: the block library, the UA 60553 device, both TLM wrappers and the VCD
#              writer (CI_SUBSET below), in build-systemc3/ci, without the RTL (no Verilator runs).
#   --jobs N   parallel compile and test jobs (default 2; everything is run under nice).
# SYSTEMC3_TARBALL: the release archive (default ../shared/vendor/systemc-3.0.2.tar.gz beside the tree).
# Exit status: ctest's (0 all passed or skipped, non-zero otherwise); 2 for bad usage.
set -euo pipefail
cd "$(dirname "$0")/.."
src="$PWD"

# The subset's programs, by ctest label (each program's tests carry its name as their label).
SUBSET=(test_blocks test_ua60553 test_ua22802 test_squared test_interp ua60553_tb test_tlm bench_specular_tlm
        bench_line_tlm test_vcd_writer test_vcd_writer_pipeline platform_example package)
# CI's: the modules (the block library and the UA 60553 device at block level), both TLM-2.0
# wrappers and the VCD writer against SystemC 3.0.2's own; nothing above the modules but the golden
# models they are checked against, so it fits CI's time (docs/systemc-versions.md).
CI_SUBSET=(test_blocks test_ua60553 test_tlm test_vcd_writer)
# What package.install_and_consume installs besides the programs above.
PACKAGE_TARGETS=(shading_golden shading_scene shading_pipeline ua22802_rom_content)

usage() { sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
subset=0
jobs=2
ctest_args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --subset) subset=1 ;;
    --ci) subset=ci ;;
    --jobs) [ $# -ge 2 ] && [[ "$2" =~ ^[1-9][0-9]*$ ]] || usage; jobs="$2"; shift ;;
    -h|--help) usage ;;
    *) ctest_args+=("$1") ;;
  esac
  shift
done

top="$src/build-systemc3"
prefix="$top/prefix"
tarball="${SYSTEMC3_TARBALL:-$src/../shared/vendor/systemc-3.0.2.tar.gz}"
sha256=3712996d902508d327479bdb074e8db2c0499d4693fc1228b27d708c2354c943
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
launcher=()
if command -v ninja >/dev/null; then launcher=(-G Ninja); fi
if command -v ccache >/dev/null; then launcher+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
now() { date +%s; }

# --- 1. SystemC 3.0.2, once.
if ! find "$prefix" -name SystemCLanguageConfig.cmake 2>/dev/null | grep -q .; then
  [ -f "$tarball" ] || { echo "systemc3: $tarball not found (set SYSTEMC3_TARBALL)" >&2; exit 1; }
  echo "$sha256  $tarball" | sha256sum -c --quiet - || { echo "systemc3: $tarball: wrong sha256" >&2; exit 1; }
  t0=$(now)
  rm -rf "$top/systemc-3.0.2" "$top/lib-build"
  mkdir -p "$top"
  tar -xzf "$tarball" -C "$top"
  # Examples and regression tests off; the banner off, as SYSTEMC_DISABLE_COPYRIGHT_MESSAGE does.
  cmake -S "$top/systemc-3.0.2" -B "$top/lib-build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_STANDARD=17 \
        -DCMAKE_INSTALL_PREFIX="$prefix" -DENABLE_EXAMPLES=OFF -DDISABLE_COPYRIGHT_MESSAGE=ON \
        "${launcher[@]}" >"$top/lib-configure.log"
  nice cmake --build "$top/lib-build" -j "$jobs"
  cmake --install "$top/lib-build" >"$top/lib-install.log"
  # SystemC's CMake build installs no systemc.pc (its Autotools build does): write one, relocatable,
  # so shading.pc's "Requires: systemc" resolves against this prefix too.
  mkdir -p "$prefix/lib/pkgconfig"
  cat >"$prefix/lib/pkgconfig/systemc.pc" <<'EOF'
prefix=${pcfiledir}/../..
libdir=${prefix}/lib
includedir=${prefix}/include

Name: SystemC
Description: Accellera SystemC 3.0.2 (C++17), built by scripts/systemc3.sh
Version: 3.0.2
Cflags: -I${includedir}
Libs: -L${libdir} -lsystemc
EOF
  echo "systemc3: SystemC 3.0.2 built and installed into $prefix in $(( $(now) - t0 )) s"
fi

# --- 2. The project against it.
t0=$(now)
if [ "$subset" = ci ]; then
  # A build folder of its own: no Verilator (its configure-time checks and RTL targets are not
  # what this run covers), no install rules.
  bdir="$top/ci"
  [ -f "$bdir/CMakeCache.txt" ] ||
    cmake -S "$src" -B "$bdir" -DCMAKE_BUILD_TYPE=Release -DSHADING_SYSTEMC_PREFIX="$prefix" \
          -DCMAKE_DISABLE_FIND_PACKAGE_verilator=ON -DSHADING_INSTALL=OFF "${launcher[@]}" >"$top/ci-configure.log"
  nice cmake --build "$bdir" -j "$jobs" --target "${CI_SUBSET[@]}"
  ctest_args=(-L "^($(IFS='|'; echo "${CI_SUBSET[*]}"))\$" "${ctest_args[@]}")
  t1=$(now)
  rc=0
  nice ctest --test-dir "$bdir" --output-on-failure --no-tests=error -j "$jobs" "${ctest_args[@]}" || rc=$?
  echo "systemc3: build $(( t1 - t0 )) s, tests $(( $(now) - t1 )) s (SystemC 3.0.2, CI subset)"
  exit "$rc"
fi
[ -f "$top/build/CMakeCache.txt" ] ||
  cmake -S "$src" -B "$top/build" -DCMAKE_BUILD_TYPE=Release -DSHADING_SYSTEMC_PREFIX="$prefix" "${launcher[@]}"
if [ "$subset" = 1 ]; then
  targets=("${PACKAGE_TARGETS[@]}")
  for t in "${SUBSET[@]}"; do [ "$t" = package ] || targets+=("$t"); done
  nice cmake --build "$top/build" -j "$jobs" --target "${targets[@]}"
  label="^($(IFS='|'; echo "${SUBSET[*]}"))\$"
  ctest_args=(-L "$label" "${ctest_args[@]}")
else
  nice cmake --build "$top/build" -j "$jobs"
fi
t1=$(now)
rc=0
nice ctest --test-dir "$top/build" --output-on-failure --no-tests=error -j "$jobs" "${ctest_args[@]}" || rc=$?
echo "systemc3: build $(( t1 - t0 )) s, tests $(( $(now) - t1 )) s (SystemC 3.0.2, $([ "$subset" = 1 ] && echo subset || echo full suite))"
exit "$rc"
