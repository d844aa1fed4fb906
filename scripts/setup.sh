#!/usr/bin/env bash
# Installs what the project needs on Debian 12 when run as root and something is missing.
#   scripts/setup.sh [GROUP...]   GROUP: plots (matplotlib for scripts/run.sh's figures), fuzz (clang
#                                 and libFuzzer for scripts/fuzz.sh); the base list always.
# The base list is what building and scripts/test.sh need (CI; python3 for synth.smoke's summary,
# standard library only; Ninja, which the scripts build with, while make stays for a build tree
# configured with it and for the package test's consumer project); the optional groups are
# installed by the scripts that use them, so a CI run does not download a second compiler it never
# calls.
set -euo pipefail
pkgs=(cmake make ninja-build g++ pkg-config libsystemc-dev googletest libgtest-dev libglm-dev libcli11-dev libtinyobjloader-dev libpng-dev nlohmann-json3-dev bsdextrautils libbenchmark-dev verilator yosys python3)
for group in "$@"; do
  case $group in
    plots) pkgs+=(python3-matplotlib python3-numpy) ;;
    fuzz) pkgs+=(clang-14 libclang-rt-14-dev) ;;
    *) echo "setup: unknown group '$group' (plots, fuzz)" >&2; exit 2 ;;
  esac
done
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
if [ "$(id -u)" -ne 0 ]; then
  echo "setup: missing Debian packages: ${missing[*]}" >&2
  echo "setup: run as root, or: sudo apt-get install ${missing[*]}" >&2
  exit 1
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
