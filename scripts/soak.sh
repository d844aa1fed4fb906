#!/usr/bin/env bash
# Soak runs (opt-in, not CI; docs/fuzzing.md): the fast SystemC pipeline renders the head 1000 times
# in one process (soak_pipeline: 0 mismatches, resident memory after the first and the last render);
# then every TLM-2.0 wrapper serves PIXELS loosely-timed
# pixels (default 10^8) and PIN pin-accurate ones (default 2·10^5) in one process, each checked
# against the device's golden model (bench_specular_tlm per device, bench_line_tlm), and each
# wrapper PIXELS transactions of one pixel (bench_specular_tlm --burst 1) or one 32-pixel interval
# (bench_line_tlm --burst 1) each, PIN of them pin-accurate; prints the
# rates and exits 1 on any mismatch. Niced: the machine is shared.
#   scripts/soak.sh [PIXELS [PIN]]      e.g. scripts/soak.sh 1000000000
set -euo pipefail
cd "$(dirname "$0")/.."
lt=${1:-100000000}
pin=${2:-200000}
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
[ -f build/CMakeCache.txt ] || scripts/build.sh
nice cmake --build build -j 2 --target soak_pipeline bench_specular_tlm bench_line_tlm >/dev/null
status=0
echo "== soak_pipeline --renders 1000 --size 128"
nice build/bin/soak_pipeline --renders 1000 --size 128 2>&1 | grep -v 'Simulation stopped by user' || status=1
for d in patent minimax rom_matched ua22802 squared sqmul; do
  echo "== bench_specular_tlm --device $d --lt-pixels $lt --pin-pixels $pin"
  nice build/bin/bench_specular_tlm --device "$d" --lt-pixels "$lt" --pin-pixels "$pin" || status=1
  # One pixel per access: PIXELS / 2 pixels are PIXELS transactions (a write and a read each).
  echo "== bench_specular_tlm --device $d --lt-pixels $((lt / 2)) --pin-pixels $((pin / 2)) --burst 1"
  nice build/bin/bench_specular_tlm --device "$d" --lt-pixels "$((lt / 2))" --pin-pixels "$((pin / 2))" --burst 1 || status=1
done
echo "== bench_line_tlm --lt-pixels $lt --pin-pixels $pin"
nice build/bin/bench_line_tlm --lt-pixels "$lt" --pin-pixels "$pin" || status=1
# One interval per access: 16 pixels per transaction (a write of the interval, a read of its 32 pixels).
echo "== bench_line_tlm --lt-pixels $((lt * 16)) --pin-pixels $((pin * 16)) --burst 1"
nice build/bin/bench_line_tlm --lt-pixels "$((lt * 16))" --pin-pixels "$((pin * 16))" --burst 1 || status=1
[ $status -eq 0 ] && echo "soak: every wrapper, 0 mismatches" || echo "soak: MISMATCH or failure above" >&2
exit $status
