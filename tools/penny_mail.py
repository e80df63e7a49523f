#!/usr/bin/python3
"""A quarter block around a penny-shaped crack, in code_aster's .mail text format (tools/box_mail.py).

  penny_mail.py hexa8|tetra4 OUT.mail [--radius A] [--h H] [--block L] [--ratio Q]

The block 0 <= x, y <= L, -L <= z <= L holds the quarter x, y >= 0 of a crack of radius A in the
plane z = 0 centred on the origin (the planes x = 0 and y = 0 are the symmetry planes of the
whole block). Cells of size H up to 1.5 A in x and y and up to A / 2 in |z|, then growing by Q per
cell to the block's faces. No node lies on z = 0: the z nodes are +-H/2, +-3H/2, ... (the crack
never goes through a node). Groups of tools/box_mail.py (SG: x = 0, SB: y = 0, FACE: z = -L,
DOS: z = L, SD, SH, VOLU) and the nodes PTOP, PBOT = (L, L, +-H/2) (a pair mirrored in z = 0).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from box_mail import volume_grid  # noqa: E402


def graded(start, h, uniform_to, end, ratio):
    """start, start + h, ... up to uniform_to, then cells growing by ratio up to end (the last
    one stretched or merged so that the grid ends on end)."""
    xs = [start]
    while xs[-1] + h <= uniform_to + 1e-12 * h:
        xs.append(xs[-1] + h)
    step = h
    while end - xs[-1] > 1e-12 * h:
        step *= ratio
        if xs[-1] + 1.5 * step >= end:
            xs.append(end)
        else:
            xs.append(xs[-1] + step)
    return xs


def penny_quarter(kind, radius, h, block, ratio):
    plane = graded(0.0, h, 1.5 * radius, block, ratio)
    upper = graded(h / 2, h, radius / 2, block, ratio)
    zs = [-z for z in reversed(upper)] + upper
    title = "%s quarter block around a penny crack: A = %g, H = %g, L = %g, %d x %d x %d" % (
        kind, radius, h, block, len(plane) - 1, len(plane) - 1, len(zs) - 1)
    m = volume_grid(kind, plane, plane, zs, title)
    n, nz = len(plane), len(zs)
    node = lambda i, j, k: "N%d" % ((k * n + j) * n + i + 1)
    m.node_groups["PTOP"] = [node(n - 1, n - 1, nz // 2)]
    m.node_groups["PBOT"] = [node(n - 1, n - 1, nz // 2 - 1)]
    return m.text({"QUAD4", "TRIA3"})


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("kind", choices=["hexa8", "tetra4"])
    parser.add_argument("output")
    parser.add_argument("--radius", type=float, default=1.0)
    parser.add_argument("--h", type=float, default=1.0 / 6.0)
    parser.add_argument("--block", type=float, default=4.0)
    parser.add_argument("--ratio", type=float, default=1.3)
    args = parser.parse_args()
    with open(args.output, "w") as out:
        out.write(penny_quarter(args.kind.upper(), args.radius, args.h, args.block, args.ratio))


if __name__ == "__main__":
    main()
