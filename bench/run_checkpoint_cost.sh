#!/usr/bin/env bash
# What a checkpoint costs (docs/PERFORMANCE.md, "Checkpoints"): for blocks of about 1e6 particles (2D
# linear elastic, 3D linear elastic, 3D Johnson-Cook with damage), `mpm run --steps 2` with a checkpoint
# after every step; prints per case the particles, the file size, bytes per particle, the write time that
# `mpm run` logs (gathering the state in id order, HDF5 write with checksums, fsync, rename) and the time
# `mpm checkpoint FILE` takes to read it back and verify every checksum.
#   bash bench/run_checkpoint_cost.sh [--mpm PATH] [--threads N] [--repeat N]
# The scenes and outputs go to a temporary directory that is removed at the end.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mpm="$root/build/apps/mpm" threads=2 repeat=2
while [[ $# -gt 0 ]]; do
  case "$1" in
    --mpm) mpm="${2:?--mpm needs a value}"; shift 2 ;;
    --threads) threads="${2:?--threads needs a value}"; shift 2 ;;
    --repeat) repeat="${2:?--repeat needs a value}"; shift 2 ;;
    *) echo "run_checkpoint_cost.sh: unknown option '$1'" >&2; sed -n '2,8p' "$0" >&2; exit 2 ;;
  esac
done
if [[ ! -x "$mpm" ]]; then
  echo "run_checkpoint_cost.sh: '$mpm' is not an executable (build the target mpm first)" >&2
  exit 2
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# 500 x 500 cells x 4 particles per cell, and 50^3 cells x 8: 1 000 000 particles each.
cat >"$work/2d_elastic.yaml" <<'EOF'
dimension: 2
grid: {origin: [0, 0], extent: [1.012, 1.012], cell_size: 0.002}
materials: {block: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}
bodies: [{name: block, material: block, shape: {type: box, min: [0.006, 0.006], max: [1.006, 1.006]}, particles_per_cell: 2, velocity: ["0.01*sin(3*x)", "0.01*cos(2*y)"]}]
solver: {scheme: musl, shape_function: linear, cfl: 0.3, end_time: 1000}
output: {fields: [], checkpoint: {interval: 1.0e-12, keep: 1}}
EOF
cat >"$work/3d_elastic.yaml" <<'EOF'
dimension: 3
grid: {origin: [0, 0, 0], extent: [1.12, 1.12, 1.12], cell_size: 0.02}
materials: {block: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}
bodies: [{name: block, material: block, shape: {type: box, min: [0.06, 0.06, 0.06], max: [1.06, 1.06, 1.06]}, particles_per_cell: 2, velocity: ["0.01*sin(3*x)", "0.01*cos(2*y)", "0.01*sin(2*z)"]}]
solver: {scheme: musl, shape_function: linear, cfl: 0.3, end_time: 1000}
output: {fields: [], checkpoint: {interval: 1.0e-12, keep: 1}}
EOF
cat >"$work/3d_johnson_cook.yaml" <<'EOF'
dimension: 3
grid: {origin: [0, 0, 0], extent: [1.12, 1.12, 1.12], cell_size: 0.02}
materials:
  copper: {model: johnson_cook, density: 8940, youngs_modulus: 115.0e9, poisson_ratio: 0.31, yield_stress: 65.0e6, hardening_coefficient: 356.0e6, hardening_exponent: 0.37, strain_rate_coefficient: 0.013, damage_d1: 0.54, damage_d2: 4.89, damage_d3: -3.03, damage_d4: 0.014}
bodies: [{name: block, material: copper, shape: {type: box, min: [0.06, 0.06, 0.06], max: [1.06, 1.06, 1.06]}, particles_per_cell: 2, velocity: [0, 0, -100]}]
solver: {scheme: musl, shape_function: linear, cfl: 0.3, end_time: 1000}
output: {fields: [], checkpoint: {interval: 1.0e-12, keep: 1}}
EOF

printf '%-18s %10s %10s %12s %10s %10s\n' case particles MB bytes/part write_s verify_s
for scene in 2d_elastic 3d_elastic 3d_johnson_cook; do
  [[ "$scene" == 3d_johnson_cook ]] && ! "$mpm" check "$work/$scene.yaml" >/dev/null 2>&1 && {
    echo "$scene: skipped (this build has no plasticity module)"
    continue
  }
  for ((k = 0; k < repeat; ++k)); do
    rm -rf "$work/out"
    log="$("$mpm" run "$work/$scene.yaml" --steps 2 --threads "$threads" -o "$work/out" 2>&1)"
    # "checkpoint: FILE (step 2, t = ...; X MB in Y s)": the second step's (the first touches fresh memory)
    line="$(grep '^checkpoint: .*(step 2,' <<<"$log")"
    file="$(sed -E 's/^checkpoint: ([^ ]+) .*/\1/' <<<"$line")"
    write_s="$(sed -E 's/.* in ([0-9.e+-]+) s\)$/\1/' <<<"$line")"
    particles="$(grep -oE '[0-9]+ particles' <<<"$log" | head -1 | cut -d' ' -f1)"
    bytes="$(stat -c %s "$file")"
    start="$(date +%s.%N)"
    "$mpm" checkpoint "$file" >/dev/null
    end="$(date +%s.%N)"
    awk -v c="$scene" -v n="$particles" -v b="$bytes" -v w="$write_s" -v s="$start" -v e="$end" \
      'BEGIN { printf "%-18s %10d %10.1f %12.1f %10.3f %10.3f\n", c, n, b / 1e6, b / n, w, e - s }'
  done
done
