"""The manufactured displacement field of the smooth scene (astest/smooth_*.comm).

FIELD_SOURCE is plain Python pasted verbatim into the command files (between the markers), so
that the .comm stays self-contained and readable; this module executes the same text to check it
(finite differences, tractions on the interfaces) and to compute the exact norms.

Four blocks of the ssnv511 square [-5,5]^2 (numbered as in ssnv511e: 1 = x<0<y, 2 = x<0,y<0,
3 = x>0,y>0, 4 = y<0<x), each with its own field

    u_k(x, y) = c_k + w_k (-y, x) + S(x, y) (p_k(x, y), q_k(x, y)),   S = (x y / L^2)^2,
    p_k = a0 + a1 x/L + a2 y/L,   q_k = b0 + b1 x/L + b2 y/L,   L = 5

(a rigid motion plus a degree-5 polynomial, so not in the span of the linear elements). Every
first derivative of S(p, q) carries a factor x y (x y^2 or x^2 y): the strain, hence the stress,
vanishes on x = 0 and on y = 0 from each side, so the interfaces are open and traction-free and
no contact or interface load is needed. Plane strain and 3D (u_z = 0, sigma_zz = lambda tr eps)
use lambda, plane stress lambda* = 2 lambda mu / (lambda + 2 mu) and sigma_zz = 0. The body
force is f = -div sigma (the derivatives below are the product rule applied by hand to S p).
"""
import math

FIELD_SOURCE = r'''
# ---- manufactured field (tools/study/smooth_field.py; checked by `./miniaster study check-field`) ----
L = 5.0
BLOCKS = {  # translation c, rotation w, coefficients a of u_x and b of u_y
    1: ((-0.25, 0.05), 0.010, (0.20, 0.10, -0.05), (-0.10, 0.05, 0.15)),
    2: ((-0.50, -0.05), -0.020, (-0.15, 0.05, 0.10), (0.20, -0.10, 0.05)),
    3: ((0.75, 0.10), 0.015, (0.10, -0.20, 0.05), (0.15, 0.10, -0.10)),
    4: ((1.00, -0.10), -0.010, (-0.20, 0.10, 0.10), (-0.05, 0.20, 0.10)),
}
MU = E / (2.0 * (1.0 + NU))
LAMBDA = E * NU / ((1.0 + NU) * (1.0 - 2.0 * NU)) if NU < 0.5 else 0.0
# plane stress: in-plane lambda* = 2 lambda mu / (lambda + 2 mu) = E nu / (1 - nu^2), sigma_zz = 0
LAMBDA_PLANE = E * NU / (1.0 - NU * NU) if MODELISATION == 'C_PLAN' else LAMBDA
LAMBDA_ZZ = 0.0 if MODELISATION == 'C_PLAN' else LAMBDA

def block(x, y):
    # the + side of an interface (level set >= 0) owns the points on it
    if y >= 0.0:
        return BLOCKS[3] if x >= 0.0 else BLOCKS[1]
    return BLOCKS[4] if x >= 0.0 else BLOCKS[2]

def ux(x, y):
    c, w, a, b = block(x, y)
    s, t = x / L, y / L
    return c[0] - w * y + (s * t) ** 2 * (a[0] + a[1] * s + a[2] * t)

def uy(x, y):
    c, w, a, b = block(x, y)
    s, t = x / L, y / L
    return c[1] + w * x + (s * t) ** 2 * (b[0] + b[1] * s + b[2] * t)

def gradient(x, y):
    """(d ux/dx, d ux/dy, d uy/dx, d uy/dy): product rule on S p, S q; the rotation gives -w, +w."""
    c, w, a, b = block(x, y)
    s, t = x / L, y / L
    S = (s * t) ** 2
    Sx, Sy = 2.0 * s * t * t / L, 2.0 * s * s * t / L
    p, q = a[0] + a[1] * s + a[2] * t, b[0] + b[1] * s + b[2] * t
    return (Sx * p + S * a[1] / L, -w + Sy * p + S * a[2] / L, w + Sx * q + S * b[1] / L, Sy * q + S * b[2] / L)

def hessian(x, y):
    """(ux_xx, ux_yy, ux_xy, uy_xx, uy_yy, uy_xy) (p, q are linear: no second derivatives of their own)."""
    c, w, a, b = block(x, y)
    s, t = x / L, y / L
    Sx, Sy = 2.0 * s * t * t / L, 2.0 * s * s * t / L
    Sxx, Syy, Sxy = 2.0 * t * t / L ** 2, 2.0 * s * s / L ** 2, 4.0 * s * t / L ** 2
    p, px, py = a[0] + a[1] * s + a[2] * t, a[1] / L, a[2] / L
    q, qx, qy = b[0] + b[1] * s + b[2] * t, b[1] / L, b[2] / L
    return (Sxx * p + 2.0 * Sx * px, Syy * p + 2.0 * Sy * py, Sxy * p + Sx * py + Sy * px,
            Sxx * q + 2.0 * Sx * qx, Syy * q + 2.0 * Sy * qy, Sxy * q + Sx * qy + Sy * qx)

def stress(x, y):
    """(sxx, syy, szz, sxy) of the exact field."""
    exx, uxy, uyx, eyy = gradient(x, y)
    return ((LAMBDA_PLANE + 2.0 * MU) * exx + LAMBDA_PLANE * eyy, LAMBDA_PLANE * exx + (LAMBDA_PLANE + 2.0 * MU) * eyy,
            LAMBDA_ZZ * (exx + eyy), MU * (uxy + uyx))

def sixx(x, y):
    exx, uxy, uyx, eyy = gradient(x, y)
    return (LAMBDA_PLANE + 2.0 * MU) * exx + LAMBDA_PLANE * eyy

def siyy(x, y):
    exx, uxy, uyx, eyy = gradient(x, y)
    return LAMBDA_PLANE * exx + (LAMBDA_PLANE + 2.0 * MU) * eyy

def sizz(x, y):
    exx, uxy, uyx, eyy = gradient(x, y)
    return LAMBDA_ZZ * (exx + eyy)

def sixy(x, y):
    exx, uxy, uyx, eyy = gradient(x, y)
    return MU * (uxy + uyx)

def fx(x, y):
    """-(d sxx/dx + d sxy/dy)"""
    uxxx, uxyy, uxxy, uyxx, uyyy, uyxy = hessian(x, y)
    return -((LAMBDA_PLANE + 2.0 * MU) * uxxx + MU * uxyy + (LAMBDA_PLANE + MU) * uyxy)

def fy(x, y):
    """-(d sxy/dx + d syy/dy)"""
    uxxx, uxyy, uxxy, uyxx, uyyy, uyxy = hessian(x, y)
    return -(MU * uyxx + (LAMBDA_PLANE + 2.0 * MU) * uyyy + (LAMBDA_PLANE + MU) * uxxy)
# ---- end of the manufactured field ----
'''


def load(modelisation="D_PLAN", E=100.0e6, NU=0.3):
    """Executes FIELD_SOURCE for one material and modelling; returns its namespace."""
    ns = {"MODELISATION": modelisation, "E": E, "NU": NU}
    exec(FIELD_SOURCE, ns)
    return ns


def gauss_legendre(n):
    """Nodes and weights on [-1, 1] (Newton on the Legendre polynomial; exact to round-off)."""
    nodes, weights = [], []
    for i in range(n):
        x = math.cos(math.pi * (i + 0.75) / (n + 0.5))
        for _ in range(100):
            p0, p1 = 1.0, x
            for k in range(2, n + 1):
                p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
            dp = n * (x * p1 - p0) / (x * x - 1.0)
            dx = p1 / dp
            x -= dx
            if abs(dx) < 1e-16:
                break
        nodes.append(x)
        weights.append(2.0 / ((1.0 - x * x) * dp * dp))
    return nodes, weights


QUADRANTS = {1: ((-5.0, 0.0), (0.0, 5.0)), 2: ((-5.0, 0.0), (-5.0, 0.0)),
             3: ((0.0, 5.0), (0.0, 5.0)), 4: ((0.0, 5.0), (-5.0, 0.0))}


def exact_norms(modelisation="D_PLAN", E=100.0e6, NU=0.3, thickness=1.0):
    """Exact ||u||_L2 over the square and the exact strain energy (what POST_ERREUR calls REFERENCE
    for DEPL_RELA and ENER_RELA) per block and in total, times the thickness (3D slabs; 1 in 2D).

    The integrands are polynomials of degree <= 10 in each variable on each block, so a 8x8
    Gauss-Legendre rule (exact to degree 15 per variable) gives the analytic integrals to round-off.
    The energy density is POST_ERREUR's w(sigma) (docs/tables.md), C_PLAN without sigma_zz."""
    f = load(modelisation, E, NU)
    nodes, weights = gauss_legendre(8)
    l2 = {}
    energy = {}
    for k, ((x0, x1), (y0, y1)) in QUADRANTS.items():
        su, se = 0.0, 0.0
        for xi, wi in zip(nodes, weights):
            x = 0.5 * (x0 + x1) + 0.5 * (x1 - x0) * xi
            for yj, wj in zip(nodes, weights):
                y = 0.5 * (y0 + y1) + 0.5 * (y1 - y0) * yj
                # points are interior to the block: block(x, y) == k
                w = wi * wj * 0.25 * (x1 - x0) * (y1 - y0)
                su += w * (f["ux"](x, y) ** 2 + f["uy"](x, y) ** 2)
                sxx, syy, szz, sxy = f["stress"](x, y)
                if modelisation == "C_PLAN":
                    szz = 0.0
                se += w * ((sxx * sxx + syy * syy + szz * szz - 2 * NU * (sxx * syy + syy * szz + szz * sxx)) / (2 * E)
                           + (1 + NU) / E * sxy * sxy)
        l2[k] = su * thickness
        energy[k] = se * thickness
    return math.sqrt(sum(l2.values())), sum(energy.values()), l2, energy


def check(modelisation="D_PLAN", E=100.0e6, NU=0.3, verbose=True):
    """Independent checks of FIELD_SOURCE: derivatives against central finite differences of u,
    body force against finite differences of the stresses, tractions on both sides of the
    interfaces. Returns the list of failures (empty when everything holds)."""
    f = load(modelisation, E, NU)
    failures = []
    h = 1e-4
    pts = [(-3.7, 2.2), (-1.3, -4.1), (2.9, 0.7), (4.4, -2.6), (-0.2, 0.3), (0.45, -0.35)]
    for (x, y) in pts:
        g = f["gradient"](x, y)
        fd = [(f["ux"](x + h, y) - f["ux"](x - h, y)) / (2 * h), (f["ux"](x, y + h) - f["ux"](x, y - h)) / (2 * h),
              (f["uy"](x + h, y) - f["uy"](x - h, y)) / (2 * h), (f["uy"](x, y + h) - f["uy"](x, y - h)) / (2 * h)]
        for name, exact, approx in zip(("ux_x", "ux_y", "uy_x", "uy_y"), g, fd):
            if abs(exact - approx) > 1e-7 * (1 + abs(exact)):
                failures.append(f"{name} at ({x}, {y}): {exact} vs finite difference {approx}")
        if tuple(f["stress"](x, y)) != (f["sixx"](x, y), f["siyy"](x, y), f["sizz"](x, y), f["sixy"](x, y)):
            failures.append(f"stress() and SIXX..SIXY differ at ({x}, {y})")
        # div sigma by finite differences of the stress functions
        dsxx = (f["sixx"](x + h, y) - f["sixx"](x - h, y)) / (2 * h)
        dsxy_y = (f["sixy"](x, y + h) - f["sixy"](x, y - h)) / (2 * h)
        dsxy_x = (f["sixy"](x + h, y) - f["sixy"](x - h, y)) / (2 * h)
        dsyy = (f["siyy"](x, y + h) - f["siyy"](x, y - h)) / (2 * h)
        scale = E * 1e-6
        for name, exact, approx in (("fx", f["fx"](x, y), -(dsxx + dsxy_y)), ("fy", f["fy"](x, y), -(dsxy_x + dsyy))):
            if abs(exact - approx) > 1e-6 * scale + 1e-7 * abs(exact):
                failures.append(f"{name} at ({x}, {y}): {exact} vs -div sigma by finite differences {approx}")
    # tractions sigma.n on y = 0 (n = (0, ±1): sxy, syy) and x = 0 (n = (±1, 0): sxx, sxy), each side
    worst = 0.0
    for v in [-4.9, -3.3, -1.0, -0.01, 0.01, 1.7, 3.9, 4.95]:
        for side in (1e-10, -1e-10):
            sxx, syy, _, sxy = f["stress"](v, side)
            worst = max(worst, abs(sxy), abs(syy))
            sxx, syy, _, sxy = f["stress"](side, v)
            worst = max(worst, abs(sxx), abs(sxy))
    if worst > 1e-8 * E:
        failures.append(f"traction on an interface: {worst}")
    # the field really jumps across the interfaces (4 distinct blocks)
    jumps = [abs(f["ux"](-1.0, 1e-9) - f["ux"](-1.0, -1e-9)), abs(f["ux"](1e-9, 1.0) - f["ux"](-1e-9, 1.0)),
             abs(f["ux"](1e-9, -1.0) - f["ux"](-1e-9, -1.0)), abs(f["ux"](1.0, 1e-9) - f["ux"](1.0, -1e-9))]
    if min(jumps) < 1e-3:
        failures.append(f"the blocks do not move apart: jumps {jumps}")
    if verbose:
        print(f"field check {modelisation} E={E} NU={NU}: derivatives, -div sigma and interface tractions "
              f"(max |sigma.n| = {worst:.1e}) " + ("OK" if not failures else "FAILED"))
        for m in failures:
            print("  " + m)
    return failures
