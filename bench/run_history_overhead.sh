#!/usr/bin/env bash
# The cost of output.histories: examples/09_ring_crush (15,400 particles, MUSL, contact with two
# rigid platens, J2 plasticity) for N steps on one thread, in three variants run in alternation, ROUNDS times:
#   none        the scene without histories (what any scene without them builds: nothing)
#   example     the scene as committed: two platen reactions every 10 us (accumulated every step)
#   every_step  every kind every step: both reactions, a box probe over the ring (stress, von Mises, plastic
#               strain, velocity; mean, min, max, sum), a particle and a grid point probe, the ring's energy
#               and its extent
# and prints each run's CPU seconds (user + system) and the output phase of --profile (where histories are
# sampled and written). The CPU time is robust to a loaded machine, the wall time is not.
#   bash bench/run_history_overhead.sh [BUILD] [STEPS] [ROUNDS]   (defaults build/, 600, 3; ~20 s per run idle)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
steps=${2:-600}
rounds=${3:-3}
dir=$(mktemp -d /tmp/mpm_history_overhead.XXXXXX)
scene=examples/09_ring_crush/scene.yaml
sed '/^  histories:/,$d' "$scene" > "$dir/none.yaml"
cp "$scene" "$dir/example.yaml"
{
  sed '/^  histories:/,$d' "$scene"
  cat <<'YAML'
  histories:  # every kind, every step (an interval below the time step)
    - {name: top_platen, type: reaction, body: top_platen, interval: 1.0e-12}
    - {name: bottom_platen, type: reaction, body: bottom_platen, interval: 1.0e-12}
    - {name: ring_box, type: probe, body: ring, box: {min: [-0.04, -0.032], max: [0.04, 0.032]},
       fields: [stress, von_mises_stress, plastic_strain, velocity], statistics: [mean, min, max, sum],
       interval: 1.0e-12}
    - {name: gauge, type: probe, body: ring, point: [0.0247, 0], fields: [stress, velocity], interval: 1.0e-12}
    - {name: gauge_grid, type: probe, body: ring, point: [0.0247, 0], from: grid, fields: [velocity],
       interval: 1.0e-12}
    - {name: ring_energy, type: energy, body: ring, interval: 1.0e-12}
    - {name: width, type: extent, body: ring, axis: x, interval: 1.0e-12}
YAML
} > "$dir/every_step.yaml"
printf '%-11s %5s %9s %9s %10s\n' variant round cpu_s wall_s output_s
for round in $(seq 1 "$rounds"); do
  for variant in none example every_step; do
    out="$dir/out_$variant"
    rm -rf "$out"
    /usr/bin/time -f '%U %S %e' -o "$dir/time" "$build/apps/mpm" run "$dir/$variant.yaml" -o "$out" \
      --threads 1 --steps "$steps" --profile > "$dir/log" 2>&1
    read -r user sys wall < "$dir/time"
    output=$(sed -n 's/^output *\([0-9.e+-]*\) .*/\1/p' "$dir/log" | head -1)
    printf '%-11s %5d %9.2f %9.2f %10s\n' "$variant" "$round" "$(echo "$user + $sys" | bc)" "$wall" "${output:-?}"
  done
done
echo "scenes and the last logs in $dir"
