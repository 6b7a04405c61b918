#!/usr/bin/env bash
# Compares two bench_throughput programs (two builds, e.g. before and after a change) on the same cases,
# alternating them round by round so that a change of machine load hits both, and prints per case the best
# and the median particle-updates/s of each, the ratio B/A of the bests, the median over the rounds of
# B/A within a round (A and B ran back to back: the most robust number on a shared machine) and the heap
# bytes per particle.
#   bash bench/compare_builds.sh A_BENCH B_BENCH [--rounds N] [--case LIST] [--threads T] [--full] [--profile]
# A_BENCH, B_BENCH: paths to bench_throughput executables. --full: 1e6-particle blocks (default: the
# --quick blocks). --profile: B runs with its phase timers on (B must support --profile): the cost of
# profiling itself. Every run goes to compare_builds.csv in the current directory.
set -euo pipefail

if [[ $# -lt 2 || "$1" == -* || "$2" == -* ]]; then
  sed -n '2,12p' "$0" >&2
  exit 2
fi
a="$1" b="$2"
shift 2
for bin in "$a" "$b"; do
  if [[ ! -x "$bin" ]]; then
    echo "compare_builds.sh: '$bin' is not an executable" >&2
    exit 2
  fi
done
rounds=5 cases=2d_linear_usl,2d_cubic_bspline_usl,3d_linear_musl threads=1 size=--quick profile=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --rounds) rounds="${2:?--rounds needs a value}"; shift 2 ;;
    --case) cases="${2:?--case needs a value}"; shift 2 ;;
    --threads) threads="${2:?--threads needs a value}"; shift 2 ;;
    --full) size=""; shift ;;
    --profile) profile=1; shift ;;
    *) echo "compare_builds.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
done
if ! [[ "$rounds" =~ ^[1-9][0-9]*$ ]]; then
  echo "compare_builds.sh: --rounds must be a positive integer, got '$rounds'" >&2
  exit 2
fi

results=compare_builds.csv
echo "round,build,case,threads,particle_updates_per_second,heap_bytes_per_particle" > "$results"
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
for ((r = 1; r <= rounds; ++r)); do
  if ((r % 2)); then order="A B"; else order="B A"; fi  # neither build always goes first
  for which in $order; do
    bin=$a extra=()
    if [[ $which == B ]]; then
      bin=$b
      [[ -n "$profile" ]] && extra=(--profile)
    fi
    for c in ${cases//,/ }; do  # one process per case: the heap per particle is measured in a fresh process
      "$bin" $size --case "$c" --threads "$threads" --steps 20 "${extra[@]}" --csv "$tmp" > /dev/null 2>&1
      # With --profile the rate of the profiled repetition is the one that counts: recompute it from the
      # phase seconds (columns after repeat_rates) when they are there.
      tail -n +2 "$tmp" | /usr/bin/python3 -c '
import csv, sys
r, which, profiled = sys.argv[1], sys.argv[2], sys.argv[3] == "1"
header = "case,dim,shape,scheme,threads,particles,grid_nodes,steps,wall_seconds,particle_updates_per_second".split(",")
for row in csv.reader(sys.stdin):
    rate = float(row[9])
    heap = row[13] if len(row) > 13 and row[13] not in ("", "nan") else ""
    if profiled and len(row) > 15 and row[15]:
        seconds = sum(float(x) for x in row[15:] if x)
        rate = float(row[5]) * float(row[7]) / seconds
    print(f"{r},{which},{row[0]},{row[4]},{rate},{heap}")
' "$r" "$which" "$([[ $which == B && -n $profile ]] && echo 1 || echo 0)" >> "$results"
    done
  done
  echo "round $r of $rounds done" >&2
done

/usr/bin/python3 - "$results" "$a" "$b" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print(f"A = {sys.argv[2]}\nB = {sys.argv[3]}\n")
print("| case | threads | A best | A median | B best | B median | B/A (best) | B/A (median of rounds) | heap B/particle A | B |")
print("|---|---|---|---|---|---|---|---|---|---|")
for case in dict.fromkeys(r["case"] for r in rows):
    for t in dict.fromkeys(r["threads"] for r in rows if r["case"] == case):
        sel = lambda w, k: [float(r[k]) for r in rows if r["case"] == case and r["threads"] == t and r["build"] == w and r[k]]
        a, b = sel("A", "particle_updates_per_second"), sel("B", "particle_updates_per_second")
        heap = lambda w: f"{statistics.median(sel(w, 'heap_bytes_per_particle')):.0f}" if sel(w, "heap_bytes_per_particle") else "–"
        # A and B of the same round ran one after the other: their ratio cancels slow changes of the load.
        paired = statistics.median(x / y for x, y in zip(b, a))
        print(f"| {case} | {t} | {max(a):.4g} | {statistics.median(a):.4g} | {max(b):.4g} | {statistics.median(b):.4g} "
              f"| {max(b) / max(a):.3f} | {paired:.3f} | {heap('A')} | {heap('B')} |")
print(f"\n{max(int(r['round']) for r in rows)} runs per case and build, in alternating rounds; all in {sys.argv[1]}")
PY
