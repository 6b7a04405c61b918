#!/usr/bin/env bash
# Builds bench_throughput (Release) in build/ if needed and runs the full throughput benchmark.
# The table goes to stdout, the CSV to build/bench_throughput.csv (results are machine-specific: they
# are not committed). Extra arguments are passed on, e.g.
#   bash bench/run_throughput.sh --quick
#   bash bench/run_throughput.sh --case 3d_linear_musl --threads 1,2
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MPM_BUILD_DIR:-$root/build}"
jobs="${MPM_JOBS:-1}"

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
elif ! grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$build/CMakeCache.txt"; then
  echo "warning: $build is not a Release build; timings will not be representative" >&2
fi
cmake --build "$build" --target bench_throughput -j "$jobs"

exec "$build/bench/bench_throughput" --csv "$build/bench_throughput.csv" "$@"
