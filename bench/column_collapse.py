#!/usr/bin/env python3
"""Granular column collapse in plane strain against the run-out and final-height laws of Lube et al. (2005).

A column of width L0 = 0.1 m and height H0 = a L0 stands against a smooth back wall (x_min: slip) on a rough base
(y_min: fixed, no slip) and collapses under gravity from rest and zero stress; grains that reach the far end of the
grid (2.5 times the law's run-out) leave through it (x_max: outflow; the table counts them). The run-out is read from the last
frame: (L_inf - L0)/L0 with L_inf the edge of the connected deposit, the outermost particle reached from the back
wall through particles no further apart along x than one cell h (beyond a wider gap the points are detached grains
that slid on alone: the tail of a tall column's collapse), plus dp/2 (dp the initial particle spacing); the table
also gives the outermost particle of all (`extent` history, "farthest"). The final height H_inf = y_max(T) + dp/2. T = 12 sqrt(H0/g): the fronts have
stopped or creep (the table gives how far the front moved over the last twelfth of the run, in L0).

The laws (Lube, Huppert, Sparks & Freundt 2005, Phys. Rev. E 72, 041301, two-dimensional collapses in a channel):
  (L_inf - L0)/L0 = 1.2 a (a < 1.8),  1.9 a^(2/3) (a > 2.8);  H_inf/H0 = 1 (a < 1.15),  H_inf/L0 = a^(2/5) (a > 1.15).
Between 1.8 and 2.8 the two run-out branches differ by 25%; the table gives both.

The materials are the glass beads of Jop, Forterre & Pouliquen (2006): mu_i with mu_s = 0.38, mu_2 = 0.64,
I_0 = 0.279, d = 0.5 mm, rho_s = 2450 kg/m^3, and drucker_prager with the same static strength: the plane-strain cone
whose sqrt(J2)/P at yield is mu_s (eta = mu_s, theory eq. 18.3: phi = 22.92 deg), no dilation, no cohesion; both
with rho = 1470 kg/m^3 (solid fraction 0.6), E = 5 MPa, nu = 0.3. MUSL, quadratic B-splines, APIC, CFL 0.4.

    /usr/bin/python3 bench/column_collapse.py                       # the sweep of docs/verification-notes.md
    /usr/bin/python3 bench/column_collapse.py --models mu_i --aspect-ratios 0.5 --cells 10,20,40,80
    options: --mpm PATH (default build/apps/mpm), --out DIR (default build/column_collapse), --csv FILE

Prints a Markdown table (and writes it as CSV with --csv): model, a, cells per L0, particles, steps, wall time,
run-out, the law's run-out and the difference, H_inf/L0 and the law's, the share of the potential energy drop the
transfers dissipated (the part the plastic work does not book), and the front's move over the last twelfth (in L0).
"""
import csv
import math
import os
import sys

import scene_runs

G = 9.81
L0 = 0.1
PHI_DP = math.degrees(math.atan(3 * 0.38 / math.sqrt(9 - 12 * 0.38**2)))  # eta(phi) = mu_s, plane-strain cone

MATERIALS = {
    "mu_i": "{model: mu_i, density: 1470, youngs_modulus: 5.0e6, poisson_ratio: 0.3, mu_s: 0.38, mu_2: 0.64, "
    "I_0: 0.279, grain_diameter: 0.5e-3, grain_density: 2450}",
    "drucker_prager": "{model: drucker_prager, density: 1470, youngs_modulus: 5.0e6, poisson_ratio: 0.3, "
    f"friction_angle: {PHI_DP:.4f} deg, cone_matching: plane_strain}}",
}


def runout_law(a):
    """Lube et al. (2005): the branch of the aspect ratio, and in 1.8-2.8 both (linear, power)."""
    if a < 1.8:
        return 1.2 * a, None
    if a > 2.8:
        return 1.9 * a ** (2 / 3), None
    return 1.2 * a, 1.9 * a ** (2 / 3)


def height_law(a):
    """H_inf / L0 of Lube et al. (2005)."""
    return a if a < 1.15 else a**0.4


def scene(model, a, cells, shape="quadratic_bspline", particles_per_cell=2):
    """The scene text of one run and its end time."""
    h = L0 / cells
    H0 = a * L0
    reach = max(runout_law(a)[0], runout_law(a)[1] or 0)
    nx = math.ceil((1 + 2.5 * reach) * cells) + 2  # room for 2.5 times the law's run-out
    ny = math.ceil(H0 / h * 1.05) + 2
    end = 12 * math.sqrt(H0 / G)
    return (
        f"""# granular column collapse, a = {a}, {model}, L0/h = {cells} (bench/column_collapse.py)
dimension: 2
grid:
  origin: [0, 0]
  extent: [{nx * h:.10g}, {ny * h:.10g}]
  cell_size: {h:.10g}
  boundary: {{x_min: slip, y_min: fixed, x_max: outflow}}
materials:
  beads: {MATERIALS[model]}
bodies:
  - {{name: column, material: beads, shape: {{type: box, min: [0, 0], max: [{L0}, {H0:.10g}]}}, particles_per_cell: {particles_per_cell}}}
solver: {{scheme: musl, shape_function: {shape}, velocity_transfer: apic, cfl: 0.4, end_time: {end:.6g}, gravity: [0, -9.81]}}
output:
  interval: {end / 12:.6g}
  fields: [velocity, stress, plastic_strain]
  histories:
    - {{name: front, type: extent, axis: x}}
    - {{name: top, type: extent, axis: y}}
""",
        h / particles_per_cell,
    )


def column(rows, name):
    header = rows[0]
    for i, c in enumerate(header):
        if c.split(" ")[0] == name:
            return [float(r[i]) for r in rows[1:] if r[i] != ""]
    raise KeyError(f"{name} not in {header}")


def last_frame(out):
    """The particle x coordinates of the run's last frame, sorted."""
    return sorted(scene_runs.last_frame(out)[0][:, 0])


def deposit_edge(xs, gap):
    """The outermost of the sorted coordinates `xs` reached from the first without a step wider than `gap`."""
    edge = xs[0]
    for x in xs[1:]:
        if x - edge > gap:
            break
        edge = x
    return edge


def run(mpm, out, model, a, cells, shape):
    text, spacing = scene(model, a, cells, shape)
    case = os.path.join(out, f"{model}_a{a:g}_n{cells}_{shape}")
    wall = scene_runs.run_case(mpm, case, text)
    if wall is None:
        return None
    read = lambda name: list(csv.reader(open(os.path.join(case, "out", name))))
    front, top, energy = read("front.csv"), read("top.csv"), read("energy.csv")
    xmax, ymax = column(front, "x_max"), column(top, "y_max")
    farthest = (xmax[-1] - xmax[0]) / L0
    h = L0 / cells
    runout = (deposit_edge(last_frame(os.path.join(case, "out")), h) + spacing / 2 - L0) / L0
    creep = (xmax[-1] - xmax[-2]) / L0
    height = (ymax[-1] + spacing / 2) / L0
    gravity, plastic = column(energy, "gravity_potential_energy"), column(energy, "plastic_work")
    kinetic, strain = column(energy, "kinetic_energy"), column(energy, "strain_energy")
    drop = gravity[0] - gravity[-1]
    transfers = (drop - plastic[-1] - kinetic[-1] - strain[-1] + strain[0]) / drop
    steps = int(column(front, "step")[-1])
    law, other = runout_law(a)
    return {
        "model": model, "a": a, "cells": cells, "particles": int(column(front, "count")[0]),
        "left": int(column(front, "count")[0] - column(front, "count")[-1]), "steps": steps,
        "wall_s": round(wall, 1), "runout": runout, "farthest": farthest, "law": law, "law_power": other,
        "error": runout / law - 1, "error_power": (runout / other - 1) if other else None, "height": height,
        "height_law": height_law(a), "transfer_loss": transfers, "creep": creep,
    }


def main():
    p = scene_runs.sweep_parser(__doc__, "column_collapse")
    p.add_argument("--models", default="drucker_prager,mu_i")
    p.add_argument("--aspect-ratios", default="0.5,1,2,4")
    p.add_argument("--cells", default="20", help="cells per column width L0, comma-separated")
    p.add_argument("--shape", default="quadratic_bspline", help="shape_function of the runs")
    p.add_argument("--csv", default=None)
    o = p.parse_args()
    results = []
    print("| model | a | L0/h | particles | steps | wall s | (L_inf - L0)/L0 | law | difference | farthest | H_inf/L0 | law "
          "| transfers' share of the drop | front's move over the last twelfth | left through x_max |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for model in o.models.split(","):
        for a in [float(x) for x in o.aspect_ratios.split(",")]:
            for cells in [int(x) for x in o.cells.split(",")]:
                r = run(o.mpm, o.out, model, a, cells, o.shape)
                if r is None:
                    continue
                results.append(r)
                law = f"{r['law']:.3f}" + (f" / {r['law_power']:.3f}" if r["law_power"] else "")
                err = f"{100 * r['error']:+.1f}%" + (f" / {100 * r['error_power']:+.1f}%" if r["law_power"] else "")
                print(f"| {model} | {a:g} | {cells} | {r['particles']} | {r['steps']} | {r['wall_s']} | "
                      f"{r['runout']:.3f} | {law} | {err} | {r['farthest']:.3f} | {r['height']:.3f} | {r['height_law']:.3f} | "
                      f"{100 * r['transfer_loss']:.1f}% | {r['creep']:.4f} | {r['left']} |", flush=True)
    scene_runs.write_rows(o.csv, results)


if __name__ == "__main__":
    main()
