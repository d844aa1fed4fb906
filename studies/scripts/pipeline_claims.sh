#!/usr/bin/env bash
# The claims sweep (opt-in, long: not part of scripts/run.sh or CI, whose ctest runs a 24-pixel smoke
# of it, pipeline.sweep.claims_shards): render_pipeline --sweep --grid claims over the head, sphere and
# torus (and any OBJ given with --scenes), three light directions, n = 5, 20, 100, 500, sizes 512 and
# 1024, every device and sixteen policies (the default fixed length, the paper's zones, the adaptive
# and the geometry-only policies, each through the forward differences and the Horner unit), golden
# model only, then each policy's worst case and median (studies/scripts/pipeline_claims.py).
#   studies/scripts/pipeline_claims.sh [OUT] [render_pipeline options...]
#   e.g. studies/scripts/pipeline_claims.sh out/claims --device squared --sizes 512
# The whole grid is 5 760 configurations (18 min on 2 quiet cores, 2026-12-03). To spread
# it over machines: add --shard I/N to each of N runs (same options), or --emit-jobs for one command
# line per configuration (GNU parallel, a Slurm array), then pipeline_claims.py OUT.md their CSVs.
set -euo pipefail
cd "$(dirname "$0")/../.."
out="${1:-out/pipeline/claims}"
shift || true
bin="${SHADING_BIN:-build/bin}/render_pipeline"
mkdir -p "$out"
SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 "$bin" --sweep --grid claims --out "$out" "$@"
if [ -e "$out/sweep.csv" ]; then
  python3 studies/scripts/pipeline_claims.py "$out/claims.md" "$out/sweep.csv"
fi
