"""The manufactured displacement field of the smooth scene (astest/smooth_*.comm, smooth_contact_*.comm).

FIELD_SOURCE is plain Python pasted verbatim into the command files (between the markers), so
that the .comm stays self-contained and readable; this module executes the same text to check it
(finite differences, interface conditions, mutations that must fail) and to compute the exact norms.

Four blocks of the ssnv511 square [-5,5]^2 (numbered as in ssnv511e: 1 = x<0<y, 2 = x<0,y<0,
3 = x>0,y>0, 4 = y<0<x), each with its own field

    u_k(x, y) = c_k + w_k (-y, x) + (exx_k x, eyy_k y) + (alpha x^3, beta y^3) / L^2 + S (p_k, q_k),
    S = (x y / L^2)^2,   p_k = a0 + a1 x/L + a2 y/L,   q_k = b0 + b1 x/L + b2 y/L,   L = 5

(a polynomial of degree 5, so not in the span of the linear elements). Every first derivative of
S(p, q) carries a factor x y (x y^2 or x^2 y): the S part has no strain, hence no stress, on x = 0
and on y = 0 from each side, and no displacement there.

* Open variant (CONTACT = False): exx = eyy = alpha = beta = 0, a rigid motion per block plus the S
  part; the interfaces are open and traction-free, no contact or interface load is needed.
* Contact variant (CONTACT = True): no rotations; (exx_k, eyy_k) is the strain of a uniform stress
  (sxx_k, syy_k) per block, with sxx equal across x = 0 and syy equal across y = 0 (as ssnv511e:
  the normal traction jumps at the junction); alpha, beta < 0 are the same in every block
  (continuous, shear-free, compressive). The translations keep u_n continuous (c1y = c2y, c3y = c4y,
  c1x = c3x, c2x = c4x) and let the blocks slide. On every interface: [u_n] = 0, tangential traction
  0 (sigma_xy = 0 there), normal traction continuous and <= -0.002 E: frictionless contact, closed.

Plane strain and 3D (u_z = 0, sigma_zz = lambda tr eps) use lambda, plane stress
lambda* = 2 lambda mu / (lambda + 2 mu) and sigma_zz = 0. The body force is f = -div sigma (the
derivatives are the product rule applied by hand; the uniform part has none, the cubic part gives
-(lambda + 2 mu) (6 alpha x, 6 beta y) / L^2).
"""
import math

FIELD_SOURCE = r'''
# ---- manufactured field (tools/study/smooth_field.py; checked by `./miniaster study check-field`) ----
L = 5.0
# Per block (1 = x<0<y, 2 = x<0,y<0, 3 = x,y>0, 4 = y<0<x): translation c, rotation w, coefficients a
# of u_x's S p and b of u_y's S q, uniform stress (sxx, syy) / E of the linear part.
if CONTACT:
    # Closed interfaces in frictionless contact. No rotation; c1 = (a, b), c2 = (a', b), c3 = (a, b'),
    # c4 = (a', b') keep the normal displacement continuous while the blocks slide (by a - a' along
    # FISS1, b - b' along FISS2/FISS3); sxx is the same across x = 0 (blocks 1|3, 2|4) and syy across
    # y = 0 (1|2, 3|4): the normal traction is continuous, compressive, and jumps at the junction.
    BLOCKS = {
        1: ((0.010, 0.015), 0.0, (0.020, 0.010, -0.005), (-0.010, 0.005, 0.015), (-0.003, -0.002)),
        2: ((-0.020, 0.015), 0.0, (-0.015, 0.005, 0.010), (0.020, -0.010, 0.005), (-0.002, -0.002)),
        3: ((0.010, -0.010), 0.0, (0.010, -0.020, 0.005), (0.015, 0.010, -0.010), (-0.003, -0.004)),
        4: ((-0.020, -0.010), 0.0, (-0.020, 0.010, 0.010), (-0.005, 0.020, 0.010), (-0.002, -0.004)),
    }
    ALPHA, BETA = -0.002, -0.003  # u_x += ALPHA x^3 / L^2, u_y += BETA y^3 / L^2 in every block
else:
    # Open traction-free interfaces: the blocks move apart, no stress on x = 0 or y = 0.
    BLOCKS = {
        1: ((-0.25, 0.05), 0.010, (0.20, 0.10, -0.05), (-0.10, 0.05, 0.15), (0.0, 0.0)),
        2: ((-0.50, -0.05), -0.020, (-0.15, 0.05, 0.10), (0.20, -0.10, 0.05), (0.0, 0.0)),
        3: ((0.75, 0.10), 0.015, (0.10, -0.20, 0.05), (0.15, 0.10, -0.10), (0.0, 0.0)),
        4: ((1.00, -0.10), -0.010, (-0.20, 0.10, 0.10), (-0.05, 0.20, 0.10), (0.0, 0.0)),
    }
    ALPHA, BETA = 0.0, 0.0
MU = E / (2.0 * (1.0 + NU))
LAMBDA = E * NU / ((1.0 + NU) * (1.0 - 2.0 * NU)) if NU < 0.5 else 0.0
# plane stress: in-plane lambda* = 2 lambda mu / (lambda + 2 mu) = E nu / (1 - nu^2), sigma_zz = 0
LAMBDA_PLANE = E * NU / (1.0 - NU * NU) if MODELISATION == 'C_PLAN' else LAMBDA
LAMBDA_ZZ = 0.0 if MODELISATION == 'C_PLAN' else LAMBDA

def uniform_strain(sxx, syy):
    # (exx, eyy) of a uniform in-plane stress (exy = 0): inverse of [[l+2m, l], [l, l+2m]], l = LAMBDA_PLANE
    det = 4.0 * MU * (LAMBDA_PLANE + MU)
    return (((LAMBDA_PLANE + 2.0 * MU) * sxx - LAMBDA_PLANE * syy) / det,
            ((LAMBDA_PLANE + 2.0 * MU) * syy - LAMBDA_PLANE * sxx) / det)

# one row per block: cx, cy, w, a0, a1, a2, b0, b1, b2, exx, eyy
ROWS = {k: (*c, w, *a, *b, *uniform_strain(E * s[0], E * s[1])) for k, (c, w, a, b, s) in BLOCKS.items()}

def coefficients(x, y):
    # the row of the block of (x, y); x, y are floats or numpy arrays (FORMULE evaluates batches as
    # arrays: no `if` on them). The + side of an interface (level set >= 0) owns the points on it.
    right, up = 1.0 * (x >= 0.0), 1.0 * (y >= 0.0)
    weight = {1: (1.0 - right) * up, 2: (1.0 - right) * (1.0 - up), 3: right * up, 4: right * (1.0 - up)}
    return [sum(weight[k] * ROWS[k][i] for k in weight) for i in range(11)]

def ux(x, y):
    cx, cy, w, a0, a1, a2, b0, b1, b2, exx, eyy = coefficients(x, y)
    s, t = x / L, y / L
    return cx - w * y + exx * x + ALPHA * x ** 3 / L ** 2 + (s * t) ** 2 * (a0 + a1 * s + a2 * t)

def uy(x, y):
    cx, cy, w, a0, a1, a2, b0, b1, b2, exx, eyy = coefficients(x, y)
    s, t = x / L, y / L
    return cy + w * x + eyy * y + BETA * y ** 3 / L ** 2 + (s * t) ** 2 * (b0 + b1 * s + b2 * t)

def gradient(x, y):
    # (d ux/dx, d ux/dy, d uy/dx, d uy/dy): product rule on S p, S q; the rotation gives -w, +w
    cx, cy, w, a0, a1, a2, b0, b1, b2, exx, eyy = coefficients(x, y)
    s, t = x / L, y / L
    S = (s * t) ** 2
    Sx, Sy = 2.0 * s * t * t / L, 2.0 * s * s * t / L
    p, q = a0 + a1 * s + a2 * t, b0 + b1 * s + b2 * t
    return (exx + 3.0 * ALPHA * s * s + Sx * p + S * a1 / L, -w + Sy * p + S * a2 / L,
            w + Sx * q + S * b1 / L, eyy + 3.0 * BETA * t * t + Sy * q + S * b2 / L)

def hessian(x, y):
    # (ux_xx, ux_yy, ux_xy, uy_xx, uy_yy, uy_xy) (p, q are linear: no second derivatives of their own)
    cx, cy, w, a0, a1, a2, b0, b1, b2, exx, eyy = coefficients(x, y)
    s, t = x / L, y / L
    Sx, Sy = 2.0 * s * t * t / L, 2.0 * s * s * t / L
    Sxx, Syy, Sxy = 2.0 * t * t / L ** 2, 2.0 * s * s / L ** 2, 4.0 * s * t / L ** 2
    p, px, py = a0 + a1 * s + a2 * t, a1 / L, a2 / L
    q, qx, qy = b0 + b1 * s + b2 * t, b1 / L, b2 / L
    return (6.0 * ALPHA * s / L + Sxx * p + 2.0 * Sx * px, Syy * p + 2.0 * Sy * py, Sxy * p + Sx * py + Sy * px,
            Sxx * q + 2.0 * Sx * qx, 6.0 * BETA * t / L + Syy * q + 2.0 * Sy * qy, Sxy * q + Sx * qy + Sy * qx)

def stress(x, y):
    # (sxx, syy, szz, sxy) of the exact field
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
    # -(d sxx/dx + d sxy/dy)
    uxxx, uxyy, uxxy, uyxx, uyyy, uyxy = hessian(x, y)
    return -((LAMBDA_PLANE + 2.0 * MU) * uxxx + MU * uxyy + (LAMBDA_PLANE + MU) * uyxy)

def fy(x, y):
    # -(d sxy/dx + d syy/dy)
    uxxx, uxyy, uxxy, uyxx, uyyy, uyxy = hessian(x, y)
    return -(MU * uyxx + (LAMBDA_PLANE + 2.0 * MU) * uyyy + (LAMBDA_PLANE + MU) * uxxy)
# ---- end of the manufactured field ----
'''


def load(modelisation="D_PLAN", E=100.0e6, NU=0.3, contact=False, source=None):
    """Executes FIELD_SOURCE (or a mutated copy, `source`) for one material, modelling and variant
    (contact: closed interfaces); returns its namespace."""
    ns = {"MODELISATION": modelisation, "E": E, "NU": NU, "CONTACT": contact}
    exec(source or FIELD_SOURCE, ns)
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


def exact_norms(modelisation="D_PLAN", E=100.0e6, NU=0.3, thickness=1.0, contact=False):
    """Exact ||u||_L2 over the square and the exact strain energy (what POST_ERREUR calls REFERENCE
    for DEPL_RELA and ENER_RELA) per block and in total, times the thickness (3D slabs; 1 in 2D).

    The integrands are polynomials of degree <= 10 in each variable on each block, so a 8x8
    Gauss-Legendre rule (exact to degree 15 per variable) gives the analytic integrals to round-off.
    The energy density is POST_ERREUR's w(sigma) (docs/tables.md), C_PLAN without sigma_zz."""
    f = load(modelisation, E, NU, contact)
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


# points along the interfaces (x on y = 0, y on x = 0), both sides at +-SIDE
INTERFACE_POINTS = [-4.99, -4.5, -3.3, -2.0, -1.0, -0.3, -0.01, 0.01, 0.3, 1.0, 1.7, 2.5, 3.9, 4.5, 4.99]
SIDE = 1e-10
# contact variant: the least compressive normal traction allowed on an interface, as a fraction of E
COMPRESSION_MARGIN = 1e-3


def check(modelisation="D_PLAN", E=100.0e6, NU=0.3, contact=False, source=None, verbose=True):
    """Independent checks of FIELD_SOURCE (or of a mutated copy, `source`): derivatives against
    central finite differences of u, body force against finite differences of the stresses, and the
    interface conditions on both sides of the interfaces (open: sigma.n = 0; contact: [u_n] = 0,
    sigma_t = 0, sigma_n continuous and <= -COMPRESSION_MARGIN E). Returns the list of failures
    (empty when everything holds)."""
    f = load(modelisation, E, NU, contact, source)
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
    # each side of y = 0 (normal y: u_n = uy, traction (sxy, syy)) and of x = 0 (normal x: ux, (sxx, sxy))
    sides = []  # (interface, point, u_n, u_t, sigma_n, sigma_t) per side
    for v in INTERFACE_POINTS:
        for side in (SIDE, -SIDE):
            sxx, syy, _, sxy = f["stress"](v, side)
            sides.append(("FISS1", v, f["uy"](v, side), f["ux"](v, side), syy, sxy))
            sxx, syy, _, sxy = f["stress"](side, v)
            sides.append(("FISS2" if v > 0 else "FISS3", v, f["ux"](side, v), f["uy"](side, v), sxx, sxy))
    pairs = list(zip(sides[0::4] + sides[1::4], sides[2::4] + sides[3::4]))  # (+ side, - side) of one point
    slip = max(abs(p[3] - m[3]) for p, m in pairs)
    if not contact:
        worst = max(max(abs(s[4]), abs(s[5])) for s in sides)
        summary = f"max |sigma.n| = {worst:.1e}"
        if worst > 1e-8 * E:
            failures.append(f"traction on an interface: {worst}")
        # the field really jumps across the interfaces (4 distinct blocks)
        jumps = [abs(f["ux"](-1.0, 1e-9) - f["ux"](-1.0, -1e-9)), abs(f["ux"](1e-9, 1.0) - f["ux"](-1e-9, 1.0)),
                 abs(f["ux"](1e-9, -1.0) - f["ux"](-1e-9, -1.0)), abs(f["ux"](1.0, 1e-9) - f["ux"](1.0, -1e-9))]
        if min(jumps) < 1e-3:
            failures.append(f"the blocks do not move apart: jumps {jumps}")
    else:
        gap = max(abs(p[2] - m[2]) for p, m in pairs)
        shear = max(abs(s[5]) for s in sides)
        traction_jump = max(abs(p[4] - m[4]) for p, m in pairs)
        least = max(s[4] for s in sides)
        where = [s[:2] for s in sides if s[4] == least][0]
        # the normal traction on FISS1 jumps at the junction (the two pieces of the facets split there)
        junction = abs(f["siyy"](-1e-6, SIDE) - f["siyy"](1e-6, SIDE))
        summary = (f"max |[u_n]| = {gap:.1e}, max |sigma_t| = {shear:.1e}, max |[sigma_n]| = {traction_jump:.1e}, "
                   f"least compressive sigma_n = {least:.4g} = {least / E:.2e} E on {where[0]} at {where[1]}, "
                   f"tangential slip up to {slip:.3g}, sigma_n jump at the junction {junction / E:.1e} E")
        if gap > 1e-9:
            failures.append(f"normal displacement jumps across an interface: {gap}")
        if shear > 1e-8 * E:
            failures.append(f"tangential traction on an interface: {shear}")
        if traction_jump > 1e-8 * E:
            failures.append(f"normal traction not continuous across an interface: {traction_jump}")
        if least > -COMPRESSION_MARGIN * E:
            failures.append(f"normal traction {least} on {where[0]} at {where[1]} is not compressive by "
                            f"{COMPRESSION_MARGIN} E")
        if slip < 1e-3:
            failures.append(f"the blocks do not slide: largest tangential jump {slip}")
    if verbose:
        print(f"field check {'contact' if contact else 'open'} {modelisation} E={E} NU={NU}: derivatives, "
              f"-div sigma, interfaces ({summary}) " + ("OK" if not failures else "FAILED"))
        for m in failures:
            print("  " + m)
    return failures


# Deliberate errors that check() must catch: (variant, what, text in FIELD_SOURCE, replacement)
MUTATIONS = [
    (False, "S term of u_x not what the gradient differentiates", "(s * t) ** 2 * (a0", "(s * t) ** 2 * (1.001 * a0"),
    (False, "d ux/dy of S p", "-w + Sy * p + S * a2 / L", "-w + Sy * p + 1.01 * S * a2 / L"),
    (False, "hessian term of the body force", "Sxx * p + 2.0 * Sx * px", "Sxx * p + 1.9 * Sx * px"),
    (True, "cubic term of the body force", "6.0 * ALPHA * s / L", "5.0 * ALPHA * s / L"),
    (True, "translation of block 2 opens FISS1", "((-0.020, 0.015), 0.0", "((-0.020, 0.016), 0.0"),
    (True, "rotation of block 1 opens FISS1 and FISS2", "((0.010, 0.015), 0.0,", "((0.010, 0.015), 0.001,"),
    (True, "syy of block 2 differs from block 1 across FISS1", "(-0.002, -0.002)),", "(-0.002, -0.0025)),"),
    (True, "cubic term makes FISS1 tensile near x = +-5", "ALPHA, BETA = -0.002, -0.003", "ALPHA, BETA = 0.004, -0.003"),
]


def check_mutations(verbose=True):
    """Every mutation of MUTATIONS must make check() fail (for D_PLAN and C_PLAN); returns the
    list of mutations that were not caught."""
    missed = []
    for contact, what, old, new in MUTATIONS:
        if FIELD_SOURCE.count(old) != 1:
            missed.append(f"mutation '{what}': '{old}' is not once in FIELD_SOURCE")
            continue
        source = FIELD_SOURCE.replace(old, new)
        caught = [len(check(m, contact=contact, source=source, verbose=False)) for m in ("D_PLAN", "C_PLAN")]
        if not all(caught):
            missed.append(f"mutation '{what}' passes the check")
        if verbose:
            print(f"mutation ({'contact' if contact else 'open'}) {what}: "
                  + ("caught" if all(caught) else "NOT CAUGHT") + f" ({caught[0]} / {caught[1]} failures)")
    return missed
