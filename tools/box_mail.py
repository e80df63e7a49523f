#!/usr/bin/python3
"""Structured box meshes in code_aster's .mail text format (LIRE_MAILLAGE FORMAT='ASTER').

  box_mail.py quad4|tria3 NX NY OUT.mail [--size LX LY] [--title TEXT]
  box_mail.py hexa8|tetra4 NX NY NZ OUT.mail [--size LX LY LZ] [--title TEXT]

Domain [0,LX] x [0,LY] (x [0,LZ]), default 2 x 4 (x 1): the scenes of the four-interface cases
(astest/xfem_four_*). Nodes N1... row by row (then layer by layer), cells M1... written type by
type in MED type order (skin before volumes, as IMPR_RESU writes them), so that a MED conversion
keeps the numbering. Groups:
  2D: SURF (QUAD4, or two TRIA3 per square split along its (0,0)-(1,1) diagonal); SEG2 sides LB (y = 0), LD (x = LX), LH (y = LY), LG (x = 0), counter-clockwise.
  3D: VOLU; outward skin SB (y = 0), SD (x = LX), SH (y = LY), SG (x = 0), FACE (z = 0),
      DOS (z = LZ): QUAD4 on hexa8, two TRIA3 per square on tetra4 (the diagonals of the
      tetrahedra: each cube is split in the 6 tetrahedra around its (0,0,0)-(1,1,1) diagonal).
  Both: GROUP_NO PIN = the node (LX, 0[, 0]).
"""
import argparse
import itertools


def fmt_node(name, xyz):
    return " %-8s " % name + " ".join("%21.14E" % v for v in xyz)


def wrapped(head, items, per_line=7):
    lines = [head + " ".join(items[:per_line])]
    for k in range(per_line, len(items), per_line):
        lines.append(" " * 10 + " ".join(items[k:k + per_line]))
    return lines


def kuhn_tetrahedra():
    """The 6 tetrahedra of the unit cube around its main diagonal, positively oriented."""
    out = []
    for perm in itertools.permutations(range(3)):
        p, path = [0, 0, 0], [(0, 0, 0)]
        for axis in perm:
            p[axis] = 1
            path.append(tuple(p))
        a, b, c, d = path
        u, v, w = ([q[t] - a[t] for t in range(3)] for q in (b, c, d))
        det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])
        out.append([a, b, c, d] if det > 0 else [a, c, b, d])
    return out


class MailWriter:
    def __init__(self, title, dim):
        self.title, self.dim = title, dim
        self.nodes, self.cells, self.cell_groups, self.node_groups = [], [], {}, {}

    def add_cell(self, kind, nodes, group):
        self.cells.append((kind, nodes))
        self.cell_groups.setdefault(group, []).append(len(self.cells) - 1)

    def text(self, skin_kinds):
        order = sorted(range(len(self.cells)), key=lambda c: 0 if self.cells[c][0] in skin_kinds else 1)
        names = {c: "M%d" % (rank + 1) for rank, c in enumerate(order)}
        out = ["TITRE", " " + self.title, "FINSF", "COOR_%dD" % self.dim]
        out += [fmt_node(name, xyz[:self.dim]) for name, xyz in self.nodes]
        out.append("FINSF")
        current = None
        for c in order:
            kind, nodes = self.cells[c]
            if kind != current:
                out += ([] if current is None else ["FINSF"]) + [kind]
                current = kind
            out += wrapped(" %-8s " % names[c], nodes)
        out.append("FINSF")
        for group, members in self.cell_groups.items():
            out += ["GROUP_MA NOM=" + group] + wrapped("  ", [names[c] for c in members]) + ["FINSF"]
        for group, members in self.node_groups.items():
            out += ["GROUP_NO NOM=" + group] + wrapped("  ", members) + ["FINSF"]
        return "\n".join(out + ["FIN"]) + "\n"


def plane_box(kind, nx, ny, lx, ly, title):
    m = MailWriter(title, 2)
    name = lambda i, j: "N%d" % (j * (nx + 1) + i + 1)
    for j in range(ny + 1):
        for i in range(nx + 1):
            m.nodes.append((name(i, j), (lx * i / nx, ly * j / ny, 0.)))
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = name(i, j), name(i + 1, j), name(i + 1, j + 1), name(i, j + 1)
            if kind == "QUAD4":
                m.add_cell("QUAD4", [a, b, c, d], "SURF")
            else:
                m.add_cell("TRIA3", [a, b, c], "SURF")
                m.add_cell("TRIA3", [a, c, d], "SURF")
    for i in range(nx):
        m.add_cell("SEG2", [name(i, 0), name(i + 1, 0)], "LB")
    for j in range(ny):
        m.add_cell("SEG2", [name(nx, j), name(nx, j + 1)], "LD")
    for i in range(nx, 0, -1):
        m.add_cell("SEG2", [name(i, ny), name(i - 1, ny)], "LH")
    for j in range(ny, 0, -1):
        m.add_cell("SEG2", [name(0, j), name(0, j - 1)], "LG")
    m.node_groups["PIN"] = [name(nx, 0)]
    return m.text({"SEG2"})


def volume_box(kind, nx, ny, nz, lx, ly, lz, title):
    grid = volume_grid(kind, [lx * i / nx for i in range(nx + 1)], [ly * j / ny for j in range(ny + 1)],
                       [lz * k / nz for k in range(nz + 1)], title)
    return grid.text({"QUAD4", "TRIA3"})


def volume_grid(kind, xs, ys, zs, title):
    """The box of the tensor grid xs x ys x zs (increasing coordinates): a MailWriter, its node
    names N((k * (ny + 1) + j) * (nx + 1) + i + 1), the groups of volume_box."""
    nx, ny, nz = len(xs) - 1, len(ys) - 1, len(zs) - 1
    m = MailWriter(title, 3)
    name = lambda i, j, k: "N%d" % ((k * (ny + 1) + j) * (nx + 1) + i + 1)
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                m.nodes.append((name(i, j, k), (xs[i], ys[j], zs[k])))
    hexa = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                shapes = [hexa] if kind == "HEXA8" else kuhn_tetrahedra()
                for shape in shapes:
                    m.add_cell(kind, [name(i + a, j + b, k + c) for a, b, c in shape], "VOLU")

    def face(group, quad):  # quad: outward, first vertex the cube's lowest corner of the face
        if kind == "HEXA8":
            m.add_cell("QUAD4", quad, group)
        else:
            m.add_cell("TRIA3", [quad[0], quad[1], quad[2]], group)
            m.add_cell("TRIA3", [quad[0], quad[2], quad[3]], group)

    for k in range(nz):
        for i in range(nx):
            face("SB", [name(i, 0, k), name(i + 1, 0, k), name(i + 1, 0, k + 1), name(i, 0, k + 1)])
            face("SH", [name(i, ny, k), name(i, ny, k + 1), name(i + 1, ny, k + 1), name(i + 1, ny, k)])
        for j in range(ny):
            face("SD", [name(nx, j, k), name(nx, j + 1, k), name(nx, j + 1, k + 1), name(nx, j, k + 1)])
            face("SG", [name(0, j, k), name(0, j, k + 1), name(0, j + 1, k + 1), name(0, j + 1, k)])
    for j in range(ny):
        for i in range(nx):
            face("FACE", [name(i, j, 0), name(i, j + 1, 0), name(i + 1, j + 1, 0), name(i + 1, j, 0)])
            face("DOS", [name(i, j, nz), name(i + 1, j, nz), name(i + 1, j + 1, nz), name(i, j + 1, nz)])
    m.node_groups["PIN"] = [name(nx, 0, 0)]
    return m



def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("kind", choices=["quad4", "tria3", "hexa8", "tetra4"])
    parser.add_argument("divisions", type=int, nargs="+", help="NX NY (NZ)")
    parser.add_argument("output")
    parser.add_argument("--size", type=float, nargs="+", help="LX LY (LZ)")
    parser.add_argument("--title", default="")
    args = parser.parse_args()
    dim = 2 if args.kind in ("quad4", "tria3") else 3
    if len(args.divisions) != dim:
        parser.error("%s needs %d divisions" % (args.kind, dim))
    size = args.size or [2., 4., 1.][:dim]
    title = args.title or "%s box %s, [0,%s]" % (args.kind.upper(), " x ".join(map(str, args.divisions)),
                                                   "] x [0,".join("%g" % s for s in size))
    if dim == 2:
        text = plane_box(args.kind.upper(), *args.divisions, *size, title)
    else:
        text = volume_box(args.kind.upper(), *args.divisions, *size, title)
    with open(args.output, "w") as out:
        out.write(text)


if __name__ == "__main__":
    main()
