#!/usr/bin/env python3
"""Writes prism.stl: a 12-sided prism, 16 mm across the corners and 1 mm tall, as an ASCII STL
(outward normals, counter-clockwise faces seen from outside). Usage: prism_stl.py OUTPUT.stl"""
import math
import sys

SIDES = 12
RADIUS_MM = 8.0
HEIGHT_MM = 1.0


def facet(out, a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    length = math.sqrt(sum(x * x for x in n))
    out.write("  facet normal %.6f %.6f %.6f\n    outer loop\n" % tuple(x / length for x in n))
    for p in (a, b, c):
        out.write("      vertex %.6f %.6f %.6f\n" % p)
    out.write("    endloop\n  endfacet\n")


def main():
    ring = [(RADIUS_MM * math.cos(2 * math.pi * k / SIDES), RADIUS_MM * math.sin(2 * math.pi * k / SIDES))
            for k in range(SIDES)]
    with open(sys.argv[1], "w") as out:
        out.write("solid prism\n")
        for k in range(SIDES):
            (x0, y0), (x1, y1) = ring[k], ring[(k + 1) % SIDES]
            facet(out, (0.0, 0.0, HEIGHT_MM), (x0, y0, HEIGHT_MM), (x1, y1, HEIGHT_MM))  # top, facing +z
            facet(out, (0.0, 0.0, 0.0), (x1, y1, 0.0), (x0, y0, 0.0))  # bottom, facing -z
            facet(out, (x0, y0, 0.0), (x1, y1, 0.0), (x1, y1, HEIGHT_MM))  # side
            facet(out, (x0, y0, 0.0), (x1, y1, HEIGHT_MM), (x0, y0, HEIGHT_MM))
        out.write("endsolid prism\n")


main()
