#!/usr/bin/python3
"""A picture of a result without ParaView (`miniaster plot`, docs/visualisation.md).

    miniaster plot RESULT.rmed [--field NAME] [--component C] [--deformed SCALE] [--step K]
                   [--view AZIMUTH,ELEVATION] [--clip X,Y,Z,NX,NY,NZ] -o OUT.png

The binary converts the MED file to a VTU file (`miniaster convert`) and runs this script on it:
the mesh (2D: every cell; 3D: the skin), deformed by DEPL times SCALE, coloured by a field
component (default: the displacement magnitude), the cell edges thin, the X-FEM cut and the
interfaces (nodes of GROUP_NO NFISSU, cells of the lips) thick, a colour bar and a title.
Nodal fields are interpolated over the cells (the colour bar spans the field's values at the
nodes); fields at Gauss points are drawn flat, one colour per cell (the cell's mean).
In 3D, --view turns the camera and --clip removes the cells whose centre lies on the normal's side
of a plane (as ParaView's Clip with Crinkle), which shows the inside and the interfaces (lips in red).
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
    if args.component and args.component not in comps:
        # `convert` writes the components of DEPL beyond DX, DY, DZ as scalar arrays NAME_<component>.
        base, at, step = name.partition("@")
        own = f"{base}_{args.component}{at}{step}"
        if own in grid.point_data:
            data, comps = decode(grid.point_data[own]).reshape(-1, 1), [args.component]
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


def drawn_cells(grid, xyz, clip):
    """Indices of the cells drawn: those of the top dimension (2 or 3) whose centre (deformed) is not
    on the normal's side of the clip plane."""
    top = max(CELLS.get(t, (0, 0))[0] for t, _ in grid.cells)
    kept = [k for k, (t, _) in enumerate(grid.cells) if CELLS.get(t, (0,))[0] == top and top >= 2]
    if clip is None:
        return kept, top
    origin, normal = np.array(clip[:3]), np.array(clip[3:])
    centre = [np.mean(xyz[grid.cells[k][1][:CELLS[grid.cells[k][0]][1]]], axis=0) for k in kept]
    return [k for k, c in zip(kept, centre) if np.dot(c - origin, normal) <= 0.0], top


def surface_pieces(grid, interface, cells, top):
    """(corner lists, cell index) of what is drawn, and the lips: 2D cells (no lips), or the faces
    of the skin of the 3D cells kept, split into the outer faces and the lips of the interfaces
    (faces whose nodes are all interface nodes)."""
    if top < 3:
        return [(list(grid.cells[k][1][:CELLS[grid.cells[k][0]][1]]), k) for k in cells], []
    count, faces = {}, {}
    for k in cells:
        t, c = grid.cells[k]
        for face in FACES[CELLS[t][1]]:
            nodes = [int(c[i]) for i in face]
            key = tuple(sorted(nodes))
            count[key] = count.get(key, 0) + 1
            faces[key] = (nodes, k)
    skin = [key for key, n in count.items() if n == 1]
    return ([faces[key] for key in skin if not set(key) <= interface],
            [faces[key] for key in skin if set(key) <= interface])


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


def colour_range(values, on_points, grid, cells):
    """The colour bar's range: the field's finite values at the nodes of the cells drawn (nodal
    fields), or over the cells drawn (fields at Gauss points)."""
    if on_points:
        nodes = np.unique(np.concatenate([grid.cells[k][1] for k in cells])) if cells else np.array([], int)
        chosen = values[nodes]
    else:
        chosen = values[cells] if cells else np.array([])
    finite = chosen[np.isfinite(chosen)]
    lo, hi = (float(finite.min()), float(finite.max())) if finite.size else (0.0, 1.0)
    if hi - lo <= 1e-300 + 1e-12 * max(abs(lo), abs(hi)):
        return lo, hi, (lo - 0.5 * max(abs(lo), 1e-30), hi + 0.5 * max(abs(hi), 1e-30))
    return lo, hi, (lo, hi)


def fan(corners):
    return [(corners[0], corners[i], corners[i + 1]) for i in range(1, len(corners) - 1)]


def interpolated_3d(pieces, xyz, values, levels=4):
    """Nodal values over 3D faces: each face fanned into triangles, each triangle split into
    levels^2 small ones coloured by the value interpolated (linearly) at their centres."""
    polygons, colours = [], []
    steps = [(i, j) for i in range(levels) for j in range(levels - i)]
    for corners, _ in pieces:
        for a, b, c in fan(corners):
            pa, pb, pc = xyz[a], xyz[b], xyz[c]
            va, vb, vc = values[a], values[b], values[c]
            for i, j in steps:
                for tri in (((i, j), (i + 1, j), (i, j + 1)), ((i + 1, j), (i + 1, j + 1), (i, j + 1))):
                    if any(u + v > levels for u, v in tri):
                        continue
                    w = [(u / levels, v / levels) for u, v in tri]
                    polygons.append([pa + u * (pb - pa) + v * (pc - pa) for u, v in w])
                    u, v = np.mean(w, axis=0)
                    colours.append(va + u * (vb - va) + v * (vc - va))
    return polygons, np.array(colours)


def draw_2d(ax, xyz, pieces, values, on_points, norm, cmap, mesh_edges, cut_edges):
    """2D: nodal values Gouraud-shaded over the cells' triangles (grey where a node has no value),
    Gauss-point values flat per cell."""
    if on_points:
        triangles = np.array([t for corners, _ in pieces for t in fan(corners)])
        bad = ~np.isfinite(values[triangles]).all(axis=1)
        if (~bad).any():
            ax.tripcolor(xyz[:, 0], xyz[:, 1], triangles[~bad], np.nan_to_num(values), shading="gouraud",
                         cmap=cmap, norm=norm)
        if bad.any():
            ax.add_collection(PolyCollection([xyz[t, :2] for t in triangles[bad]], facecolors="lightgrey",
                                             edgecolors="none"))
    else:
        colours = np.array([values[k] for _, k in pieces])
        ax.add_collection(PolyCollection([xyz[c, :2] for c, _ in pieces],
                                         facecolors=cmap(norm(np.ma.masked_invalid(colours))), edgecolors="none"))
    ax.add_collection(LineCollection([xyz[[a, b], :2] for a, b in mesh_edges], colors="0.25", linewidths=0.3))
    ax.add_collection(LineCollection([xyz[[a, b], :2] for a, b in cut_edges], colors="red", linewidths=2.0))
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.set_xlabel("X")
    ax.set_ylabel("Y")


def draw_3d(ax, xyz, pieces, lips, values, on_points, norm, cmap, cut_edges, view):
    """3D: the skin (nodal values interpolated over sub-triangles, Gauss-point values flat) and the
    lips of the interfaces in red, in one collection so that they are depth-sorted together."""
    if on_points:
        polygons, colours = interpolated_3d(pieces, xyz, values)
    else:
        polygons, colours = [xyz[c] for c, _ in pieces], np.array([values[k] for _, k in pieces])
    faces = cmap(norm(np.ma.masked_invalid(colours))) if len(colours) else np.zeros((0, 4))
    lip_colour = np.array([[0.85, 0.1, 0.1, 1.0]] * len(lips))
    ax.add_collection3d(Poly3DCollection(polygons + [xyz[c] for c, _ in lips],
                                         facecolors=np.concatenate([faces, lip_colour]) if len(lips) else faces,
                                         edgecolors="none"))
    edges = sorted(edge_counts(pieces))
    ax.add_collection3d(Line3DCollection([xyz[[a, b]] for a, b in edges], colors="0.25", linewidths=0.2))
    ax.add_collection3d(Line3DCollection([xyz[[a, b]] for a, b in cut_edges], colors="red", linewidths=2.0))
    span = xyz.max(axis=0) - xyz.min(axis=0)
    centre = (xyz.max(axis=0) + xyz.min(axis=0)) / 2
    half = span.max() / 2 or 1.0
    for set_lim, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        set_lim(c - half, c + half)
    ax.view_init(elev=view[1], azim=view[0])
    ax.set_xlabel("X")
    ax.set_ylabel("Y")
    ax.set_zlabel("Z")


def draw(grid, args):
    values, on_points, label = colour_values(grid, args)
    xyz = displaced(grid, args)
    interface = interface_nodes(grid)
    cells, top = drawn_cells(grid, xyz, args.clip)
    pieces, lips = surface_pieces(grid, interface, cells, top)
    if not pieces:
        sys.exit(f"miniaster plot: {args.source} has no 2D cells or volumes to draw"
                 + (" on this side of the --clip plane" if args.clip and top >= 2 else ""))
    lo, hi, bar_range = colour_range(values, on_points, grid, cells)
    norm = matplotlib.colors.Normalize(*bar_range)
    cmap = plt.get_cmap("viridis").copy()
    cmap.set_bad("lightgrey")
    counts = edge_counts(pieces + lips)
    cut_edges = interface_edges(grid, counts, interface)
    fig = plt.figure(figsize=(8, 6.5), dpi=args.dpi)
    if grid.dim == 2:
        ax = fig.add_subplot(111)
        draw_2d(ax, xyz, pieces, values, on_points, norm, cmap, sorted(edge_counts(pieces)), cut_edges)
    else:
        ax = fig.add_subplot(111, projection="3d")
        draw_3d(ax, xyz, pieces, lips, values, on_points, norm, cmap, cut_edges, args.view)
    bar = fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, shrink=0.8)
    bar.set_label(label + ("" if on_points else " (cell means)"))
    deformed = f", deformed x {args.deformed:g}" if args.deformed else ""
    clipped = ", clipped" if args.clip else ""
    interfaces = ", interfaces in red (GROUP_NO NFISSU)" if cut_edges or lips else ""
    ax.set_title(args.title or f"{os.path.basename(args.source)}: {label}{deformed}{clipped}{interfaces}", fontsize=9)
    fig.tight_layout()
    fig.savefig(args.output)
    plt.close(fig)
    print(f"miniaster plot: {args.output} ({label}, {'nodal values' if on_points else 'cell means'}, "
          f"min {lo:.17g}, max {hi:.17g}{deformed}{clipped})")


def numbers(count, name):
    def parse(text):
        try:
            values = [float(v) for v in text.split(",")]
        except ValueError:
            raise argparse.ArgumentTypeError(f"{name} expects {count} comma-separated numbers, got '{text}'")
        if len(values) != count or not all(math.isfinite(v) for v in values):
            raise argparse.ArgumentTypeError(f"{name} expects {count} comma-separated finite numbers, got '{text}'")
        return values
    return parse


class Arguments(argparse.ArgumentParser):
    def error(self, message):
        """A usage error exits with 1, as every other error of miniaster does (argparse: 2)."""
        self.print_usage(sys.stderr)
        self.exit(1, f"{self.prog}: error: {message}\n")


def main():
    # The binary's temporary folder goes whatever happens, a usage error included.
    cleanup = argparse.ArgumentParser(add_help=False)
    cleanup.add_argument("--remove-folder", default=None)
    folder = cleanup.parse_known_args()[0].remove_folder
    try:
        return run(sys.argv[1:])
    finally:
        if folder:
            shutil.rmtree(folder, ignore_errors=True)


def run(argv):
    ap = Arguments(prog="miniaster plot", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("vtu", metavar="RESULT.rmed")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--field", default=None, help="field (MED name or NOM_CHAM suffix); default the DEPL field")
    ap.add_argument("--component", default=None, help="default: the magnitude of DX, DY, DZ")
    ap.add_argument("--deformed", type=float, default=0.0, help="displacement scale (default: undeformed)")
    ap.add_argument("--deform-field", default="DEPL", help="the nodal field that moves the mesh (default DEPL)")
    ap.add_argument("--step", type=int, default=None, help="NUME_ORDRE (default: the last one)")
    ap.add_argument("--view", type=numbers(2, "--view"), default=[-55.0, 25.0], metavar="AZIMUTH,ELEVATION",
                    help="3D: the camera's azimuth and elevation in degrees (default -55,25)")
    ap.add_argument("--clip", type=numbers(6, "--clip"), default=None, metavar="X,Y,Z,NX,NY,NZ",
                    help="remove the cells whose centre lies on the side of the plane through (X,Y,Z) that the "
                         "normal (NX,NY,NZ) points to (3D: shows the inside and the interfaces)")
    ap.add_argument("--title", default=None)
    ap.add_argument("--dpi", type=int, default=100)
    ap.add_argument("--source", default=None, help=argparse.SUPPRESS)
    ap.add_argument("--remove-folder", default=None, help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    args.source = args.source or args.vtu
    if not math.isfinite(args.deformed):
        sys.exit("miniaster plot: --deformed must be a finite number")
    draw(Grid(args.vtu), args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
