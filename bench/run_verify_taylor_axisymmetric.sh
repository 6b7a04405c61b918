#!/usr/bin/env bash
# Solution verification of the Taylor anvil in its axisymmetric form (docs/verify.md, "Taylor anvil,
# axisymmetric"): `mpm verify` on examples/16_axisymmetric_taylor/verify.yaml (TLMPM, hat, 1 particle per cell)
# at h = 1.27 mm / 2^k, k = 0 ... RUNS-1 (default 5: down to 0.079375 mm, 122,880 particles), the rod's shortening
# and the change of the foot's radius from 0 to 80 us. The suite's test (tests/verification/test_verify.cpp) runs
# the first four; the fifth is the finer reference for the numbers of docs/verify.md.
#   bash bench/run_verify_taylor_axisymmetric.sh [BUILD] [OUT] [RUNS]   (defaults build/, /tmp/mpm_verify_taylor_axi, 5;
#                                                                      about 2 min on one idle core, most of it the
#                                                                      finest run)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=${2:-/tmp/mpm_verify_taylor_axi}
runs=${3:-5}
"$build/apps/mpm" verify examples/16_axisymmetric_taylor/verify.yaml --refine "$runs" --threads 1 \
  --quantity length.y_span@0:8e-5 --quantity foot.x_max@0:8e-5 -o "$out"
echo "report: $out/verify.md; runs: $out/verify_runs.csv"
