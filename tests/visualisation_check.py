#!/usr/bin/python3
"""Independent readers for the visualisation tests (tests/cli/visualisation_outputs.cpp).

  visualisation_check.py vtu OUT.vtu RESULT.med FIELD...   VTK's reader (python3-vtk9's or ParaView's
                                                           python3-paraview's `vtk`) against h5py's
                                                           MED values: every nodal field of the MED
                                                           file, every step, every component (DEPL:
                                                           the vector DX DY DZ, the others NAME_<c>);
                                                           FIELD... must be among the component names
  visualisation_check.py png OUT.png WIDTH HEIGHT           size and a non-blank picture (and its share
                                                           of red pixels: the interfaces)
  visualisation_check.py range RESULT.med FIELD COMPONENT   min and max of a nodal field's component (MAG:
                                                           |(DX, DY, DZ)|) at its last step, over the
                                                           nodes that carry it (h5py)
  visualisation_check.py meshio RESULT.med                  what meshio reads of the file
Prints one summary line and exits 1 on any difference.
"""
import sys

import numpy as np


def med_nodal_fields(path):
    """{array name as `miniaster convert` names it: (components, values[nodes, components])}."""
    import h5py
    out = {}
    with h5py.File(path, "r") as f:
        profiles = f.get("PROFILS")
        for name, field in f["CHA"].items():
            comps = field.attrs["NOM"].decode()
            comps = [comps[i:i + 16].strip() for i in range(0, len(comps), 16)]
            mesh = f["ENS_MAA"][field.attrs["MAI"].decode()]
            nnodes = mesh[sorted(mesh.keys())[0]]["NOE"]["COO"].attrs["NBR"]
            steps = sorted(field.keys())
            for key in steps:
                step = field[key]
                if "NOE" not in step:
                    continue
                label = name if len(steps) == 1 else f"{name}@{step.attrs['NDT']}"
                values = np.full((nnodes, len(comps)), np.nan)
                for pname, block in step["NOE"].items():
                    n = block.attrs["NBR"]
                    data = block["CO"][()].reshape(len(comps), n).T  # MED stores component by component
                    rows = np.arange(n) if pname == "MED_NO_PROFILE_INTERNAL" else profiles[pname]["PFL"][()] - 1
                    values[rows] = data
                out[label] = (comps, values)
    return out


def check_vtu(vtu, med, wanted):
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(vtu)
    reader.Update()
    grid = reader.GetOutput()
    if reader.GetErrorCode() or grid.GetNumberOfPoints() == 0:
        sys.exit(f"vtu: VTK could not read {vtu}")
    expected = med_nodal_fields(med)
    point_data = grid.GetPointData()
    compared, seen = 0, set()

    def compare(name, got, want, comps):
        same = (got == want) | (np.isnan(got) & np.isnan(want))
        if not same.all():
            bad = np.argwhere(~same)[0]
            sys.exit(f"vtu: {name}: node {bad[0]} {comps[bad[1]]}: VTK {got[tuple(bad)]!r}, MED {want[tuple(bad)]!r}")
        return want.size

    def array(name, components):
        a = point_data.GetArray(name)
        if a is None:
            sys.exit(f"vtu: no point array {name} in {vtu}")
        names = [a.GetComponentName(i) for i in range(a.GetNumberOfComponents())] if len(components) > 1 else []
        if len(components) > 1 and names != components:
            sys.exit(f"vtu: {name}: components {names}, expected {components}")
        return vtk_to_numpy(a).reshape(grid.GetNumberOfPoints(), -1)

    for name, (comps, values) in expected.items():
        seen.update(comps)
        if "DX" not in comps or "DY" not in comps:
            compared += compare(name, array(name, comps), values, comps)
            continue
        # A displacement: the vector (DX, DY, DZ; DZ = 0 where DX is known in 2D), the rest one array each.
        dz = values[:, comps.index("DZ")] if "DZ" in comps else np.where(np.isnan(values[:, comps.index("DX")]),
                                                                         np.nan, 0.0)
        vector = np.column_stack([values[:, comps.index("DX")], values[:, comps.index("DY")], dz])
        compared += compare(name, array(name, ["DX", "DY", "DZ"]), vector, ["DX", "DY", "DZ"])
        base, at, step = name.partition("@")
        for i, c in enumerate(comps):
            if c not in ("DX", "DY", "DZ"):
                own = f"{base}_{c}{at}{step}"
                compared += compare(own, array(own, [c]), values[:, i:i + 1], [c])
    if point_data.GetVectors() is None:
        sys.exit(f"vtu: {vtu} names no active vectors (Warp By Vector would have none)")
    missing = [w for w in wanted if w not in seen]
    if missing:
        sys.exit(f"vtu: components {missing} not found (found {sorted(seen)})")
    types = sorted({grid.GetCellType(i) for i in range(grid.GetNumberOfCells())})
    print(f"vtu: OK {len(expected)} nodal fields, {compared} values equal to the MED file's; "
          f"active vectors {point_data.GetVectors().GetName()}; "
          f"{grid.GetNumberOfPoints()} points, {grid.GetNumberOfCells()} cells, VTK types {types}; "
          f"cell arrays {[grid.GetCellData().GetArrayName(i) for i in range(grid.GetCellData().GetNumberOfArrays())]}")


def check_png(path, width, height):
    import matplotlib.image
    image = matplotlib.image.imread(path)
    h, w = image.shape[:2]
    if (w, h) != (width, height):
        sys.exit(f"png: {path} is {w}x{h}, expected {width}x{height}")
    rgb = (image[:, :, :3] * 255).astype(int)
    colours = len(np.unique(rgb.reshape(-1, 3), axis=0))
    coloured = float((rgb.sum(axis=2) < 3 * 250).mean())
    if colours < 50 or coloured < 0.1:
        sys.exit(f"png: {path} looks blank: {colours} colours, {coloured:.1%} non-white pixels")
    red = float(((rgb[:, :, 0] > 180) & (rgb[:, :, 1] < 80) & (rgb[:, :, 2] < 80)).mean())
    print(f"png: OK {w}x{h}, {colours} colours, {coloured:.0%} non-white pixels, red {red:.4f}")


def print_range(med, field, component):
    fields = med_nodal_fields(med)
    names = [n for n in fields if n.split("@")[0] == field]
    if not names:
        sys.exit(f"range: no nodal field {field} in {med} ({sorted(fields)})")
    last = max(names, key=lambda n: int(n.split("@")[1]) if "@" in n else 0)
    comps, values = fields[last]
    if component == "MAG":
        picked = [comps.index(c) for c in ("DX", "DY", "DZ") if c in comps]
        data = np.sqrt((values[:, picked] ** 2).sum(axis=1))
    else:
        data = values[:, comps.index(component)]
    data = data[np.isfinite(data)]
    print("range %.17g %.17g" % (data.min(), data.max()))


def check_meshio(path):
    """meshio reads the file (MED, or the VTU of `miniaster convert`); for a MED file its nodal
    values are compared with h5py's, step by step (meshio names step i of F `F[i] - t`)."""
    import meshio
    is_med = not path.endswith(".vtu")
    mesh = meshio.read(path, file_format="med") if is_med else meshio.read(path)
    fields = sorted(k for k in list(mesh.point_data) + list(mesh.cell_data) if not k.endswith("_tags"))
    compared = 0
    if is_med:
        expected = list(med_nodal_fields(path).values())
        got = [mesh.point_data[k] for k in mesh.point_data if k != "point_tags"]
        if len(got) != len(expected):
            sys.exit(f"meshio: {len(got)} nodal arrays, the MED file has {len(expected)}")
        for (comps, values), array in zip(expected, got):
            if not np.array_equal(array.reshape(values.shape), values, equal_nan=True):
                sys.exit(f"meshio: values differ from the MED file's ({comps})")
            compared += values.size
    print(f"meshio: OK {len(mesh.points)} points, {sum(len(c.data) for c in mesh.cells)} cells, "
          f"{compared} nodal values equal to h5py's, fields {fields}")


def main():
    kind = sys.argv[1]
    if kind == "vtu":
        check_vtu(sys.argv[2], sys.argv[3], sys.argv[4:])
    elif kind == "png":
        check_png(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]))
    elif kind == "range":
        print_range(sys.argv[2], sys.argv[3], sys.argv[4])
    elif kind == "meshio":
        check_meshio(sys.argv[2])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
