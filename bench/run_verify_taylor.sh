#!/usr/bin/env bash
# Solution verification of the Taylor anvil (docs/verify.md, "Taylor anvil"): `mpm verify` on the TLMPM rod of
# examples/05_taylor_anvil (one particle per cell) at h = 1, 0.5 and 0.25 mm (the example's resolution, the
# finest run), on a grid whose extent is a multiple of 2 mm. Quantities: the change of the rod's length (z_span
# of the particle centres) and of its largest radius (the foot) from t = 0 to 80 us, free of the h-dependent
# gap between the outermost centres and the surface.
#   bash bench/run_verify_taylor.sh [BUILD] [OUT] [H0] [RUNS]   (defaults build/, /tmp/mpm_verify_taylor, 0.001
#                                                                m, 3; about 3 min on two idle cores, most of it
#                                                                the 0.25 mm run)
# `bash bench/run_verify_taylor.sh build OUT 0.002 4` adds h = 2 mm: the report then shows that the coarsest
# triple is not in the asymptotic range.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=${2:-/tmp/mpm_verify_taylor}
h0=${3:-0.001}
runs=${4:-3}
mkdir -p "$out"
cat > "$out/taylor.yaml" <<YAML
# Taylor anvil of examples/05_taylor_anvil (TLMPM, hat, 1 particle per cell) on a grid whose extent is a
# multiple of 2 mm. Written by bench/run_verify_taylor.sh.
dimension: 3
grid: {origin: [-0.004, -0.004, 0], extent: [0.008, 0.008, 0.026], cell_size: $h0, boundary: {z_min: slip}}
materials:
  copper: {model: johnson_cook, density: 8940, youngs_modulus: 115.0e9, poisson_ratio: 0.31, yield_stress: 65.0e6,
           hardening_coefficient: 356.0e6, hardening_exponent: 0.37, strain_rate_coefficient: 0.013,
           bulk_sound_speed: 3933, hugoniot_slope: 1.5, gruneisen_gamma: 0}
bodies:
  - {name: rod, material: copper, particles_per_cell: 1, velocity: [0, 0, -190],
     shape: {type: cylinder, center: [0, 0, 0], radius: 3.8e-3, length: 25.4e-3, axis: z}}
solver: {scheme: tlmpm, shape_function: linear, cfl: 0.5, end_time: 8.0e-5}
output:
  interval: 1.0e-5
  histories:
    - {name: length, type: extent, axis: z}
    - {name: foot, type: extent, radial: {axis: z, through: [0, 0, 0]}}
YAML
"$build/apps/mpm" verify "$out/taylor.yaml" --refine "$runs" --quantity length.z_span@0:8e-5 \
  --quantity foot.radius_max@0:8e-5 -o "$out/verify"
echo "report: $out/verify/verify.md"
