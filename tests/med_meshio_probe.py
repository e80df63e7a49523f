#!/usr/bin/python3
"""Independent MED reader/writer for the med_* unit tests (meshio + h5py, no libmedC).

  med_meshio_probe.py dump FILE          mesh as text: nodes, cells (MED node order, 0-based,
                                         numbered by increasing MED type code), groups
  med_meshio_probe.py field FILE NAME    values of the nodal field NAME (meshio point_data)
  med_meshio_probe.py rawconn FILE TYP    connectivity of MED cell type TYP (HE8, H20, ...) read
                                         with h5py from the first mesh, one cell per line, 1-based
  med_meshio_probe.py write-mixed FILE   writes a small mesh of quadratic and linear cells with
                                         multi-group families (another MED writer than ours)
"""
import sys

import meshio
import numpy as np

MED_CODE = {"PO1": 1, "SE2": 102, "SE3": 103, "TR3": 203, "QU4": 204, "TR6": 206, "QU8": 208,
            "TE4": 304, "PY5": 305, "PE6": 306, "HE8": 308, "T10": 310, "P13": 313, "P15": 315,
            "H20": 320}
MESHIO_TO_MED = {"vertex": "PO1", "line": "SE2", "line3": "SE3", "triangle": "TR3",
                 "triangle6": "TR6", "quad": "QU4", "quad8": "QU8", "tetra": "TE4",
                 "tetra10": "T10", "hexahedron": "HE8", "hexahedron20": "H20", "pyramid": "PY5",
                 "pyramid13": "P13", "wedge": "PE6", "wedge15": "P15"}


def groups_of(tags):
    out = {}
    for num, names in (tags or {}).items():
        out[int(num)] = [n if isinstance(n, str) else n.decode() for n in names]
    return out


def dump(path):
    m = meshio.read(path, file_format="med")
    for i, p in enumerate(m.points):
        xyz = list(p) + [0.0] * (3 - len(p))
        print("node", i, " ".join(repr(float(v)) for v in xyz))
    blocks = []
    for k, block in enumerate(m.cells):
        code = MED_CODE[MESHIO_TO_MED[block.type]]
        tags = m.cell_data["cell_tags"][k] if "cell_tags" in m.cell_data else [0] * len(block.data)
        blocks.append((code, block.data, tags))
    blocks.sort(key=lambda b: b[0])
    cell_groups, node_groups = {}, {}
    cell_fam, node_fam = groups_of(m.cell_tags), groups_of(m.point_tags)
    index = 0
    for code, data, tags in blocks:
        for row, tag in zip(data, tags):
            print("cell", index, code, " ".join(str(int(v)) for v in row))
            for g in cell_fam.get(int(tag), []):
                cell_groups.setdefault(g, []).append(index)
            index += 1
    if "point_tags" in m.point_data:
        for i, tag in enumerate(m.point_data["point_tags"]):
            for g in node_fam.get(int(tag), []):
                node_groups.setdefault(g, []).append(i)
    for g, members in cell_groups.items():
        print("cellgroup", g, " ".join(map(str, members)))
    for g, members in node_groups.items():
        print("nodegroup", g, " ".join(map(str, members)))


def field(path, name):
    m = meshio.read(path, file_format="med")
    values = np.asarray(m.point_data[name])
    if values.ndim == 1:
        values = values[:, None]
    print("shape", values.shape[0], values.shape[1])
    for row in values:
        print(" ".join(repr(float(v)) for v in row))


def rawconn(path, typ):
    import h5py
    f = h5py.File(path, "r")
    mesh = f["ENS_MAA"][list(f["ENS_MAA"].keys())[0]]
    step = mesh[list(mesh.keys())[0]]
    nod = np.asarray(step["MAI"][typ]["NOD"])
    n = int(step["MAI"][typ]["NOD"].attrs["NBR"])
    rows = nod.reshape(-1, n).T  # stored no-interlace: all first nodes, then all second nodes...
    for row in rows:
        print(" ".join(str(int(v)) for v in row))


def write_mixed(path):
    # Two unit cubes side by side in x (HEXA20 + HEXA8 would need a conforming face: keep the
    # HEXA20 alone), a QUAD8 and a TRIA6 on its bottom face z=0, SEG3 edges. Node numbering
    # (0-based) follows the MED reference orders.
    pts = []

    def node(x, y, z):
        pts.append((x, y, z))
        return len(pts) - 1

    # HEXA20 in MED order: vertices (first face z=0 seen from outside: 1-2-3-4 clockwise from +z)
    v = [node(0, 0, 0), node(0, 1, 0), node(1, 1, 0), node(1, 0, 0),
         node(0, 0, 1), node(0, 1, 1), node(1, 1, 1), node(1, 0, 1)]
    def mid(a, b):
        return node(*[(pts[a][i] + pts[b][i]) / 2 for i in range(3)])
    edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4),
             (0, 4), (1, 5), (2, 6), (3, 7)]
    mids = {e: mid(v[e[0]], v[e[1]]) for e in edges}
    hexa20 = v + [mids[e] for e in edges]
    # QUAD8 on z=0: vertices v0 v3 v2 v1 (counter-clockwise from +z), mid-edges in edge order
    quad_v = [v[0], v[3], v[2], v[1]]
    emap = {}
    for (a, b), m in mids.items():
        emap[(v[a], v[b])] = m
        emap[(v[b], v[a])] = m
    quad8 = quad_v + [emap[(quad_v[i], quad_v[(i + 1) % 4])] for i in range(4)]
    # TRIA6 in the plane z=0 next to the cube: x in [1,2]
    t = [v[3], node(2, 0, 0), v[2]]
    tria6 = t + [mid(t[0], t[1]), mid(t[1], t[2]), emap[(t[2], t[0])]]
    # SEG3 along y=0, z=0 (two of them: the cube edge and the triangle edge)
    seg3 = [[v[0], v[3], emap[(v[0], v[3])]], [t[0], t[1], tria6[3]]]
    cells = [meshio.CellBlock("hexahedron20", np.array([hexa20])),
             meshio.CellBlock("quad8", np.array([quad8])),
             meshio.CellBlock("triangle6", np.array([tria6])),
             meshio.CellBlock("line3", np.array(seg3))]
    # Families: cells -1 {VOLU}, -2 {BAS, FACES}, -3 {FACES, TRI, A_VERY_LONG_GROUP_NAME_OF_30C},
    # -4 {ARETES}; nodes 1 {BAS} (same name as a cell group), 2 {BAS, ORIGINE}.
    cell_tags = [np.array([-1]), np.array([-2]), np.array([-3]), np.array([-4, -4])]
    point_tags = np.zeros(len(pts), dtype=int)
    for i, p in enumerate(pts):
        if abs(p[2]) < 1e-12:
            point_tags[i] = 1
    point_tags[v[0]] = 2
    mesh = meshio.Mesh(np.array(pts, dtype=float), cells,
                       point_data={"point_tags": point_tags},
                       cell_data={"cell_tags": cell_tags})
    mesh.cell_tags = {-1: ["VOLU"], -2: ["BAS", "FACES"],
                      -3: ["FACES", "TRI", "A_VERY_LONG_GROUP_NAME_OF_30C"], -4: ["ARETES"]}
    mesh.point_tags = {1: ["BAS"], 2: ["BAS", "ORIGINE"]}
    meshio.write(path, mesh, file_format="med")


if __name__ == "__main__":
    cmd = sys.argv[1]
    if cmd == "dump":
        dump(sys.argv[2])
    elif cmd == "field":
        field(sys.argv[2], sys.argv[3])
    elif cmd == "rawconn":
        rawconn(sys.argv[2], sys.argv[3])
    elif cmd == "write-mixed":
        write_mixed(sys.argv[2])
    else:
        sys.exit("unknown command " + cmd)
