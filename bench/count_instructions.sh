#!/usr/bin/env bash
# Instructions per particle-update of bench_throughput's cases, counted by valgrind (cachegrind, no cache
# simulation), for one or two builds. Wall time on a shared VM wanders by +-10% even idle (PERFORMANCE.md
# §11); the instruction count of the same program on the same input does not, so a claim of "within 1%" of
# another build can be checked here. It is a count of work, not of time: memory stalls are not in it.
#   bash bench/count_instructions.sh A_BENCH [B_BENCH] [--case LIST] [--steps N1,N2]
# Each case runs twice per build, with N1 and N2 timed steps (default 2,6) after the same set-up and warm-up;
# the difference of the two counts over (N2 - N1) steps x particles is the count per particle-update, with
# the set-up cancelled. One thread (valgrind runs threads one at a time anyway). About 1 minute per case
# and build for the --quick blocks (2.5e5 particles).
set -euo pipefail

usage() { sed -n '2,10p' "$0" >&2; exit 2; }
[[ $# -ge 1 && "$1" != -* ]] || usage
bins=("$1")
shift
if [[ $# -ge 1 && "$1" != -* ]]; then bins+=("$1"); shift; fi
cases=2d_linear_usl,2d_cubic_bspline_usl,3d_linear_musl steps=2,6
while [[ $# -gt 0 ]]; do
  case "$1" in
    --case) cases="${2:?--case needs a value}"; shift 2 ;;
    --steps) steps="${2:?--steps needs a value}"; shift 2 ;;
    *) echo "count_instructions.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
done
if ! [[ "$steps" =~ ^([0-9]+),([0-9]+)$ ]] || ((BASH_REMATCH[2] <= BASH_REMATCH[1])); then
  echo "count_instructions.sh: --steps must be N1,N2 with N2 > N1, got '$steps'" >&2
  exit 2
fi
n1=${BASH_REMATCH[1]} n2=${BASH_REMATCH[2]}
for bin in "${bins[@]}"; do
  [[ -x "$bin" ]] || { echo "count_instructions.sh: '$bin' is not an executable" >&2; exit 2; }
done
command -v valgrind > /dev/null || { echo "count_instructions.sh: valgrind is not installed (apt-get install valgrind)" >&2; exit 2; }

log=$(mktemp)
trap 'rm -f "$log"' EXIT
# Prints the instruction count ("I refs") of one run and, on the second line, its particle count.
count() {
  valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null \
    "$1" --quick --case "$2" --threads 1 --steps "$3" > "$log" 2>&1 ||
    { echo "count_instructions.sh: $1 --case $2 failed:" >&2; tail -5 "$log" >&2; exit 1; }
  grep -E 'I +refs' "$log" | tr -d ',' | awk '{print $NF}'
  grep -E "^$2: [0-9]+ particles" "$log" | awk '{print $2}'
}

echo "| case | build | instructions per particle-update | (N2 - N1) steps x particles |"
echo "|---|---|---|---|"
declare -A per_update
for c in ${cases//,/ }; do
  for i in "${!bins[@]}"; do
    label=A
    ((i == 0)) || label=B
    mapfile -t first < <(count "${bins[$i]}" "$c" "$n1")
    mapfile -t second < <(count "${bins[$i]}" "$c" "$n2")
    per=$(/usr/bin/python3 -c 'import sys; a, b, n1, n2, p = map(int, sys.argv[1:]); print(f"{(b - a) / ((n2 - n1) * p):.2f}")' \
      "${first[0]}" "${second[0]}" "$n1" "$n2" "${second[1]}")
    per_update[$c,$i]=$per
    echo "| $c | $label | $per | $((n2 - n1)) x ${second[1]} |"
  done
done
if [[ ${#bins[@]} -eq 2 ]]; then
  echo
  echo "A = ${bins[0]}"
  echo "B = ${bins[1]}"
  for c in ${cases//,/ }; do
    /usr/bin/python3 -c 'import sys; print(f"{sys.argv[1]}: B/A = {float(sys.argv[3]) / float(sys.argv[2]):.4f}")' \
      "$c" "${per_update[$c,0]}" "${per_update[$c,1]}"
  done
fi
