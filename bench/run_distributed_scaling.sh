#!/usr/bin/env bash
# Strong and weak scaling of distributed runs, per-phase times and the link figures, then the cost
# model fitted to them (bench/distributed_model.py). One command, one table:
#
#   bash bench/run_distributed_scaling.sh [--repeat N] [--steps N] [--quick] [--only CASES] [--csv FILE] [--baseline]
#
# Cases (each `mpirun --oversubscribe -np R build/apps/mpm run SCENE --threads T --steps N --profile`, with
# `--bind-to none` when T > 1):
#   2d  strong scaling, 2D linear-hat USL, the two disks of examples/02_two_disks at 1000 x 1000 cells
#       (1,005,304 particles): (ranks, threads) = (1,1), (1,2), (2,1)
#   3d  strong scaling, 3D cubic B-spline USL, two spheres at 77^3 cells (~2.4e5 particles): (1,1), (1,2), (2,1)
#   weak  5e5 particles per rank: the 2D scene at 707^2 cells (~5.0e5) on 1 rank, at 1000^2 (1.0e6) on 2 ranks
#   pingpong  bench_pingpong (one-way time 8 B .. 8 MB; latency and bandwidth)
# With 2d and 3d, every round also runs the machine's control ("0 x 1" in the table): two independent 1-rank runs
# of half the scene at once (2D: weak1; 3D: 61^3 cells, ~1.2e5 particles), no MPI; its wall is what a 2 x 1 run could take on this machine at that moment.
# Scenes are written from examples/02_two_disks/scene.yaml into a temporary directory (removed at the end).
# Each case runs N rounds (default 3), each round every configuration once (so that a drift of the machine's speed
# reaches all alike); the median stepping wall time is reported with its phases (s) and the machine's 1-minute load
# (uptime) before the run, and the speed-up both of the medians and paired (the median over the rounds of the
# round's 1 x 1 time over the configuration's): the machine may be shared, so say how loaded it was.
# `mpm run` prints rank 0's profile; with several ranks it also prints each phase's min and max over the ranks.
# --baseline: every multi-rank run is followed by the same run with `mpm run --exchange-every-scatter` (every
# scatter exchanges, as before session 16; same bits), rows "<case>_baseline": a before/after comparison under the same load. --quick: scenes 4x (2D) and ~3x (3D) smaller, a smoke test.
#
# Environment: MPM_BUILD_DIR (default build), MPM_BIN (default $MPM_BUILD_DIR/apps/mpm), MPIRUN (default mpirun). As root the OMPI_ALLOW_RUN_AS_ROOT pair is
# set here. Needs a build with MPM_WITH_MPI and the targets mpm and bench_pingpong.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${MPM_BUILD_DIR:-$here/build}
mpirun=${MPIRUN:-mpirun}
repeat=3
steps=40
only="pingpong,2d,3d,weak"
csv=""
quick=0
baseline=0
while [ $# -gt 0 ]; do
  case "$1" in
    --repeat) repeat=$2; shift 2 ;;
    --steps) steps=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --csv) csv=$2; shift 2 ;;
    --quick) quick=1; shift ;;
    --baseline) baseline=1; shift ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    *) echo "run_distributed_scaling.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
mpm=${MPM_BIN:-$build/apps/mpm}  # MPM_BIN: another build of mpm (a before/after comparison)
pingpong=$build/bench/bench_pingpong
for f in "$mpm" "$pingpong"; do
  [ -x "$f" ] || { echo "run_distributed_scaling.sh: $f missing (build the targets mpm and bench_pingpong)" >&2; exit 2; }
done
work=$(mktemp -d /tmp/mpm_scaling.XXXXXX)
trap 'rm -rf "$work"' EXIT
csv=${csv:-$build/distributed_scaling.csv}

# The scenes: examples/02_two_disks with another cell size, USL, a fixed small dt (the disks hardly move in the
# timed steps: the cost of a step, not a collision) and one output field.
make_scene() {  # name dim shape cell_size
  local name=$1 dim=$2 shape=$3 h=$4
  /usr/bin/python3 - "$here/examples/02_two_disks/scene.yaml" "$work/$name.yaml" "$dim" "$shape" "$h" <<'EOF'
import sys
src, dst, dim, shape, h = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4], sys.argv[5]
text = open(src).read()
text = text.replace("cell_size: 0.05", f"cell_size: {h}").replace("scheme: musl", "scheme: usl")
text = text.replace("shape_function: linear", f"shape_function: {shape}").replace("dt: 0.001", "dt: 2.0e-5")
text = text.replace("fields: [velocity, stress, von_mises_stress, body]", "fields: [velocity]")
if dim == 3:
    text = text.replace("dimension: 2", "dimension: 3").replace("origin: [0, 0]", "origin: [0, 0, 0]")
    text = text.replace("extent: [1, 1]", "extent: [1, 1, 1]")
    text = text.replace("type: disk, center: [0.2, 0.2]", "type: sphere, center: [0.2, 0.2, 0.2]")
    text = text.replace("type: disk, center: [0.8, 0.8]", "type: sphere, center: [0.8, 0.8, 0.8]")
    text = text.replace("velocity: [0.1, 0.1]", "velocity: [0.1, 0.1, 0.1]")
    text = text.replace("velocity: [-0.1, -0.1]", "velocity: [-0.1, -0.1, -0.1]")
open(dst, "w").write(text)
EOF
}
if [ $quick = 1 ]; then
  make_scene strong2d 2 linear 0.002; make_scene strong3d 3 cubic_bspline 0.025; make_scene weak1 2 linear 0.0028248587570621469
  make_scene weak2 2 linear 0.002; make_scene half3d 3 cubic_bspline 0.03125
else
  make_scene strong2d 2 linear 0.001; make_scene strong3d 3 cubic_bspline 0.012987012987012988; make_scene weak1 2 linear 0.0014144271570014145
  make_scene weak2 2 linear 0.001; make_scene half3d 3 cubic_bspline 0.01639344262295082
fi

load() { cut -d' ' -f1 /proc/loadavg; }

# One run: prints "wall particles p2g grid g2p stress halo migrate rebalance sort other halo_max migrate_max compute_min
# compute_max other_min other_max" (rank 0's phases; *_min, *_max over the ranks; compute = P2G + grid + G2P + stress:
# with equal particle counts, unequal compute means unequal cores) from the log of `mpm run`.
# ranks = 0: the machine's control, no MPI: two independent 1-rank runs of the scene at the same time (the half
# scenes: each what a rank of the 2 x 1 run holds); the slower one's wall and phases, the two runs' compute and other
# as min and max. What a 2 x 1 run could reach on this machine at that moment: on this VM the two vCPUs' speeds differ
# and drift, which no decomposition can undo (PERFORMANCE.md §16.6).
one_run() {  # ranks threads scene [extra mpm run option]
  local log=$work/run.log logs
  if [ "$1" = 0 ]; then
    "$mpm" run "$work/$3.yaml" --threads 1 --steps "$steps" --profile -o "$work/out_a" ${4:-} > "$log" 2>&1 &
    local a=$!
    "$mpm" run "$work/$3.yaml" --threads 1 --steps "$steps" --profile -o "$work/out_b" ${4:-} > "$log.b" 2>&1 ||
      { cat "$log.b" >&2; return 1; }
    wait $a || { cat "$log" >&2; return 1; }
    logs="$log $log.b"
  else
    # OpenMPI binds each rank to one core by default (up to two ranks): a rank with several threads must be unbound,
    # or its threads share one core (measured before this: 1 rank x 2 threads at 0.94x of 1 x 1).
    local bind=""
    [ "$2" -gt 1 ] && bind="--bind-to none"
    "$mpirun" --oversubscribe $bind -np "$1" "$mpm" run "$work/$3.yaml" --threads "$2" --steps "$steps" \
      --profile -o "$work/out" --rebalance-every 20 ${4:-} > "$log" 2>&1 || { cat "$log" >&2; return 1; }
    logs=$log
  fi
  /usr/bin/python3 - $logs <<'EOF'
import re, sys
def parse(path):
    text = open(path).read()
    done = re.search(r"done: \d+ steps .* in ([0-9.]+) s wall, .* particle-updates/s, (\d+) particles", text)
    phase = {}
    for name in ["P2G", "grid update", "G2P", "stress update", "halo", "migrate", "rebalance", "sort", "other"]:
        m = re.search(r"^" + re.escape(name) + r"\s+([0-9.]+)\s", text, re.M)
        phase[name] = float(m.group(1)) if m else 0.0
    spread = {}
    compute = sum(phase[k] for k in ["P2G", "grid update", "G2P", "stress update"])
    for name, alone in [("halo", phase["halo"]), ("migrate", phase["migrate"]), ("compute", compute),
                        ("other", phase["other"])]:
        m = re.search(r"^ranks' " + re.escape(name) + r": min ([0-9.]+) s, max ([0-9.]+) s", text, re.M)
        spread[name] = (float(m.group(1)), float(m.group(2))) if m else (alone, alone)
    return float(done.group(1)), int(done.group(2)), phase, spread
runs = [parse(p) for p in sys.argv[1:]]
wall, particles, phase, spread = max(runs, key=lambda r: r[0])
if len(runs) > 1:  # the control: the two runs' spread
    for name in ["compute", "other"]:
        spread[name] = (min(r[3][name][0] for r in runs), max(r[3][name][1] for r in runs))
    particles = sum(r[1] for r in runs)
print(wall, particles, *[f"{phase[k]:.4f}" for k in phase],
      f"{spread['halo'][1]:.4f}", f"{spread['migrate'][1]:.4f}", *[f"{v:.4f}" for v in spread["compute"]],
      *[f"{v:.4f}" for v in spread["other"]])
EOF
}

echo "case,ranks,threads,particles,steps,run,load,wall,p2g,grid,g2p,stress,halo,migrate,rebalance,sort,other,halo_max,migrate_max,compute_min,compute_max,other_min,other_max" > "$csv"
# Every configuration of a case once per round, the rounds repeated: the machine's speed drifts over minutes (a shared
# VM), and runs of one configuration in a row would each see another machine. The model pairs the runs of a round.
run_cases() {  # label "ranks threads scene" ...
  local label=$1; shift
  local k cfg ranks threads scene variant name setting l r wall particles rest
  for k in $(seq 1 "$repeat"); do
    for cfg in "$@"; do
      read -r ranks threads scene <<< "$cfg"
      for variant in "" baseline; do
        [ -z "$variant" ] || { [ "$baseline" = 1 ] && [ "$ranks" -gt 1 ]; } || continue
        name=$label setting=""
        [ -z "$variant" ] || { name=${label}_baseline; setting=--exchange-every-scatter; }
        l=$(load)
        r=$(one_run "$ranks" "$threads" "$scene" $setting)
        read -r wall particles rest <<< "$r"
        echo "$name,$ranks,$threads,$particles,$steps,$k,$l,$wall,$(echo "$rest" | tr ' ' ',')" >> "$csv"
        echo "  $name np $ranks x $threads threads, round $k: $wall s (load $l)" >&2
      done
    done
  done
}
echo "machine: $(nproc) cores, $(uptime)" >&2
if [[ $only == *pingpong* ]]; then
  for k in $(seq 1 "$repeat"); do
    l=$(load)
    line=$("$mpirun" --oversubscribe -np 2 "$pingpong" | grep '^model:')
    lat=$(echo "$line" | sed -E 's/.*latency ([0-9.]+) us.*/\1/')
    bw=$(echo "$line" | sed -E 's/.*bandwidth ([0-9.]+) MB.*/\1/')
    echo "pingpong,2,1,0,0,$k,$l,0,$lat,$bw,0,0,0,0,0,0,0,0,0,0,0,0,0" >> "$csv"
    echo "  pingpong run $k: latency $lat us, bandwidth $bw MB/s (load $l)" >&2
  done
fi
if [[ $only == *2d* ]]; then run_cases strong2d "1 1 strong2d" "1 2 strong2d" "2 1 strong2d" "0 1 weak1"; fi
if [[ $only == *3d* ]]; then run_cases strong3d "1 1 strong3d" "1 2 strong3d" "2 1 strong3d" "0 1 half3d"; fi
if [[ $only == *weak* ]]; then run_cases weak "1 1 weak1" "2 1 weak2"; fi
echo "machine after: $(uptime)" >&2
/usr/bin/python3 "$here/bench/distributed_model.py" "$csv"
