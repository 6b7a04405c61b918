#!/usr/bin/env bash
# Every example scene to its end time with the energy sentinel (no false alarm): prints, per example,
# the exit status, whether the sentinel warned, its largest balance / tolerance (1 = the warning threshold) and
# the relative energy change of the run, as the program's last lines report them. Not a test: the whole
# sweep takes about 30-60 min of one core; docs/VERIFICATION.md, "Energy sentinel", holds the last result.
#   bash bench/run_examples_sentinel.sh [BUILD] [TIMEOUT_S] [SCENE...]
# (defaults build/, 1800 s per scene, every examples/*/*.yaml; a run stopped by the time limit shows status 124)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
limit=${2:-1800}
shift $(( $# < 2 ? $# : 2 ))
scenes=("$@")
[ ${#scenes[@]} -eq 0 ] && scenes=(examples/*/*.yaml)
dir=$(mktemp -d /tmp/mpm_examples_sentinel.XXXXXX)
printf '%-40s %6s %6s %12s %8s %14s\n' scene status warned largest_ratio at_step energy_change
for scene in "${scenes[@]}"; do
  name=$(basename "$(dirname "$scene")")_$(basename "$scene" .yaml)
  log="$dir/$name.log"
  status=0
  timeout "$limit" "$build/apps/mpm" run "$scene" -o "$dir/$name" > "$log" 2>&1 || status=$?
  warned=no
  grep -q 'warning: energy sentinel' "$log" && warned=yes
  ratio=$(sed -n 's/^energy sentinel: largest balance \/ tolerance \([^ ]*\) (step \([0-9]*\)).*/\1 \2/p' "$log")
  change=$(sed -n 's/.*relative energy change \([^;]*\);.*/\1/p' "$log")
  printf '%-40s %6s %6s %12s %8s %14s\n' "$name" "$status" "$warned" "${ratio% *}" "${ratio#* }" "${change:--}"
  rm -rf "${dir:?}/$name"
done
echo "logs: $dir"
