#!/usr/bin/python3
"""Refinement study of ssnp138a's inclined cracks (issue 26, docs/cracks.md).

ssnp138a (code_aster's file, 100 x 100 QUAD4 of a 0.2 x 0.5 plate, a SEGMENT crack of length
A = 0.04 through the centre at 0, 15, 30, 45, 60 degrees) checks CALC_G and POST_K1_K2_K3 against
K1 = sigma sqrt(pi A / 2) f(A / W) cos^2(alpha), K2 = ... cos(alpha) sin(alpha) (Tada's finite-width
factor f of the straight crack). At 60 degrees its POST_K1_K2_K3 K1 is NOOK (tolerances 3 % at tip 1,
2 % at tip 2). This script builds the same problem on the same grid family (tools/ssnv511_mesh
--bounds -0.1 0.1 -0.25 0.25: N = 100 is the file's grid, same nodes, groups LB / LH for its LIG1 /
LIG3) refined N = 100, 200, 400 and tabulates at each angle CALC_G (OPTION='CALC_K_G', the file's
crown R_INF = 0.1 A, R_SUP = 0.3 A) and POST_K1_K2_K3 (NB_NOEUD_COUPE=4 as the file: ABSC_CURV_MAXI
by default, 5 x TAILLE_R, and a fixed 0.01) at both tips, with their errors against the file's
reference.

  ./miniaster study ssnp138a --out docs/study
  /usr/bin/python3 tools/study/ssnp138a_refinement.py [--build build] [--sizes 100,200,400] [--angles 45,60]
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
W, H, A, PRES, E, NU = 0.2, 0.5, 0.04, -1.0e6, 210e9, 0.3

COMM = """DEBUT()
from math import *
W = {W}
H = {H}
eps = sqrt((W/{n})**2 + (H/{n})**2)
A = {A}
alpha = {angle}*pi/180.
ACIER = DEFI_MATERIAU(ELAS=_F(E={E}, NU={NU}))
MA = LIRE_MAILLAGE(FORMAT='MED')
MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=(
    _F(NOM='NA', OPTION='ENV_SPHERE', POINT=(-W/2., 0.), PRECISION=eps/4., RAYON=eps/4.),
    _F(NOM='NB', OPTION='ENV_SPHERE', POINT=(+W/2., 0.), PRECISION=eps/4., RAYON=eps/4.),
    _F(NOM='NC', OPTION='ENV_SPHERE', POINT=(0., -H/2.), PRECISION=eps/4., RAYON=eps/4.),
    _F(NOM='ND', OPTION='ENV_SPHERE', POINT=(0., +H/2.), PRECISION=eps/4., RAYON=eps/4.)))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=('SURF', 'LB', 'LH'), PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU_2D=_F(GROUP_MA=('LB', 'LH')))
FISS = DEFI_FISS_XFEM(MAILLAGE=MA, DEFI_FISS=_F(FORM_FISS='SEGMENT',
    PFON_ORIG=(-A*cos(alpha)/2, -A*sin(alpha)/2, 0.), PFON_EXTR=(A*cos(alpha)/2, A*sin(alpha)/2, 0.)),
    TYPE_ENRI_FOND='GEOMETRIQUE', NB_COUCHES=5)
MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=FISS)
CM = AFFE_MATERIAU(MAILLAGE=MA, MODELE=MX, AFFE=_F(TOUT='OUI', MATER=ACIER))
CH = AFFE_CHAR_MECA(MODELE=MX, DDL_IMPO=(_F(GROUP_NO=('NA', 'NB'), DY=0.), _F(GROUP_NO=('NC', 'ND'), DX=0.)),
    PRES_REP=_F(GROUP_MA=('LB', 'LH'), PRES={PRES}))
RESU = MECA_STATIQUE(MODELE=MX, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH))
for fond in (1, 2):
    T = CALC_G(RESULTAT=RESU, OPTION='CALC_K_G', THETA=_F(FISSURE=FISS, NUME_FOND=fond, R_INF=0.1*A, R_SUP=0.3*A))
    IMPR_TABLE(TABLE=T)
for fond in (1, 2):
    P = POST_K1_K2_K3(FISSURE=FISS, NUME_FOND=fond, RESULTAT=RESU, NB_NOEUD_COUPE=4)
for fond in (1, 2):
    P = POST_K1_K2_K3(FISSURE=FISS, NUME_FOND=fond, RESULTAT=RESU, NB_NOEUD_COUPE=4, ABSC_CURV_MAXI=0.01)
FIN()
"""


def references(angle):
    """The file's K1REF, K2REF (Tada p. 42 with cos^2, cos sin)."""
    a, r = math.radians(angle), A / W
    f = 1.0 + 0.128 * r - 0.288 * r**2 + 1.525 * r**3
    k = -PRES * math.sqrt(math.pi * A / 2.0) * f
    return k * math.cos(a) ** 2, k * math.cos(a) * math.sin(a)


def run(build, n, angle, work):
    mesh = os.path.join(work, f"plate_n{n}.med")
    if not os.path.exists(mesh):
        subprocess.run([os.path.join(build, "tools", "ssnv511_mesh"), "--type", "quad4", "--n", str(n), "--bounds",
                        str(-W / 2), str(W / 2), str(-H / 2), str(H / 2), "-o", mesh], check=True,
                       stdout=subprocess.DEVNULL)
    name = f"ssnp138a_n{n}_a{angle:g}"
    comm = os.path.join(work, name + ".comm")
    with open(comm, "w") as f:
        f.write(COMM.format(W=W, H=H, A=A, E=E, NU=NU, PRES=PRES, n=n, angle=angle))
    out = os.path.join(work, name)
    t0 = time.time()
    p = subprocess.run([os.path.join(build, "miniaster"), "run", comm, "--mesh", mesh, "--out-dir", out],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.time() - t0
    if p.returncode != 0:
        sys.exit(f"{name} failed (exit {p.returncode}):\n{p.stdout[-3000:]}")
    resu = open(os.path.join(out, name + ".resu")).read()
    mess = open(os.path.join(out, name + ".mess")).read()
    calc_g = [(float(m.group(1)), float(m.group(2))) for m in re.finditer(
        r"^\s+[12]\s+1\s+\S+\s+\S+\s+\S+\s+\S+\s+(\S+)\s+(\S+)\s+\S+\s*$", resu, re.M)]
    post_k = [(float(m.group(1)), float(m.group(2)), float(m.group(3))) for m in re.finditer(
        r"points over (\S+): K1 = (\S+), K2 = (\S+),", mess)]
    if len(calc_g) != 2 or len(post_k) != 4:
        sys.exit(f"{name}: expected 2 CALC_G rows and 4 POST_K1_K2_K3 results, found {len(calc_g)}, {len(post_k)}")
    return calc_g, post_k, wall


def pct(value, ref):
    return f"{100.0 * (value - ref) / ref:+.2f} %"


def table(rows):
    head = ("| angle | N | CALC_G K1 tip 1 / 2 | CALC_G K2 tip 1 / 2 | ABSC_CURV_MAXI | POST_K1_K2_K3 K1 tip 1 / 2 "
            "| POST K2 tip 1 / 2 | ABSC_CURV_MAXI 0.01: POST K1 tip 1 / 2 | wall (s) |")
    lines = [head, "|" + "---|" * 9]
    for angle, n, (calc_g, post_k, wall) in rows:
        k1, k2 = references(angle)
        lines.append(
            f"| {angle:g} | {n} | {pct(calc_g[0][0], k1)}, {pct(calc_g[1][0], k1)} | "
            f"{pct(calc_g[0][1], k2)}, {pct(calc_g[1][1], k2)} | {post_k[0][0]:.4g} | "
            f"{pct(post_k[0][1], k1)}, {pct(post_k[1][1], k1)} | {pct(post_k[0][2], k2)}, {pct(post_k[1][2], k2)} | "
            f"{pct(post_k[2][1], k1)}, {pct(post_k[3][1], k1)} | {wall:.0f} |")
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--sizes", default="100,200,400")
    ap.add_argument("--angles", default="45,60")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "study"))
    args = ap.parse_args(argv)
    rows = []
    with tempfile.TemporaryDirectory(prefix="ssnp138a-") as work:
        for angle in (float(a) for a in args.angles.split(",")):
            for n in (int(s) for s in args.sizes.split(",")):
                result = run(args.build, n, angle, work)
                rows.append((angle, n, result))
                print(f"{angle:g} deg, N = {n}: CALC_G K1 {result[0][0][0]:.6e}, POST_K1_K2_K3 K1 "
                      f"{result[1][0][1]:.6e} / {result[1][1][1]:.6e}, {result[2]:.0f} s")
    text = f"""# ssnp138a refinement study

Generated by `./miniaster study ssnp138a --out docs/study` (tools/study/ssnp138a_refinement.py): the
problem of code_aster's ssnp138a.comm (plate 0.2 x 0.5, D_PLAN, E = 210e9, nu = 0.3, pressure
{-PRES:g} on top and bottom, SEGMENT crack of length A = {A} centred at the origin, GEOMETRIQUE,
NB_COUCHES=5) on QUAD4 grids N x N of `tools/ssnv511_mesh` (N = 100: the file's grid). Errors
against the file's references K1 = sigma sqrt(pi A/2) f cos^2(alpha), K2 = sigma sqrt(pi A/2) f
cos(alpha) sin(alpha), f = 1 + 0.128 (A/W) - 0.288 (A/W)^2 + 1.525 (A/W)^3. CALC_G: OPTION='CALC_K_G',
R_INF = 0.1 A, R_SUP = 0.3 A (the file's first crown). POST_K1_K2_K3: NB_NOEUD_COUPE=4, ABSC_CURV_MAXI
by default (5 x TAILLE_R; the crack is A/2 = {A / 2:g} from its centre to a tip) and fixed at 0.01.
The file's tolerances for POST_K1_K2_K3 K1: 3 % (tip 1), 2 % (tip 2).

{table(rows)}
"""
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "ssnp138a_refinement.md")
    with open(path, "w") as f:
        f.write(text)
    print(f"table: {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
