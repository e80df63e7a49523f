#!/usr/bin/python3
"""Stress intensity factors of X-FEM cracks against closed forms, versus mesh size (issue 26).

A plate -1 <= x <= 1, -2 <= y <= 2 (QUAD4 from `tools/ssnv511_mesh`, N cells across, 2N up),
plane strain, a uniform traction sigma on its top and bottom edges, a centre crack of half-length
a = 0.25 at angle beta (FORM_FISS='SEGMENT', TYPE_ENRI_FOND='GEOMETRIQUE', NB_COUCHES=5 as ssnp138a)
whose centre is moved by (ox, oy) cell sizes so that the tips fall anywhere in a cell. CALC_G
OPTION='CALC_K_G' (default crown 2h-4h, then R_INF/R_SUP = 0.05/0.15 fixed) and POST_K1_K2_K3 at both tips.

Closed forms (Tada, Paris, Irwin, The Stress Analysis of Cracks Handbook, 3rd ed., p. 2.2: centre
crack in a strip of half-width b, Feddersen's secant form with Tada's polynomial, 0.1 % for any
lambda = a/b): K1 = sigma sqrt(pi a) F(lambda), F = (1 - 0.025 lambda^2 + 0.06 lambda^4)
sqrt(sec(pi lambda / 2)) = 1.0367 at lambda = 0.25; inclined (the same F as an approximation): K1 = sigma sqrt(pi a) F cos^2 beta, K2 = sigma sqrt(pi a) F sin beta cos beta.
The plate's height 4b keeps the height effect below the handbook formula's accuracy.

  ./miniaster study cracks --out docs/study
  /usr/bin/python3 tools/study/cracks.py [--build build] [--sizes 40,80,160,320] [--out docs/study]
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
A, SIGMA, E, NU = 0.25, 1.0e6, 2.0e11, 0.3

COMM = """DEBUT()
MA = LIRE_MAILLAGE(FORMAT='MED')
eps = {eps}
MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=(
    _F(NOM='NA', OPTION='ENV_SPHERE', POINT=(-1., 0.), PRECISION=eps, RAYON=eps),
    _F(NOM='NB', OPTION='ENV_SPHERE', POINT=(1., 0.), PRECISION=eps, RAYON=eps),
    _F(NOM='NC', OPTION='ENV_SPHERE', POINT=(0., -2.), PRECISION=eps, RAYON=eps),
    _F(NOM='ND', OPTION='ENV_SPHERE', POINT=(0., 2.), PRECISION=eps, RAYON=eps)))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=('SURF', 'LB', 'LH'), PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
FISS = DEFI_FISS_XFEM(MAILLAGE=MA, DEFI_FISS=_F(FORM_FISS='SEGMENT', PFON_ORIG=({x1}, {y1}, 0.),
                      PFON_EXTR=({x2}, {y2}, 0.)), TYPE_ENRI_FOND='GEOMETRIQUE', NB_COUCHES=5)
MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=FISS)
ACIER = DEFI_MATERIAU(ELAS=_F(E={E}, NU={NU}))
CM = AFFE_MATERIAU(MAILLAGE=MA, MODELE=MX, AFFE=_F(TOUT='OUI', MATER=ACIER))
CH = AFFE_CHAR_MECA(MODELE=MX, DDL_IMPO=(_F(GROUP_NO=('NA', 'NB'), DY=0.), _F(GROUP_NO=('NC', 'ND'), DX=0.)),
                    PRES_REP=_F(GROUP_MA=('LB', 'LH'), PRES={pres}))
RE = MECA_STATIQUE(MODELE=MX, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH))
for fond in (1, 2):
    T = CALC_G(RESULTAT=RE, OPTION='CALC_K_G', THETA=_F(FISSURE=FISS, NUME_FOND=fond))
    IMPR_TABLE(TABLE=T)
    T = CALC_G(RESULTAT=RE, OPTION='CALC_K_G', THETA=_F(FISSURE=FISS, NUME_FOND=fond, R_INF=0.05, R_SUP=0.15))
    IMPR_TABLE(TABLE=T)
    P = POST_K1_K2_K3(FISSURE=FISS, NUME_FOND=fond, RESULTAT=RE)
    IMPR_TABLE(TABLE=P)
FIN()
"""


def closed_form(beta):
    lam = A / 1.0
    f = (1 - 0.025 * lam ** 2 + 0.06 * lam ** 4) * math.sqrt(1 / math.cos(math.pi * lam / 2))
    k = SIGMA * math.sqrt(math.pi * A) * f
    return k * math.cos(beta) ** 2, k * math.sin(beta) * math.cos(beta)


def tables(resu):
    """The IMPR_TABLE blocks of the .resu, in order: dicts column -> first-row value."""
    out = []
    lines = resu.splitlines()
    for i, line in enumerate(lines[:-1]):
        names = [] if line.startswith("#-") else line.lstrip("#").split()  # a titled table: header without #
        if names[:1] in (["NUME_FOND"], ["INST"]):
            out.append(dict(zip(names, (float(v) for v in lines[i + 1].split()))))
    return out


def run(build, n, beta, offset, work):
    mesh = os.path.join(work, f"plate_n{n}_{offset[0]}_{offset[1]}.med")
    if not os.path.exists(mesh):
        subprocess.run([os.path.join(build, "tools", "ssnv511_mesh"), "--type", "quad4", "--n", str(n), "--bounds",
                        "-1", "1", "-2", "2", "-o", mesh], check=True, stdout=subprocess.DEVNULL)
    h = 2.0 / n
    cx, cy = offset[0] * h, offset[1] * h
    c, s = A * math.cos(beta), A * math.sin(beta)
    tag = f"n{n}_b{round(math.degrees(beta))}_o{offset[0]}_{offset[1]}"
    comm = os.path.join(work, tag + ".comm")
    with open(comm, "w") as f:
        f.write(COMM.format(eps=h / 4, x1=cx - c, y1=cy - s, x2=cx + c, y2=cy + s, E=E, NU=NU, pres=-SIGMA))
    out = os.path.join(work, tag)
    p = subprocess.run([os.path.join(build, "miniaster"), "run", comm, "--mesh", mesh, "--out-dir", out],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        sys.exit(f"{tag} failed (exit {p.returncode}):\n{p.stdout[-3000:]}")
    t = tables(open(os.path.join(out, tag + ".resu")).read())
    k1, k2 = closed_form(beta)
    row = {"N": n, "beta": round(math.degrees(beta)), "offset": offset, "K1": k1, "K2": k2}
    for i, name in enumerate(("default", "fixed", "post")):
        for fond in (0, 1):
            tab = t[3 * fond + i]
            row[f"{name}{fond + 1}"] = (tab["K1"], tab["K2"], tab["G"])
    return row


def err(value, ref, scale):
    return (value - ref) / scale


def table(rows):
    lines = ["| beta | N | h/a | offset (cells) | method | K1 tip 1 | K1 tip 2 | err K1 | K2 tip 1 | err K2 | G / G_ref - 1 |",
             "|" + "---|" * 11]
    for r in rows:
        g_ref = (r["K1"] ** 2 + r["K2"] ** 2) * (1 - NU ** 2) / E
        for name, label in (("default", "CALC_G, default crown"), ("fixed", "CALC_G, R 0.05-0.15"),
                            ("post", "POST_K1_K2_K3")):
            a, b = r[name + "1"], r[name + "2"]
            e1 = max(abs(err(a[0], r["K1"], r["K1"])), abs(err(b[0], r["K1"], r["K1"])))
            e2 = max(abs(err(a[1], r["K2"], r["K1"])), abs(err(b[1], r["K2"], r["K1"])))
            eg = max(abs(a[2] / g_ref - 1), abs(b[2] / g_ref - 1))
            lines.append(f"| {r['beta']} | {r['N']} | {2.0 / r['N'] / A:.3f} | {r['offset']} | {label} | {a[0]:.5e} | "
                         f"{b[0]:.5e} | {e1:.2%} | {a[1]:.4e} | {e2:.2%} | {eg:.2%} |")
    return "\n".join(lines)


# The penny-shaped crack (docs/cracks.md): the astest case's command file without its checks,
# on quarter blocks of tools/penny_mail.py.
PENNY_A, PENNY_SIGMA, PENNY_E, PENNY_NU = 1.0, 1.0, 2.0e5, 0.3


def penny_comm():
    text = open(os.path.join(ROOT, "astest", "xfem_penny_hexa8.comm")).read()
    return text.split("BEHIND = ")[0] + "FIN()\n"


def penny_run(build, kind, h, block, work):
    sys.path.insert(0, os.path.join(ROOT, "tools"))
    import penny_mail
    tag = f"penny_{kind}_h{round(PENNY_A / h)}_L{block:g}"
    mesh, comm = os.path.join(work, tag + ".mail"), os.path.join(work, tag + ".comm")  # the .export names both
    with open(mesh, "w") as f:
        f.write(penny_mail.penny_quarter(kind.upper(), PENNY_A, h, block, 1.3))
    with open(comm, "w") as f:
        f.write(penny_comm())
    export = os.path.join(work, tag + ".export")
    with open(export, "w") as f:
        f.write(f"P time_limit 3600\nP memory_limit 8000\nP ncpus 1\n\nF comm {tag}.comm D 1\nF mail {tag}.mail D 20\n")
    out = os.path.join(work, tag)
    p = subprocess.run(["nice", os.path.join(build, "miniaster"), "run", export, "--out-dir", out],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        sys.exit(f"{tag} failed (exit {p.returncode}):\n{p.stdout[-3000:]}")
    lines = open(os.path.join(out, tag + ".resu")).read().splitlines()
    head = next(i for i, line in enumerate(lines) if "RATIO" in line and "COOR_X" in line)
    rows = []
    for line in lines[head + 1:]:
        v = line.split()
        if len(v) != 6:
            break
        rows.append([float(x) for x in v])
    mess = open(os.path.join(out, tag + ".mess")).read()
    peak = max(float(m) for m in re.findall(r"peak memory ([0-9.]+) MB", mess))
    tips = re.search(r"(\d+) crack-tip elements", mess).group(1)
    wall = re.search(r"MECA_STATIQUE +line +\d+ +([0-9.]+) s", p.stdout)
    worst = lambda rmax: max(abs(r[5] - 1) for r in rows if r[3] <= rmax * PENNY_A)
    centre = [r[5] for r in rows if r[3] < 1e-9]
    return {"kind": kind.upper(), "h": h, "L": block, "tips": tips, "peak": peak,
            "wall": float(wall.group(1)) if wall else float("nan"), "centre": sum(centre) / len(centre) - 1,
            "r05": worst(0.5), "r08": worst(0.8), "r09": worst(0.9)}


def penny_table(rows):
    lines = ["| cells | h/a | L/a | tip elements | COD at the centre | max over r <= 0.5a | r <= 0.8a | r <= 0.9a | "
             "MECA_STATIQUE (s) | peak memory (MB) |", "|" + "---|" * 10]
    for r in rows:
        lines.append(f"| {r['kind']} | 1/{round(1 / r['h'])} | {r['L']:g} | {r['tips']} | {r['centre']:+.2%} | "
                     f"{r['r05']:.2%} | {r['r08']:.2%} | {r['r09']:.2%} | {r['wall']:.1f} | {r['peak']:.0f} |")
    return "\n".join(lines)


def penny_study(build, out):
    runs = [("hexa8", 1 / 4, 4.0), ("hexa8", 1 / 6, 4.0), ("hexa8", 1 / 8, 4.0), ("hexa8", 1 / 6, 8.0),
            ("tetra4", 1 / 4, 4.0), ("tetra4", 1 / 6, 4.0)]
    rows = []
    with tempfile.TemporaryDirectory(prefix="penny-") as work:
        for kind, h, block in runs:
            rows.append(penny_run(build, kind, h, block, work))
            print(f"penny {kind} h = a/{round(1 / h)} L = {block:g}a: centre {rows[-1]['centre']:+.3%}", flush=True)
    text = f"""# Penny-shaped crack: the opening against Sneddon's closed form

Generated by `./miniaster study cracks --out docs/study` (tools/study/cracks.py, `--part penny`). The
command file of astest/xfem_penny_hexa8.comm without its checks, on quarter blocks of
tools/penny_mail.py (a = 1, cells of size h up to 1.5a in x, y and a/2 in |z|, then growing by 1.3;
block 0 <= x, y <= L, |z| <= L), E = 2e5, nu = 0.3, sigma = 1, TYPE_ENRI_FOND='GEOMETRIQUE'. The
lips' half opening |DZ| at the nodes of the crack (POST_CHAM_XFEM) over Sneddon's
4(1 - nu^2) sigma sqrt(a^2 - r^2) / (pi E) for an infinite body, minus 1: at the centre and the
largest deviation over the nodes within r of the centre. Peak memory: the largest resident size
the .mess reports.

{penny_table(rows)}
"""
    with open(os.path.join(out, "cracks_penny.md"), "w") as f:
        f.write(text)
    print(f"table: {os.path.join(out, 'cracks_penny.md')}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--sizes", default="40,80,160,320")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "study"))
    ap.add_argument("--part", choices=["plate", "penny", "all"], default="all")
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    if args.part in ("penny", "all"):
        penny_study(args.build, args.out)
    if args.part == "penny":
        return 0
    sizes = [int(s) for s in args.sizes.split(",")]
    rows = []
    with tempfile.TemporaryDirectory(prefix="cracks-") as work:
        for n in sizes:  # Griffith, the tips inside cells
            rows.append(run(args.build, n, 0.0, (0.37, 0.29), work))
        for beta in (30, 45):  # inclined
            rows.append(run(args.build, sizes[-1], math.radians(beta), (0.37, 0.29), work))
        # (0, 0) puts the crack's middle on a node: docs/cracks.md, "Closed forms"
        for offset in ((0.5, 0.5), (0.11, 0.83), (0.93, 0.07)):  # mesh independence
            rows.append(run(args.build, sizes[-2], 0.0, offset, work))
        for r in rows:
            print(f"beta {r['beta']} N {r['N']} offset {r['offset']}: K1 {r['default1'][0]:.5e} "
                  f"(closed form {r['K1']:.5e})", flush=True)
    os.makedirs(args.out, exist_ok=True)
    text = f"""# Cracks: K and G against closed forms

Generated by `./miniaster study cracks --out docs/study` (tools/study/cracks.py). {__doc__.split(chr(10), 2)[2].split("  ./miniaster")[0]}
Errors are relative to the closed-form K1 (K2's too, so that K2 = 0 is measured on the same scale);
G is compared with (K1² + K2²)(1 − ν²)/E of the closed forms.

{table(rows)}
"""
    path = os.path.join(args.out, "cracks.md")
    with open(path, "w") as f:
        f.write(text)
    print(f"table: {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
