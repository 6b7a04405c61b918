#!/usr/bin/env bash
# "Leave out what a scene does not need", measured: a scene that uses no optional module
# must run as fast, and hold as much memory per particle, in a build with every optional module compiled in
# as in a build with none. This builds bench_throughput twice (Release), with every MPM_WITH_* option of the
# project switched off and on, then compares them with bench/compare_builds.sh (alternating rounds; best and
# median particle-updates/s, heap bytes per particle; runs in $MPM_BUILD_DIR-modules-on/compare_builds.csv).
#   bash bench/run_module_overhead.sh [--rounds N] [--case 2d_linear_usl,3d_linear_usl] [--threads 1] [--full]
#   bash bench/run_module_overhead.sh --instructions [--case ...]
# --full uses the 1e6-particle blocks (default: the --quick blocks of about 2.5e5 particles). --instructions
# counts instructions per particle-update instead (bench/count_instructions.sh, valgrind): exact to the last
# digit, where the wall-time comparison wanders by +-10% on a shared VM (PERFORMANCE.md §11, §14).
# Build directories: $MPM_BUILD_DIR-modules-off and -on (default build-modules-off, build-modules-on);
# MPM_JOBS compile jobs (default 1). Optional modules follow one convention: a CMake option MPM_WITH_<NAME>
# (physics/CMakeLists.txt); the script finds them in the CMake cache, so new modules are included as they land.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
base="${MPM_BUILD_DIR:-$root/build}"
jobs="${MPM_JOBS:-1}"
rounds=5
cases=2d_linear_usl,3d_linear_usl
threads=1
size=""
instructions=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --rounds) rounds="${2:?--rounds needs a value}"; shift 2 ;;
    --case) cases="${2:?--case needs a value}"; shift 2 ;;
    --threads) threads="${2:?--threads needs a value}"; shift 2 ;;
    --full) size="--full"; shift ;;
    --instructions) instructions=1; shift ;;
    -h | --help) sed -n '2,14p' "$0"; exit 0 ;;
    *) echo "run_module_overhead.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done
if ! [[ "$rounds" =~ ^[1-9][0-9]*$ ]]; then
  echo "run_module_overhead.sh: --rounds must be a positive integer, got '$rounds'" >&2
  exit 2
fi

on="$base-modules-on"
off="$base-modules-off"
cmake -S "$root" -B "$on" -DCMAKE_BUILD_TYPE=Release -DMPM_BUILD_TESTS=OFF > /dev/null
options=$(cmake -N -LA "$on" | sed -n 's/^\(MPM_WITH_[A-Z0-9_]*\):BOOL=.*/\1/p')
on_flags=() off_flags=()
for o in $options; do on_flags+=("-D$o=ON"); off_flags+=("-D$o=OFF"); done
echo "optional modules: ${options:-none (no MPM_WITH_* option yet: the two builds are the same)}" >&2
cmake -S "$root" -B "$on" "${on_flags[@]}" > /dev/null
cmake -S "$root" -B "$off" -DCMAKE_BUILD_TYPE=Release -DMPM_BUILD_TESTS=OFF "${off_flags[@]}" > /dev/null
cmake --build "$on" --target bench_throughput -j "$jobs"
cmake --build "$off" --target bench_throughput -j "$jobs"

# Modules off = A, modules on = B.
cd "$base-modules-on"
if [[ -n "$instructions" ]]; then
  exec bash "$root/bench/count_instructions.sh" "$off/bench/bench_throughput" "$on/bench/bench_throughput" --case "$cases"
fi
exec bash "$root/bench/compare_builds.sh" "$off/bench/bench_throughput" "$on/bench/bench_throughput" \
  --rounds "$rounds" --case "$cases" --threads "$threads" ${size:+"$size"}
