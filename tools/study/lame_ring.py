#!/usr/bin/python3
"""Refinement study of Lame's thick cylinder cut by a circular X-FEM interface in contact.

astest/lame_ring_contact.comm (a quarter ring 1 <= r <= 2, plane strain, inner pressure, the
interface r = 1.4567 closed in frictionless contact, STANDARD) on QUAD4 and TRIA3 meshes from
`tools/ssnv511_mesh --polar` with N divisions in r and in theta, astest/lame_cylinder_contact_3d.comm
(the same as one HEXA8 layer, DZ = 0, a cylindrical interface), and the same ring without the
interface (its INTERFACE parameter): POST_ERREUR's relative L2 and energy errors against Lame's
closed form, the observed rates between successive meshes and over the whole grid, the contact
iterations and active points.

  ./miniaster study lame --out docs/study
  /usr/bin/python3 tools/study/lame_ring.py [--build build] [--sizes 8,16,32,64,128] [--out docs/study]
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
COMM = {"quad4": os.path.join(ROOT, "astest", "lame_ring_contact.comm"),
        "tria3": os.path.join(ROOT, "astest", "lame_ring_contact.comm"),
        "hexa8": os.path.join(ROOT, "astest", "lame_cylinder_contact_3d.comm")}
ELEMENTS = ("quad4", "tria3", "hexa8")


def run(build, element, n, interface, work):
    mesh = os.path.join(work, f"{element}_n{n}.med")
    if not os.path.exists(mesh):
        layer = ["--zbounds", "0", "0.1"] if element == "hexa8" else []
        subprocess.run([os.path.join(build, "tools", "ssnv511_mesh"), "--type", element, "--n", str(n), "--bounds",
                        "1", "2", "0", "90", "--polar", "-o", mesh] + layer, check=True, stdout=subprocess.DEVNULL)
    tag = f"{element}_n{n}_{'contact' if interface else 'plain'}"
    comm = os.path.join(work, tag + ".comm")
    text = open(COMM[element]).read()
    text = re.sub(r"^INTERFACE = \w+", f"INTERFACE = {interface}", text, flags=re.M)
    text = text[:text.index("# ---- checks")] + "FIN()\n"  # the bounds are those of N = 16 only
    with open(comm, "w") as f:
        f.write(text)
    out = os.path.join(work, tag)
    p = subprocess.run([os.path.join(build, "miniaster"), "run", comm, "--mesh", mesh, "--out-dir", out],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        sys.exit(f"{tag} failed (exit {p.returncode}):\n{p.stdout[-3000:]}")
    resu = open(os.path.join(out, tag + ".resu")).read()
    mess = open(os.path.join(out, tag + ".mess")).read()
    errors = [float(m.group(1)) for m in re.finditer(r"^TOTAL\s+\S+\s+\S+\s+(\S+)", resu, re.M)]
    dofs = int(re.search(r"(\d+) dofs \(components", mess).group(1))
    contact = re.search(r"increment 1 \(INST 1\): (\d+) contact iteration\(s\), (\d+) active contact points of (\d+)",
                        mess)
    row = {"element": element, "N": n, "interface": interface, "dofs": dofs, "l2": errors[0], "energy": errors[1]}
    if contact:
        row.update(iterations=int(contact.group(1)), active=int(contact.group(2)), points=int(contact.group(3)))
    return row


def rate(a, b, key):
    return math.log(a[key] / b[key]) / math.log(b["N"] / a["N"])


def table(rows):
    lines = ["| element | N | dofs | L2 (contact) | rate | energy (contact) | rate | L2 (no interface) | "
             "energy (no interface) | contact iterations | active / points |", "|" + "---|" * 11]
    for element in ELEMENTS:
        contact = [r for r in rows if r["element"] == element and r["interface"]]
        plain = {r["N"]: r for r in rows if r["element"] == element and not r["interface"]}
        for i, r in enumerate(contact):
            rl = f"{rate(contact[i - 1], r, 'l2'):.2f}" if i else ""
            re_ = f"{rate(contact[i - 1], r, 'energy'):.2f}" if i else ""
            p = plain[r["N"]]
            lines.append(f"| {element.upper()} | {r['N']} | {r['dofs']} | {r['l2']:.3e} | {rl} | {r['energy']:.3e} | "
                         f"{re_} | {p['l2']:.3e} | {p['energy']:.3e} | {r['iterations']} | "
                         f"{r['active']} / {r['points']} |")
    return "\n".join(lines)


def overall(rows):
    text = []
    for element in ELEMENTS:
        contact = [r for r in rows if r["element"] == element and r["interface"]]
        text.append(f"{element.upper()} N = {contact[0]['N']} → {contact[-1]['N']}: L2 rate "
                    f"{rate(contact[0], contact[-1], 'l2'):.2f}, energy rate {rate(contact[0], contact[-1], 'energy'):.2f}")
    return "; ".join(text)


def ratios(rows):
    plain = {(r["element"], r["N"]): r["energy"] for r in rows if not r["interface"]}
    parts = []
    for element in ELEMENTS:
        q = [r["energy"] / plain[(element, r["N"])] for r in rows if r["element"] == element and r["interface"]]
        parts.append(f"{element.upper()} {min(q):.3f} … {max(q):.3f}")
    return ", ".join(parts)


def released(rows):
    open_ = [f"{r['element'].upper()} N = {r['N']}: {r['points'] - r['active']} of {r['points']}" for r in rows
             if r["interface"] and r["active"] < r["points"]]
    if not open_:
        return "Every contact point ends active, as the exact contact is closed everywhere (σrr(1.4567) = −0.295 MPa)."
    return ("The exact contact is closed everywhere (σrr(1.4567) = −0.295 MPa); points ending open (Nitsche's discrete "
            "active set, P(u) = σn + γ g ≥ 0 there): " + "; ".join(open_) + ".")


def plot(rows, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return False
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    for element, marker in zip(ELEMENTS, ("o", "s", "^")):
        for interface, style in ((True, "-"), (False, ":")):
            pts = [r for r in rows if r["element"] == element and r["interface"] == interface]
            label = f"{element.upper()} {'contact' if interface else 'no interface'}"
            ax.loglog([1.0 / r["N"] for r in pts], [r["energy"] for r in pts], style, marker=marker,
                      label=label + ", energy")
            ax.loglog([1.0 / r["N"] for r in pts], [r["l2"] for r in pts], style, marker=marker, mfc="none",
                      label=label + ", L2")
    ax.set_xlabel("1 / N (N divisions in r and theta)")
    ax.set_ylabel("relative error")
    ax.set_title("Lamé ring, circular / cylindrical interface in contact")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    return True


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--sizes", default="8,16,32,64,128")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "study"))
    args = ap.parse_args(argv)
    sizes = [int(s) for s in args.sizes.split(",")]
    rows = []
    with tempfile.TemporaryDirectory(prefix="lame-ring-") as work:
        for element in ELEMENTS:
            for n in sizes:
                for interface in (True, False):
                    r = run(args.build, element, n, interface, work)
                    rows.append(r)
                    print(f"{element} N = {n:4d} {'contact' if interface else 'plain  '}: L2 {r['l2']:.3e}, "
                          f"energy {r['energy']:.3e}", flush=True)
    os.makedirs(args.out, exist_ok=True)
    figure = plot(rows, os.path.join(args.out, "lame_ring.png"))
    text = f"""# Lamé ring with a circular interface in contact: refinement study

Generated by `./miniaster study lame --out docs/study` (tools/study/lame_ring.py): astest/lame_ring_contact.comm
on QUAD4 and TRIA3 meshes of the quarter ring 1 ≤ r ≤ 2 from `tools/ssnv511_mesh --polar` (N divisions in
r and in θ) and astest/lame_cylinder_contact_3d.comm on one layer of HEXA8 of the same ring (DZ = 0: plane
strain; the interface is a cylinder and its facets quadrilaterals cut in the cells), the X-FEM interface
r = 1.4567 closed in frictionless contact (STANDARD), and the same ring without the interface. Errors are POST_ERREUR's relative ones against Lamé's closed form (the energy error
is the square root of the energy of the difference over the energy of the solution); the rates are the
observed orders between successive meshes.

{table(rows)}

Over the whole grid: {overall(rows)}. Linear elements converge at order 1 in energy and 2 in L2, and the
interface in contact keeps both orders: its energy error over the ring's without the interface is
{ratios(rows)} (the interface is cut through the cells, its facets are the chords of the level set's zero
in each cell, and the rollers hold both lips of the enriched nodes, H1X/H1Y/H1Z = 0 as code_aster's
ssnv511e writes them). {released(rows)}
{"" if not figure else chr(10) + "![errors](lame_ring.png)" + chr(10)}"""
    path = os.path.join(args.out, "lame_ring.md")
    with open(path, "w") as f:
        f.write(text)
    print(f"table: {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
