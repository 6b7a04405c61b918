#!/usr/bin/env python3
"""Slope stability by strength reduction (issue 52): the factor of safety of Griffiths & Lane's (1999) example 1
against their finite-element 1.4 and Bishop & Morgenstern's 1.38; docs/verification-notes.md, "Slope stability by
strength reduction"; tests/verification/strength_reduction.hpp is the same case.

The slope (plane strain): H = 10 m high, 2:1 (26.57 deg), a crest 1.2 H wide; depth factor D = 1 (G&L's example 1:
the rough base at the toe, the trapezoid of 12 m and 32 m) or D > 1 (a foundation (D - 1) H deep under the toe,
reaching 1.2 H beyond it, its far side on rollers). The left side is on rollers (x_min: slip), the base fixed
(y_min: fixed). Mohr-Coulomb, rho = 2000 kg/m^3, g = 10 m/s^2 (gamma = 20 kN/m^3), E = 100 MPa, nu = 0.3,
c = 0.05 gamma H = 10 kPa, phi = 20 deg, psi = 0, tension up to the apex c cot(phi) (which the reduction keeps).

Strength reduction: for a factor F the soil gets c/F and atan(tan(phi)/F); the geostatic stress (K0 = 1 - sin phi_F)
is put in and the gravity stage (docs/theory.md §20: local damping 0.8, PIC) steps until the unbalanced force ratio
stays below `--tolerance` for 10 steps, or gives up after the step limit. The slope stands at F when the stage
settles within the limit: the factor of safety lies between the largest F that settles and the smallest that does
not. That is Griffiths & Lane's criterion (no convergence of their visco-plastic iterations within 1000), with the
dynamic relaxation of Dawson, Roth & Drescher (1999) in FLAC in place of their iterations. Near the factor of safety
the steps to settle rise steeply, so the bracket depends on the limit, the more so on a coarse mesh: the limit is
`--limit` K times N(1), the steps the slope takes at F = 1 on the same mesh (K = 4 by default). The table gives the
steps (and N/N(1)) and the largest displacement of the stage for every F (the displacement jumps where the slope
fails), so the outcome for any smaller K can be read off it. `--bisect TOL` narrows the bracket to TOL.

    /usr/bin/python3 bench/strength_reduction.py                       # hats, 1 m and 0.5 m cells, the table
    /usr/bin/python3 bench/strength_reduction.py --cells 1 --factors 1.3,1.4,1.5,1.6 --bisect 0.02
    options: --mpm PATH (default build/apps/mpm), --out DIR (default build/strength_reduction), --shapes S,
             --depth-factor D, --tension apex|none, --tolerance R, --limit K, --max-steps N (a fixed limit instead of
             K N(1)), --threads N (1), --csv FILE
"""
import math
import os
import re
import sys

import scene_runs

H = 10.0  # m
RHO, G = 2000.0, 10.0  # kg/m^3, m/s^2
E, NU = 1.0e8, 0.3  # Pa
PHI = 20.0  # deg
C = 0.05 * RHO * G * H  # Pa: c / (gamma H) = 0.05


def reduced(F):
    """(phi_F in degrees, c_F in Pa) of the factor F."""
    return math.degrees(math.atan(math.tan(math.radians(PHI)) / F)), C / F


def outline(depth):
    """The slope's polygon (m), the grid's extent and whether its x_max face holds the foundation's far side."""
    crest, face = 1.2 * H, 2.0 * H
    if depth <= 1:
        return [[0, 0], [crest + face, 0], [crest, H], [0, H]], crest + face + 4, H + 4, False
    base = (depth - 1) * H
    width = crest + face + 1.2 * H
    return ([[0, 0], [width, 0], [width, base], [crest + face, base], [crest, base + H], [0, base + H]], width,
            base + H + 4, True)


def scene(F, cell, shape, depth, tolerance, max_steps, tension="apex"):
    phi, c = reduced(F)
    # the apex c_F cot(phi_F) is the same for every F; "none": no tension at all (the models' default)
    cutoff = C / math.tan(math.radians(PHI)) if tension == "apex" else 0.0
    vertices, x_extent, y_extent, far_side = outline(depth)
    faces = "x_min: slip, y_min: fixed" + (", x_max: slip" if far_side else "")
    return f"""# strength reduction F = {F:g}: c = {c:.6g} Pa, phi = {phi:.6g} deg (bench/strength_reduction.py)
dimension: 2
grid: {{origin: [0, 0], extent: [{x_extent:g}, {y_extent:g}], cell_size: {cell:g}, boundary: {{{faces}}}}}
materials:
  soil: {{model: mohr_coulomb, density: {RHO:g}, youngs_modulus: {E:g}, poisson_ratio: {NU}, friction_angle: {phi:.12g},
         cohesion: {c:.12g}, tension_cutoff: {cutoff:.12g}}}
bodies:
  - {{name: slope, material: soil, shape: {{type: polygon, vertices: {vertices}}}, volume: lattice}}
sets: {{all: {{body: slope}}}}
conditions: [{{set: all, initial_stress: geostatic}}]
solver:
  shape_function: {shape}
  cfl: 0.5
  end_time: 1.0e-3
  gravity: [0, {-G:g}]
  gravity_stage: {{tolerance: {tolerance:g}, max_steps: {max_steps}, on_no_equilibrium: warn}}
output: {{fields: [displacement, plastic_strain]}}
"""


STAGE = re.compile(r"gravity stage: (at rest|not at rest) after (\d+) steps \(unbalanced force ratio ([0-9.eE+-]+)"
                   r".*largest displacement ([0-9.eE+-]+) m\)")


def run_factor(o, cell, shape, F, max_steps):
    """One run: {F, settled, steps, ratio, displacement (m), wall (s)}, or None when mpm failed."""
    case = os.path.join(o.out, f"{shape}_h{cell:g}_D{o.depth_factor:g}_{o.tension}", f"F{F:.4f}")
    text = scene(F, cell, shape, o.depth_factor, o.tolerance, max_steps, o.tension)
    wall, log = scene_runs.run_case_logged(o.mpm, case, text, ["--threads", str(o.threads), "--steps", "1"])
    m = STAGE.search(log)
    if wall is None or not m:
        sys.stderr.write(f"{case}: no gravity stage line in the log\n")
        return None
    row = {"shape": shape, "cell": cell, "F": F, "settled": m.group(1) == "at rest", "steps": int(m.group(2)),
           "limit": max_steps, "ratio": float(m.group(3)), "displacement": float(m.group(4)), "wall": wall}
    print(f"  F = {F:.4f}: {'settled' if row['settled'] else 'NOT settled'} after {row['steps']} steps "
          f"(ratio {row['ratio']:.3g}), largest displacement {1e3 * row['displacement']:.2f} mm, {wall:.1f} s",
          flush=True)
    return row


def main():
    p = scene_runs.sweep_parser(__doc__, "strength_reduction")
    p.add_argument("--shapes", default="linear")
    p.add_argument("--cells", default="1,0.5", help="cell sizes in m, comma-separated")
    p.add_argument("--factors", default="1.2,1.3,1.4,1.5,1.6", help="strength reduction factors, comma-separated")
    p.add_argument("--depth-factor", type=float, default=1.0, help="D: 1 (G&L's example 1) or more")
    p.add_argument("--tolerance", type=float, default=1e-4, help="of the unbalanced force ratio")
    p.add_argument("--limit", type=float, default=4.0, help="the step limit in steps to settle at F = 1")
    p.add_argument("--tension", default="apex", choices=["apex", "none"], help="tension up to the apex, or none")
    p.add_argument("--max-steps", type=int, default=None, help="a fixed step limit instead of --limit")
    p.add_argument("--bisect", type=float, default=None, help="narrow the bracket to this width")
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--csv", default=None)
    o = p.parse_args()
    results = []
    for shape in o.shapes.split(","):
        for cell in (float(x) for x in o.cells.split(",")):
            print(f"{shape}, {cell:g} m cells ({H / cell:g} per H), D = {o.depth_factor:g}:", flush=True)
            n1 = None
            if o.max_steps:
                limit = o.max_steps
            else:
                first = run_factor(o, cell, shape, 1.0, int(400000 * max(1.0, 1 / cell)))
                if first is None or not first["settled"]:
                    continue
                n1 = first["steps"]
                limit = int(round(o.limit * n1))
                print(f"  the step limit: {o.limit:g} x {first['steps']} = {limit}")
            rows = [r for r in (run_factor(o, cell, shape, float(F), limit) for F in o.factors.split(",")) if r]
            while o.bisect and rows:
                lo = max((r["F"] for r in rows if r["settled"]), default=None)
                hi = min((r["F"] for r in rows if not r["settled"]), default=None)
                if lo is None or hi is None or hi - lo <= o.bisect * 1.0001:
                    break
                r = run_factor(o, cell, shape, round(0.5 * (lo + hi), 4), limit)
                if r is None:
                    break
                rows.append(r)
            rows.sort(key=lambda r: r["F"])
            lo = max((r["F"] for r in rows if r["settled"]), default=None)
            hi = min((r["F"] for r in rows if not r["settled"]), default=None)
            print(f"  factor of safety: above {lo}, below {hi} (step limit {limit}); Griffiths & Lane 1.4, "
                  "Bishop & Morgenstern 1.38")
            print("\n| F | settled | steps | steps / N(F = 1) | largest displacement (mm) | wall (s) |\n"
                  "|---|---|---|---|---|---|")
            for r in rows:
                ratio = "-" if n1 is None else f"{r['steps'] / n1:.2f}"
                print(f"| {r['F']:.4g} | {'yes' if r['settled'] else 'no'} | {r['steps']} | {ratio} | "
                      f"{1e3 * r['displacement']:.2f} | {r['wall']:.1f} |")
            print(flush=True)
            results += rows
    scene_runs.write_rows(o.csv, results)


if __name__ == "__main__":
    main()
