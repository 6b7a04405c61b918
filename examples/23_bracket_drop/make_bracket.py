#!/usr/bin/env python3
"""Writes bracket.stl: an L-bracket in mm, a 40 x 6 mm flange and a 6 x 34 mm web (the profile in the x-y plane)
extruded 30 mm along z, as a closed ASCII STL with outward normals.

    /usr/bin/python3 examples/23_bracket_drop/make_bracket.py [bracket.stl]
"""
import sys

PROFILE = [(0, 0), (40, 0), (40, 6), (6, 6), (6, 40), (0, 40)]  # counter-clockwise, star-shaped about (0, 0)
DEPTH = 30.0


def facet(out, a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
    length = sum(x * x for x in n) ** 0.5
    out.write("facet normal %g %g %g\n outer loop\n" % tuple(x / length for x in n))
    for p in (a, b, c):
        out.write("  vertex %g %g %g\n" % p)
    out.write(" endloop\nendfacet\n")


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "bracket.stl"
    with open(path, "w") as out:
        out.write("solid bracket\n")
        for k in range(1, len(PROFILE) - 1):  # the end caps: a fan from (0, 0)
            a, b, c = PROFILE[0], PROFILE[k], PROFILE[k + 1]
            facet(out, (*a, 0.0), (*c, 0.0), (*b, 0.0))
            facet(out, (*a, DEPTH), (*b, DEPTH), (*c, DEPTH))
        for i, p in enumerate(PROFILE):  # the sides
            q = PROFILE[(i + 1) % len(PROFILE)]
            facet(out, (*p, 0.0), (*q, 0.0), (*q, DEPTH))
            facet(out, (*p, 0.0), (*q, DEPTH), (*p, DEPTH))
        out.write("endsolid bracket\n")


if __name__ == "__main__":
    main()
