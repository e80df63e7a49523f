#!/usr/bin/python3
"""GetFEM 5.4 peer of the refined ssnv511c scene (3D side by side, tools/bench3d/sidebyside3d.sh).

Box [-5,5] x [-5,5] x [0,DEPTH] (ssnv511c: DEPTH = 1) meshed with N x N x LAYERS hexahedra
(GetFEM QK(3,1), LAYERS = N by default), linear isotropic elasticity E = 100e6, nu = 0.3.
Two plane interfaces through the whole box, y = 0 and x = 0, cut it into four blocks. The faces
x = -5 and x = +5 are moved rigidly with ux = -0.25 / -0.5 (x < 0, y > 0 / y < 0) and
0.75 / 1.0 (x > 0, y > 0 / y < 0), uy = uz = 0: the exact field is that rigid translation of
each block.

Discretisation as GetFEM does X-FEM: two level sets on a MeshLevelSet, the displacement space
MeshFem('levelset') on the QK(3,1) space (every basis function whose support is cut is replaced
by one copy per zone its support meets: 2 copies next to one interface, 4 next to the junction
line), cut integration MeshIm('levelset', 'all') (sub-tetrahedra of the cut cells from GetFEM's
own Delaunay cutting). The Dirichlet data, discontinuous across y = 0, is imposed weakly with
Lagrange multipliers in the enriched trace space (the same level-set enrichment, filtered on the
two faces), so that the piecewise-constant data lies in the multiplier space and is met exactly.
Solved with GetFEM's direct solver MUMPS (gf.linsolve_mumps), or SuperLU with --solver superlu.

Grid lines: the interior ones are moved by OFFSET cell sizes (--offset, as
`ssnv511_mesh --offset`): odd N with offset 0 has no node on an interface; even N needs a
non-zero offset (sidebyside3d.sh passes 0.5) else x = 0 and y = 0 are grid planes.

usage:  /usr/bin/python3 ssnv511c_getfem.py --n N [--offset O] [--depth D] [--layers K]
                                            [--solver mumps|superlu]
Prints one JSON line: dofs, times per phase, peak RSS, relative L2 error against the exact
field, max error of the displacement at the nodes and on both sides of every cut cell.
"""
import argparse
import json
import resource
import sys
import time

import numpy as np
import getfem as gf

YOUNG = 100.0e6
POISSON = 0.3
HALF_WIDTH = 5.0
# rigid x-translation of the blocks: (x < 0, y > 0), (x < 0, y < 0), (x > 0, y > 0), (x > 0, y < 0)
UX_BLOCK = {(-1, 1): -0.25, (-1, -1): -0.5, (1, 1): 0.75, (1, -1): 1.0}
FACE_XMIN, FACE_XMAX, FACES_X = 1, 2, 3


def peak_rss_mb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def mapped_blas():
    """The BLAS the process mapped (reference / openblas), read from /proc/self/maps."""
    try:
        with open("/proc/self/maps") as maps:
            libs = {line.split()[-1] for line in maps if "blas" in line}
    except OSError:
        return "unknown"
    if any("openblas" in lib for lib in libs):
        return "openblas"
    if any("libblas.so" in lib for lib in libs):
        return "reference"
    return ",".join(sorted(libs)) or "unknown"


def grid_line(lo, hi, n, offset):
    """n cells on [lo, hi], the interior lines moved by offset cell sizes (ssnv511_mesh's rule)."""
    h = (hi - lo) / n
    x = lo + (np.arange(n + 1) + offset) * h
    x[0], x[-1] = lo, hi
    return x


def exact_ux(x, y):
    """numpy: ux of the block containing each point (uy = uz = 0)."""
    right = x > 0.0
    top = y > 0.0
    return np.where(right, np.where(top, 0.75, 1.0), np.where(top, -0.25, -0.5))


def exact_u_gwfl():
    """The exact field in GetFEM's weak form language (Heaviside of the two level sets)."""
    hx, hy = "Heaviside(X(1))", "Heaviside(X(2))"
    terms = []
    for (sx, sy), val in UX_BLOCK.items():
        fx = hx if sx > 0 else "(1-%s)" % hx
        fy = hy if sy > 0 else "(1-%s)" % hy
        terms.append("%r*%s*%s" % (val, fx, fy))
    return "[%s, 0, 0]" % " + ".join(terms)


class Phases:
    """Wall time of consecutive phases."""

    def __init__(self):
        self.start = self.last = time.perf_counter()
        self.times = {}

    def done(self, name):
        now = time.perf_counter()
        self.times[name] = self.times.get(name, 0.0) + now - self.last
        self.last = now

    def total(self):
        return self.last - self.start


def build_mesh(args):
    xs = grid_line(-HALF_WIDTH, HALF_WIDTH, args.n, args.offset)
    zs = np.linspace(0.0, args.depth, args.layers + 1)
    mesh = gf.Mesh("cartesian", xs, xs, zs)
    mesh.set_region(FACE_XMIN, mesh.outer_faces_with_direction([-1.0, 0.0, 0.0], 0.01))
    mesh.set_region(FACE_XMAX, mesh.outer_faces_with_direction([1.0, 0.0, 0.0], 0.01))
    mesh.region_merge(FACES_X, FACE_XMIN)
    mesh.region_merge(FACES_X, FACE_XMAX)
    return mesh, xs, zs


def build_model(mesh, args, keep):
    """Level sets, enriched spaces, cut integration, the model; keep holds the objects the model
    refers to (GetFEM's Python handles must outlive it)."""
    lame_mu = YOUNG / (2 * (1 + POISSON))
    lame_lambda = YOUNG * POISSON / ((1 + POISSON) * (1 - 2 * POISSON))
    phases = args.phases
    ls_y = gf.LevelSet(mesh, 1, "y")
    ls_x = gf.LevelSet(mesh, 1, "x")
    mls = gf.MeshLevelSet(mesh)
    mls.add(ls_y)
    mls.add(ls_x)
    mls.adapt()
    phases.done("levelset_cut")

    mf_q1 = gf.MeshFem(mesh, 1)
    mf_q1.set_fem(gf.Fem("FEM_QK(3,1)"))
    mfu = gf.MeshFem("levelset", mls, mf_q1)
    mfu.set_qdim(3)
    mfu.nbdof()  # builds the enriched dof table
    phases.done("mesh_fem_levelset")

    mim = gf.MeshIm("levelset", mls, "all", gf.Integ("IM_TETRAHEDRON(%d)" % args.cut_order))
    mim.set_integ(gf.Integ("IM_GAUSS_PARALLELEPIPED(3,3)"))  # 2x2x2 points in the uncut cells
    mim.adapt()
    phases.done("mesh_im_levelset")

    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_initialized_data("lambda", [lame_lambda])
    md.add_initialized_data("mu", [lame_mu])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda", "mu")
    # u = data on x = -5 and x = +5, weakly, multipliers in the enriched trace space
    mf_mult = gf.MeshFem("levelset", mls, mf_q1)
    mf_mult.set_qdim(3)
    md.add_filtered_fem_variable("traction", mf_mult, FACES_X)
    md.add_linear_term(mim, "traction.Test_u + Test_traction.u", FACES_X)
    md.add_source_term(mim, "(%s).Test_traction" % exact_u_gwfl(), FACES_X)
    phases.done("model")
    keep += [ls_y, ls_x, mls, mf_q1, mf_mult]
    return md, mfu, mim


def probe_points(mesh, xs, zs):
    """Points where the computed field is compared with the exact one: every mesh node, and the
    eight corners of every (cut cell) x (block) box, pulled 1e-6 of the box toward its centre so
    that each side of the interfaces is probed."""
    nodes = mesh.pts()
    cut = int(np.searchsorted(xs, 0.0)) - 1  # the cell row / column with the interface inside
    n, layers = len(xs) - 1, len(zs) - 1
    cells = sorted({(i, cut) for i in range(n)} | {(cut, j) for j in range(n)})
    boxes = []
    for i, j in cells:
        cx = [xs[i], 0.0, xs[i + 1]] if i == cut else [xs[i], xs[i + 1]]
        cy = [xs[j], 0.0, xs[j + 1]] if j == cut else [xs[j], xs[j + 1]]
        for a in range(len(cx) - 1):
            for b in range(len(cy) - 1):
                for k in range(layers):
                    boxes.append((cx[a], cx[a + 1], cy[b], cy[b + 1], zs[k], zs[k + 1]))
    boxes = np.array(boxes).reshape(-1, 6)
    corners = []
    for ix in (0, 1):
        for iy in (2, 3):
            for iz in (4, 5):
                corners.append(np.stack([boxes[:, ix], boxes[:, iy], boxes[:, iz]]))
    corners = np.hstack(corners)
    centres = np.vstack([np.tile(0.5 * (boxes[:, 0] + boxes[:, 1]), 8),
                         np.tile(0.5 * (boxes[:, 2] + boxes[:, 3]), 8),
                         np.tile(0.5 * (boxes[:, 4] + boxes[:, 5]), 8)])
    corners = corners + 1e-6 * (centres - corners)
    return np.hstack([nodes, corners]), nodes.shape[1]


def errors(md, mfu, mim, mesh, xs, zs):
    """Relative L2 error and max displacement error against the exact field."""
    uh = md.variable("u")
    uex = exact_u_gwfl()
    l2_diff = gf.asm_generic(mim, 0, "Norm_sqr(u - %s)" % uex, -1, md)
    l2_ref = gf.asm_generic(mim, 0, "Norm_sqr(%s)" % uex, -1, md)
    pts, n_nodes = probe_points(mesh, xs, zs)
    vals = np.asarray(gf.compute_interpolate_on(mfu, uh, pts)).reshape(3, -1)
    err = np.abs(vals - np.vstack([exact_ux(pts[0], pts[1]), np.zeros((2, pts.shape[1]))]))
    return {
        "err_rel_l2": float(np.sqrt(l2_diff / l2_ref)),
        "norm_l2_exact": float(np.sqrt(l2_ref)),
        "err_max_disp_nodes": float(err[:, :n_nodes].max()),
        "err_max_disp": float(err.max()),
        "n_probe_pts": int(pts.shape[1]),
    }


def enrichment_census(mfu):
    """Mesh nodes by the number of copies of their scalar Q1 function (1 = not enriched, 2 = next
    to one interface, 4 = next to the junction line)."""
    pts = mfu.basic_dof_nodes()[:, ::3]
    _, counts = np.unique(np.round(pts.T * 1e9).astype(np.int64), axis=0, return_counts=True)
    copies, nodes = np.unique(counts, return_counts=True)
    return {str(int(c)): int(k) for c, k in zip(copies, nodes)}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", type=int, default=5, help="cells along x and y")
    ap.add_argument("--layers", type=int, default=None, help="cells along z (default N)")
    ap.add_argument("--depth", type=float, default=1.0, help="box depth along z (ssnv511c: 1)")
    ap.add_argument("--offset", type=float, default=0.0,
                    help="interior grid lines moved by this fraction of a cell (|offset| < 1)")
    ap.add_argument("--solver", choices=["mumps", "superlu"], default="mumps")
    ap.add_argument("--cut-order", type=int, default=5,
                    help="degree of the IM_TETRAHEDRON rule on the sub-tetrahedra of the cut cells")
    args = ap.parse_args()
    args.layers = args.layers or args.n
    if args.n < 1 or args.layers < 1 or not abs(args.offset) < 1 or args.depth <= 0:
        ap.error("need N >= 1, LAYERS >= 1, |offset| < 1, depth > 0")
    h = 2 * HALF_WIDTH / args.n
    xs_check = grid_line(-HALF_WIDTH, HALF_WIDTH, args.n, args.offset)
    if np.any(np.abs(xs_check) < 1e-9 * h):
        ap.error("a grid plane lies on the interface x = 0 / y = 0 (even N needs --offset, e.g. 0.5)")

    gf.util_trace_level(0)
    try:
        load0 = float(open("/proc/loadavg").read().split()[0])
    except OSError:
        load0 = None
    args.phases = phases = Phases()
    mesh, xs, zs = build_mesh(args)
    phases.done("mesh")
    keep = []
    md, mfu, mim = build_model(mesh, args, keep)

    md.assembly("build_all")
    phases.done("assembly")
    K = md.tangent_matrix()
    F = md.rhs()
    phases.done("extract_K_F")
    solve = gf.linsolve_mumps if args.solver == "mumps" else gf.linsolve_superlu
    X = solve(K, F)
    md.to_variables(np.asarray(X).ravel())
    phases.done("solve")
    t_total = phases.total()
    rss_solve = peak_rss_mb()
    nnz = int(K.nnz())
    del K

    tp = time.perf_counter()
    res = {
        "scene": "ssnv511c refined",
        "n": args.n,
        "layers": args.layers,
        "depth": args.depth,
        "offset": args.offset,
        "dofs": int(mfu.nbdof()),
        "dofs_plain": 3 * (args.n + 1) ** 2 * (args.layers + 1),
        "dofs_multipliers": int(md.nbdof() - mfu.nbdof()),
        "dofs_total": int(md.nbdof()),
        "nnz_matrix": nnz,
        "nodes_by_copies": enrichment_census(mfu),
        "t_total_s": round(t_total, 4),
        "t_phases_s": {k: round(v, 4) for k, v in phases.times.items()},
        "peak_rss_mb": round(rss_solve, 1),
    }
    res.update(errors(md, mfu, mim, mesh, xs, zs))
    res["t_post_s"] = round(time.perf_counter() - tp, 4)
    res["solver"] = args.solver
    res["cut_integration"] = "IM_TETRAHEDRON(%d)" % args.cut_order
    res["blas"] = mapped_blas()
    res["loadavg_1m_at_start"] = load0
    print(json.dumps(res))
    return 0


if __name__ == "__main__":
    sys.exit(main())
