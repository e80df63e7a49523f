#!/usr/bin/python3
"""A picture of a result without ParaView (`miniaster plot`, docs/visualisation.md).

    miniaster plot RESULT.rmed [--field NAME] [--component C] [--deformed SCALE] [--step K] -o OUT.png

The binary converts the MED file to a VTU file (`miniaster convert`) and runs this script on it:
the mesh (2D: every cell; 3D: the skin), deformed by DEPL times SCALE, coloured by a field
component (default: the displacement magnitude), the cell edges thin, the X-FEM cut and the
interfaces (nodes of GROUP_NO NFISSU, cells of the lips) thick, a colour bar and a title.
"""
import argparse
import base64
import math
import os
import shutil
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402

DTYPES = {"Float64": np.float64, "Int64": np.int64, "UInt8": np.uint8}
# VTK cell type -> (dimension, corner count): the picture uses the corners only.
CELLS = {1: (0, 1), 3: (1, 2), 21: (1, 2), 35: (1, 2), 5: (2, 3), 22: (2, 3), 34: (2, 3), 9: (2, 4), 23: (2, 4),
         28: (2, 4), 10: (3, 4), 24: (3, 4), 12: (3, 8), 25: (3, 8), 13: (3, 6), 26: (3, 6), 14: (3, 5), 27: (3, 5)}
# Faces of the volumes (VTK corner numbering).
FACES = {4: [(0, 1, 2), (0, 1, 3), (1, 2, 3), (0, 2, 3)],
         8: [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)],
         6: [(0, 1, 2), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5)],
         5: [(0, 1, 2, 3), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)]}
INTERFACE_NODES = "GROUP_NO:NFISSU"


def decode(element):
    """A binary DataArray of miniaster's VTU files: base64 of (UInt64 byte count, values)."""
    raw = base64.b64decode("".join(element.text.split()))
    count = int(np.frombuffer(raw[:8], dtype=np.uint64)[0])
    values = np.frombuffer(raw[8:8 + count], dtype=DTYPES[element.get("type")])
    n = int(element.get("NumberOfComponents", "1"))
    return values.reshape(-1, n) if n > 1 else values


def component_names(element):
    n = int(element.get("NumberOfComponents", "1"))
    return [element.get(f"ComponentName{i}", str(i)) for i in range(n)] if n > 1 else [element.get("Name")]


class Grid:
    def __init__(self, path):
        piece = ET.parse(path).getroot().find("UnstructuredGrid/Piece")
        self.points = decode(piece.find("Points/DataArray"))
        cells = {a.get("Name"): decode(a) for a in piece.find("Cells")}
        offsets, conn = cells["offsets"], cells["connectivity"]
        starts = np.concatenate([[0], offsets[:-1]])
        self.cells = [(int(t), conn[s:e]) for t, s, e in zip(cells["types"], starts, offsets)]
        self.point_data = {a.get("Name"): a for a in piece.find("PointData")}
        self.cell_data = {a.get("Name"): a for a in piece.find("CellData")}
        self.dim = 3 if np.ptp(self.points[:, 2]) > 0 else 2


def pick_step(names, wanted, step):
    """Arrays of a field: NAME, or NAME@k for several steps (the last one unless --step)."""
    def base(n):
        return n.split("@")[0]
    matches = [n for n in names if not n.startswith("GROUP_") and (wanted is None or base(n) == wanted
                                                                   or base(n).endswith(wanted))]
    if wanted is None:
        matches = [n for n in matches if base(n).endswith("DEPL")] or matches
    if not matches:
        return None
    if step is not None:
        matches = [n for n in matches if n.endswith(f"@{step}")] or [n for n in matches if "@" not in n]
        if not matches:
            return None
    first = base(matches[0])
    steps = [n for n in matches if base(n) == first]
    return max(steps, key=lambda n: int(n.split("@")[1]) if "@" in n else 0)


def colour_values(grid, args):
    """(values, on_points, label): the chosen component (or the displacement magnitude)."""
    name = pick_step(list(grid.point_data) + list(grid.cell_data), args.field, args.step)
    if name is None:
        sys.exit(f"miniaster plot: no field {args.field or 'DEPL'} in {args.source} "
                 f"(fields: {', '.join(n for n in list(grid.point_data) + list(grid.cell_data) if not n.startswith('GROUP_'))})")
    on_points = name in grid.point_data
    element = (grid.point_data if on_points else grid.cell_data)[name]
    data, comps = decode(element), component_names(element)
    if data.ndim == 1:
        data = data.reshape(-1, 1)
    if args.component:
        if args.component not in comps:
            sys.exit(f"miniaster plot: field {name} has no component {args.component} (components: {', '.join(comps)})")
        return data[:, comps.index(args.component)], on_points, f"{name} {args.component}"
    xyz = [comps.index(c) for c in ("DX", "DY", "DZ") if c in comps]
    if xyz:
        return np.sqrt((data[:, xyz] ** 2).sum(axis=1)), on_points, f"{name} |({', '.join(comps[i] for i in xyz)})|"
    return data[:, 0], on_points, f"{name} {comps[0]}"


def displaced(grid, args):
    if not args.deformed:
        return grid.points
    name = pick_step(list(grid.point_data), args.deform_field, args.step)
    if name is None:
        sys.exit(f"miniaster plot: --deformed needs a nodal displacement field ({args.deform_field})")
    element = grid.point_data[name]
    data, comps = decode(element), component_names(element)
    u = np.zeros_like(grid.points)
    for axis, c in enumerate(("DX", "DY", "DZ")):
        if c in comps:
            u[:, axis] = np.nan_to_num(data[:, comps.index(c)])
    return grid.points + args.deformed * u


def interface_nodes(grid):
    element = grid.point_data.get(INTERFACE_NODES)
    return set(np.nonzero(decode(element))[0]) if element is not None else set()


def surface_pieces(grid, interface):
    """(corner lists, cell index) of what is drawn: 2D cells, or the faces of the 3D skin without
    the lips of the interfaces (their nodes are all interface nodes)."""
    top = max(CELLS.get(t, (0, 0))[0] for t, _ in grid.cells)
    if top < 3:
        return [(list(c[:CELLS[t][1]]), k) for k, (t, c) in enumerate(grid.cells) if CELLS.get(t, (0,))[0] == 2]
    count, faces = {}, {}
    for k, (t, c) in enumerate(grid.cells):
        dim, n = CELLS.get(t, (0, 0))
        if dim != 3:
            continue
        for face in FACES[n]:
            nodes = [int(c[i]) for i in face]
            key = tuple(sorted(nodes))
            count[key] = count.get(key, 0) + 1
            faces[key] = (nodes, k)
    return [faces[key] for key, n in count.items() if n == 1 and not set(key) <= interface]


def edge_counts(pieces):
    counts = {}
    for corners, _ in pieces:
        for a, b in zip(corners, corners[1:] + corners[:1]):
            key = (min(a, b), max(a, b))
            counts[key] = counts.get(key, 0) + 1
    return counts


def interface_edges(grid, counts, interface):
    """2D: the border edges of the pieces between interface nodes (the lips; an edge inside a
    block is shared by two pieces). 3D: the skin's edges between interface nodes (the traces)."""
    return sorted(e for e, n in counts.items() if e[0] in interface and e[1] in interface
                  and (grid.dim == 3 or n == 1))


def piece_values(pieces, values, on_points):
    if on_points:
        return np.array([np.mean(values[corners]) for corners, _ in pieces])
    return np.array([values[k] for _, k in pieces])


def draw(grid, args):
    values, on_points, label = colour_values(grid, args)
    xyz = displaced(grid, args)
    interface = interface_nodes(grid)
    pieces = surface_pieces(grid, interface)
    if not pieces:
        sys.exit(f"miniaster plot: {args.source} has no 2D cells or volumes to draw")
    colours = piece_values(pieces, values, on_points)
    finite = colours[np.isfinite(colours)]
    lo, hi = (float(finite.min()), float(finite.max())) if finite.size else (0.0, 1.0)
    if hi - lo <= 1e-300 + 1e-12 * max(abs(lo), abs(hi)):
        lo, hi = lo - 0.5 * max(abs(lo), 1e-30), hi + 0.5 * max(abs(hi), 1e-30)
    norm = matplotlib.colors.Normalize(lo, hi)
    cmap = plt.get_cmap("viridis").copy()
    cmap.set_bad("lightgrey")
    face_colours = cmap(norm(np.ma.masked_invalid(colours)))
    counts = edge_counts(pieces)
    mesh_edges, cut_edges = sorted(counts), interface_edges(grid, counts, interface)
    fig = plt.figure(figsize=(8, 6.5), dpi=args.dpi)
    if grid.dim == 2:
        ax = fig.add_subplot(111)
        ax.add_collection(PolyCollection([xyz[c, :2] for c, _ in pieces], facecolors=face_colours, edgecolors="none"))
        ax.add_collection(LineCollection([xyz[[a, b], :2] for a, b in mesh_edges], colors="0.25", linewidths=0.3))
        ax.add_collection(LineCollection([xyz[[a, b], :2] for a, b in cut_edges], colors="red", linewidths=2.0))
        ax.autoscale_view()
        ax.set_aspect("equal")
        ax.set_xlabel("X")
        ax.set_ylabel("Y")
    else:
        ax = fig.add_subplot(111, projection="3d")
        ax.add_collection3d(Poly3DCollection([xyz[c] for c, _ in pieces], facecolors=face_colours,
                                             edgecolors="0.25", linewidths=0.2))
        ax.add_collection3d(Line3DCollection([xyz[[a, b]] for a, b in cut_edges], colors="red", linewidths=2.0))
        span = xyz.max(axis=0) - xyz.min(axis=0)
        centre = (xyz.max(axis=0) + xyz.min(axis=0)) / 2
        half = span.max() / 2 or 1.0
        for set_lim, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
            set_lim(c - half, c + half)
        ax.view_init(elev=25, azim=-55)
        ax.set_xlabel("X")
        ax.set_ylabel("Y")
        ax.set_zlabel("Z")
    bar = fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, shrink=0.8)
    bar.set_label(label)
    deformed = f", deformed x {args.deformed:g}" if args.deformed else ""
    interfaces = ", interfaces in red (GROUP_NO NFISSU)" if cut_edges else ""
    ax.set_title(args.title or f"{os.path.basename(args.source)}: {label}{deformed}{interfaces}", fontsize=9)
    fig.tight_layout()
    fig.savefig(args.output)
    plt.close(fig)
    print(f"miniaster plot: {args.output} ({label}, min {lo:.6g}, max {hi:.6g}{deformed})")


def main():
    ap = argparse.ArgumentParser(prog="miniaster plot", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("vtu")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--field", default=None, help="field (MED name or NOM_CHAM suffix); default the DEPL field")
    ap.add_argument("--component", default=None, help="default: the magnitude of DX, DY, DZ")
    ap.add_argument("--deformed", type=float, default=0.0, help="displacement scale (default: undeformed)")
    ap.add_argument("--deform-field", default="DEPL", help="the nodal field that moves the mesh (default DEPL)")
    ap.add_argument("--step", type=int, default=None, help="NUME_ORDRE (default: the last one)")
    ap.add_argument("--title", default=None)
    ap.add_argument("--dpi", type=int, default=100)
    ap.add_argument("--source", default=None, help=argparse.SUPPRESS)
    ap.add_argument("--remove-folder", default=None, help=argparse.SUPPRESS)
    args = ap.parse_args()
    args.source = args.source or args.vtu
    try:
        if not math.isfinite(args.deformed):
            sys.exit("miniaster plot: --deformed must be a finite number")
        draw(Grid(args.vtu), args)
    finally:
        if args.remove_folder:
            shutil.rmtree(args.remove_folder, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
