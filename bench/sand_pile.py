#!/usr/bin/env python3
"""Angle of repose of a cohesionless sand pile in plane strain (issue 52, item 4): the ladders of
docs/verification-notes.md, "Angle of repose of a sand pile"; tests/verification/sand_pile.hpp is the same case.

Half of a symmetric pile: a column of sand L0 = 1 m wide and H0 = a L0 tall (or, with --initial DEG, a triangle whose
flank stands DEG degrees steeper than phi) against a smooth wall (x_min: slip, the pile's plane of symmetry) on a
rough base (y_min: fixed, no slip), released from rest and zero stress under gravity with local (Cundall) damping
(`solver.damping`, docs/theory.md eq. 2.74), run for T = `--time` sqrt(H0/g). Its flank fails, flows and stops. The
slope is read from the last frame:

  - the free surface: the particles sorted into columns of one cell h along x, the highest particle of each column
    (its x and its y + dp/2, dp the initial particle spacing);
  - the flank: those surface points whose height lies between 25% and 75% of the pile's height H (the highest surface
    point), which leaves out the toe (the thin front) and the crest (the rounded shoulder);
  - the angle: the least-squares line y = c0 + c1 x through the flank points, beta = atan(-c1); the table gives the
    rms distance of the points from the line (in dp): how straight the flank is.

The references (docs/theory.md eqs. 18.25-18.27): a slope can stand up to the static limit, phi for Mohr-Coulomb and
phi_ps of eq. 18.26 for Drucker-Prager in plane strain (asin(eta) without dilation); a layer flowing down the surface
stops at tan(beta_flow) = sin(phi_ps) cos(psi_ps) / (1 - sin(phi_ps) sin(psi_ps)) (Davis 1968): atan(sin phi) for
Mohr-Coulomb and atan(eta) for the cone without dilation. With associated flow both are phi for Mohr-Coulomb and the
plane_strain cone. `--models mu_i` runs the mu(I) rheology with mu_s = tan(phi) (mu_2 = mu_s + 0.26, I_0 = 0.279,
d = 0.5 mm, rho_s = 2650 kg/m^3): its flowing limit is atan(mu_s) = phi, its static limit asin(mu_s).

Sand: rho = 1800 kg/m^3, E = 2 MPa, nu = 0.3 (rho g H0 / E = 0.9% at a = 1), c = 0. MUSL, quadratic B-splines, APIC,
2 particles per cell per axis, CFL 0.4.

    /usr/bin/python3 bench/sand_pile.py                              # the table of docs/verification-notes.md
    /usr/bin/python3 bench/sand_pile.py --models mohr_coulomb --angles 25 --cells 10,20,40 --damping 0,0.5,0.8
    options: --mpm PATH (default build/apps/mpm), --out DIR (default build/sand_pile), --time T, --aspect-ratio A,
             --dilation {zero,associated}, --matching M, --shape S, --initial column|DEG, --youngs-modulus E, --csv FILE
"""
import csv
import math
import os
import sys

import scene_runs

G = 9.81
L0 = 1.0
RHO, E, NU = 1800.0, 2.0e6, 0.3


def cone(phi, matching):
    """eta of the Drucker-Prager cone matched to Mohr-Coulomb (docs/theory.md eq. 18.3), phi in degrees."""
    s, t = math.sin(math.radians(phi)), math.tan(math.radians(phi))
    if matching == "outer_cone":
        return 6 * s / (math.sqrt(3) * (3 - s))
    if matching == "inner_cone":
        return 6 * s / (math.sqrt(3) * (3 + s))
    return 3 * t / math.sqrt(9 + 12 * t * t)


def plane_angles(model, phi, psi, matching):
    """(phi_ps, psi_ps) in degrees: the Mohr-Coulomb angles of the in-plane Mohr circle and flow (docs/theory.md
    eq. 18.26 for Drucker-Prager in plane strain, d eps_zz^p = 0; phi and psi themselves for Mohr-Coulomb)."""
    if model == "mohr_coulomb":
        return phi, psi
    if model == "mu_i":  # the cone eta = mu_s = tan(phi), isochoric (docs/theory.md §18, "Slope limits")
        return math.degrees(math.asin(math.tan(math.radians(phi)))), 0.0
    eta, eta_bar = cone(phi, matching), cone(psi, matching)
    phi_ps = math.asin(eta * math.sqrt(1 - eta_bar**2 / 3) / (1 - eta * eta_bar / 3))
    psi_ps = math.asin(eta_bar / math.sqrt(1 - eta_bar**2 / 3))
    return math.degrees(phi_ps), math.degrees(psi_ps)


def slope_limits(model, phi, psi, matching):
    """(static, flowing) slope limits in degrees (docs/theory.md eqs. 18.25-18.27)."""
    phi_ps, psi_ps = (math.radians(x) for x in plane_angles(model, phi, psi, matching))
    flow = math.atan(math.sin(phi_ps) * math.cos(psi_ps) / (1 - math.sin(phi_ps) * math.sin(psi_ps)))
    return math.degrees(phi_ps), math.degrees(flow)


def material(model, phi, psi, matching, youngs=E):
    if model == "mu_i":  # mu_s = tan(phi): Jop et al.'s angle at which flow starts; mu_2 - mu_s of their glass beads
        mu_s = math.tan(math.radians(phi))
        return (f"{{model: mu_i, density: {RHO:g}, youngs_modulus: {youngs:g}, poisson_ratio: {NU}, mu_s: {mu_s:.10g}, "
                f"mu_2: {mu_s + 0.26:.10g}, I_0: 0.279, grain_diameter: 0.5e-3, grain_density: 2650}}")
    m = (f"{{model: {model}, density: {RHO:g}, youngs_modulus: {youngs:g}, poisson_ratio: {NU}, friction_angle: {phi:g}, "
         f"dilation_angle: {psi:g}")
    return m + (f", cone_matching: {matching}}}" if model == "drucker_prager" else "}")


def body(phi, a, initial):
    """The initial shape: `column` (a box L0 x a L0) or `wedge` (the triangle of height a L0 whose flank stands
    `initial` degrees steeper than phi)."""
    H0 = a * L0
    if initial == "column":
        return f"{{type: box, min: [0, 0], max: [{L0}, {H0:.10g}]}}", L0
    w = H0 / math.tan(math.radians(phi + float(initial)))
    return f"{{type: polygon, vertices: [[0, 0], [{w:.10g}, 0], [0, {H0:.10g}]]}}", w


def scene(model, phi, psi, matching, a, cells, damping, time_factor, shape, initial="column", youngs=E):
    """The scene text of one run and its particle spacing."""
    h = L0 / cells
    H0 = a * L0
    shape_text, width = body(phi, a, initial)
    reach = width + 1.3 * H0 / math.tan(math.radians(min(phi, 25)))  # room for a pile flatter than the limit
    nx = math.ceil(reach / h) + 4
    ny = math.ceil(H0 / h * 1.05) + 2
    end = time_factor * math.sqrt(H0 / G)
    return (
        f"""# sand pile, {model} phi = {phi:g} psi = {psi:g}, a = {a}, L0/h = {cells}, damping {damping} (bench/sand_pile.py)
dimension: 2
grid:
  origin: [0, 0]
  extent: [{nx * h:.10g}, {ny * h:.10g}]
  cell_size: {h:.10g}
  boundary: {{x_min: slip, y_min: fixed}}
materials:
  sand: {material(model, phi, psi, matching, youngs)}
bodies:
  - {{name: pile, material: sand, shape: {shape_text}, particles_per_cell: 2}}
solver: {{scheme: musl, shape_function: {shape}, velocity_transfer: apic, cfl: 0.4, end_time: {end:.6g}, gravity: [0, -9.81], damping: {damping}}}
output:
  interval: {end / 10:.6g}
  fields: [velocity, stress, plastic_strain]
""",
        h / 2,
    )


def last_frame(out):
    """Positions x, y and velocities of the run's last frame."""
    x, v = scene_runs.last_frame(out)
    return x[:, 0], x[:, 1], v


def surface(xs, ys, h, spacing):
    """The highest particle of each column of width h along x: (x, y + spacing/2), sorted by x."""
    top = {}
    for x, y in zip(xs, ys):
        k = int(math.floor(x / h))
        if k not in top or y > top[k][1]:
            top[k] = (x, y)
    return [(x, y + spacing / 2) for _, (x, y) in sorted(top.items())]


def flank_angle(points, low=0.25, high=0.75):
    """The least-squares slope angle (degrees) of the surface points with heights in [low H, high H], H the highest;
    returns (angle, number of points, rms distance from the line)."""
    H = max(y for _, y in points)
    sel = [(x, y) for x, y in points if low * H <= y <= high * H]
    n = len(sel)
    if n < 3:  # no flank yet (a column that has not failed)
        return float("nan"), n, float("nan")
    mx, my = sum(x for x, _ in sel) / n, sum(y for _, y in sel) / n
    sxx = sum((x - mx) ** 2 for x, _ in sel)
    sxy = sum((x - mx) * (y - my) for x, y in sel)
    c1 = sxy / sxx
    rms = math.sqrt(sum((y - my - c1 * (x - mx)) ** 2 for x, y in sel) / n) * math.cos(math.atan(c1))
    return math.degrees(math.atan(-c1)), n, rms


def run(mpm, out, model, phi, psi, matching, a, cells, damping, time_factor, shape, initial="column", youngs=E):
    text, spacing = scene(model, phi, psi, matching, a, cells, damping, time_factor, shape, initial, youngs)
    case = os.path.join(out, f"{model}_phi{phi:g}_psi{psi:g}_a{a:g}_n{cells}_d{damping:g}_t{time_factor:g}_{shape}_{initial}_E{youngs:g}")
    wall = scene_runs.run_case(mpm, case, text)
    if wall is None:
        return None
    xs, ys, v = last_frame(os.path.join(case, "out"))
    angle, n, rms = flank_angle(surface(xs, ys, L0 / cells, spacing))
    energy = list(csv.reader(open(os.path.join(case, "out", "energy.csv"))))
    steps = int(float(energy[-1][1]))
    speed = math.sqrt(sum(float(c) ** 2 for row in v for c in row) / len(v)) / math.sqrt(G * a * L0)
    static, flow = slope_limits(model, phi, psi, matching)
    return {"model": model, "phi": phi, "psi": psi, "static_limit": static, "flow_limit": flow, "a": a, "cells": cells, "damping": damping,
            "time": time_factor, "particles": len(xs), "steps": steps, "wall_s": round(wall, 1), "angle": angle,
            "difference": angle - flow, "flank_points": n, "rms_dp": rms / spacing,
            "height": max(ys) + spacing / 2, "toe": max(xs) + spacing / 2, "speed": speed}


def main():
    p = scene_runs.sweep_parser(__doc__, "sand_pile")
    p.add_argument("--models", default="mohr_coulomb,drucker_prager")
    p.add_argument("--angles", default="25,35", help="friction angles, degrees")
    p.add_argument("--dilation", default="zero", choices=["zero", "associated"])
    p.add_argument("--matching", default="plane_strain")
    p.add_argument("--aspect-ratio", type=float, default=1.0)
    p.add_argument("--cells", default="20", help="cells per column width L0, comma-separated")
    p.add_argument("--damping", default="0.8", help="solver.damping values, comma-separated")
    p.add_argument("--time", default="40", help="end times in sqrt(H0/g), comma-separated")
    p.add_argument("--shape", default="quadratic_bspline")
    p.add_argument("--initial", default="column", help="column, or the wedge's excess angle over phi in degrees")
    p.add_argument("--youngs-modulus", type=float, default=E, help="Pa")
    p.add_argument("--csv", default=None)
    o = p.parse_args()
    results = []
    print("| model | phi | psi | static limit | flowing limit | a | L0/h | damping | T/sqrt(H0/g) | particles | steps "
          "| wall s | angle | against the flowing limit | flank points | rms (dp) | H/L0 | toe/L0 | rms speed/sqrt(g H0) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for model in o.models.split(","):
        for phi in [float(x) for x in o.angles.split(",")]:
            psi = phi if o.dilation == "associated" else 0.0
            for cells in [int(x) for x in o.cells.split(",")]:
                for damping in [float(x) for x in o.damping.split(",")]:
                    for tf in [float(x) for x in o.time.split(",")]:
                        r = run(o.mpm, o.out, model, phi, psi, o.matching, o.aspect_ratio, cells, damping, tf, o.shape,
                                o.initial, o.youngs_modulus)
                        if r is None:
                            continue
                        results.append(r)
                        print(f"| {model} | {phi:g} | {psi:g} | {r['static_limit']:.2f} | {r['flow_limit']:.2f} | "
                              f"{o.aspect_ratio:g} | {cells} | "
                              f"{damping:g} | {tf:g} | {r['particles']} | {r['steps']} | {r['wall_s']} | "
                              f"{r['angle']:.2f} | {r['difference']:+.2f} | {r['flank_points']} | {r['rms_dp']:.2f} | "
                              f"{r['height']:.3f} | {r['toe']:.3f} | {r['speed']:.1e} |", flush=True)
    scene_runs.write_rows(o.csv, results)


if __name__ == "__main__":
    main()
