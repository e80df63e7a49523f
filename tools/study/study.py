#!/usr/bin/python3
"""miniaster speed/accuracy study (issue 8). Run through the launcher:

    ./miniaster study smooth      [--full]   convergence of the smooth manufactured scene, sub-cell quadrature
                                             rules (--group quadrature: `miniaster run --subcell-quadrature`)
    ./miniaster study stability   [--full]   extreme inputs on the ssnv511a rigid scene
    ./miniaster study penalty     [--full]   exact contact vs penalty (COEF_PENA_CONT 1e4..1e24), ssnv511e-h (2D and 3D)
    ./miniaster study perf        [--full]   set-up/assembly vs factorisation on ssnv511a (N=1001 with --full),
                                             also code_aster's ssnv511a.comm read in place on the largest mesh
    ./miniaster study all         [--full]   the three above
    ./miniaster study check-field            checks of the manufactured field (derivatives, tractions)
    ./miniaster study astest                 regenerates astest/smooth_*.{comm,export,mmed}
    ./miniaster study cracks                 K1, K2, G of X-FEM cracks against closed forms versus mesh size
    ./miniaster study ssnv513e               ssnv513e (the family file, unmodified) refined N = 5 ... 81 (docs/family.md)
    ./miniaster study ssnp138a               ssnp138a's inclined cracks (its problem) refined N = 100 ... 400 (docs/cracks.md)

Options: --out DIR (tables and plots, default a fresh folder miniaster-study-<name>-<time> here;
--out docs/study updates the committed figures; astest reads docs/study by default), --work DIR (runs, default a temporary
folder), --build DIR (miniaster build, default build/), --elements quad4,tria3,..., --contact
all|open|only, --group all|convergence|quadrature (smooth), --settings/--scenes (solvers: a subset),
--timeout S.
Results: DIR/<study>.csv, DIR/<study>.md and DIR/<study>_*.png; the Markdown file names the
command that made it. See docs/study.md.
"""
import argparse
import datetime
import math
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)

import report  # noqa: E402
import runner  # noqa: E402
import scenes  # noqa: E402
import smooth_field  # noqa: E402

ALL_ELEMENTS = ["quad4", "tria3", "hexa8", "tetra4"]


class Context:
    def __init__(self, args):
        self.args = args
        self.build = os.path.abspath(args.build)
        self.binary = os.path.join(self.build, "miniaster")
        self.out = os.path.abspath(args.out)
        self.work = os.path.abspath(args.work) if args.work else tempfile.mkdtemp(prefix="miniaster-study-")
        self.keep = bool(args.work)
        self.elements = args.elements.split(",") if args.elements else ALL_ELEMENTS
        os.makedirs(self.out, exist_ok=True)
        os.makedirs(self.work, exist_ok=True)
        shown, skip = [], False
        for a in sys.argv[1:]:  # the command line without the private folders
            if skip:
                skip = False
            elif a in ("--work", "--build", "--out"):
                skip = True
            elif not a.startswith(("--work=", "--build=", "--out=")):
                shown.append(a)
        self.command = "./miniaster study " + " ".join(shown)

    def run(self, tag, comm, mesh, options=()):
        return runner.run_case(self.binary, comm, mesh, os.path.join(self.work, tag), "case", self.args.timeout,
                               options)

    def mesh(self, element, n, **kw):
        key = f"{element}_n{n}_" + "_".join(f"{k}{v}" for k, v in sorted(kw.items()))
        path = os.path.join(self.work, "meshes", key.replace(" ", "").replace(",", "_") + ".med")
        if not os.path.exists(path):
            os.makedirs(os.path.dirname(path), exist_ok=True)
            runner.make_mesh(self.build, element, n, path, **kw)
        return path

    def header(self, title):
        load = os.getloadavg()
        return (f"# {title}\n\nMade by `{self.command}` on {datetime.date.today().isoformat()} "
                f"(git {git_head()}, {platform.node()}, {os.cpu_count()} cores, load average at the end "
                f"{load[0]:.1f}). Times are wall-clock seconds of a shared machine: compare orders of magnitude, "
                f"not percents.\n\n")

    def finish(self):
        if not self.keep:
            shutil.rmtree(self.work, ignore_errors=True)


def git_head():
    try:
        return subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def write_text(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def log(*a):
    print(*a, flush=True)


# ----------------------------------------------------------------------------------------------
# smooth: convergence, solvers, trade curves, with and without contact at the junction

SMOOTH_COLUMNS = ["element", "modelisation", "contact", "N", "h", "solver", "ordering", "dofs", "equations",
                  "nonzeros", "t_mesh", "t_xfem", "t_setup", "t_numbering", "t_pattern", "t_assembly",
                  "t_factorisation", "t_solve", "t_analysis_other", "t_analysis", "t_post", "t_commands", "wall",
                  "peak_mb", "solver_peak_mb", "factor_entries", "newton", "contact_iterations", "factorisations",
                  "penetration", "residual", "l2_rel", "energy_rel", "l2_ref", "l2_ref_exact", "energy_ref",
                  "energy_ref_exact", "min_fraction", "group", "quadrature", "subcell_points", "xfem_volume_cells", "skin_points",
                  "all_points", "alarms",
                  "diagnostic", "exit", "failure", "command", "git"]
# COEF_PENA_CONT of the penalised rows (QUAD4): with E = 1e8 and normal tractions 2e5..5e5 Pa the
# interpenetration p/kappa is 5e-5 and 5e-7 (the displacements are ~0.03)
SMOOTH_PENALTIES = [1e10, 1e12]
SMOOTH_PARTS = {"all": ("open", "contact"), "open": ("open",), "only": ("contact",)}
# groups of rows of smooth.csv (--group): the convergence grid with the solver rows, and the sub-cell
# quadrature rows (`miniaster run --subcell-quadrature DEGREE`)
SMOOTH_GROUPS = {"all": ("convergence", "quadrature"), "convergence": ("convergence",),
                 "quadrature": ("quadrature",)}


def smooth_grid(full):
    n2 = [5, 11, 21, 41, 81, 161] + ([321, 641, 1001] if full else [])
    n3 = [5, 11, 21, 41] + ([81, 161, 321] if full else [])
    solver_points = [("quad4", 321), ("hexa8", 161)] if full else [("quad4", 161), ("hexa8", 41)]
    solvers = ["MUMPS:AMD", "MUMPS:AMF", "MUMPS:PORD", "MUMPS:SCOTCH", "MUMPS:QAMD", "MULT_FRONT", "LDLT"]
    return n2, n3, solver_points, solvers


def quadrature_grid(full):
    """Sub-cell rules (None = the catalogue) and meshes of the quadrature group: 2D, 3D."""
    rules = [1, 2, 3, None] + ([4, 6] if full else [])
    n2 = [11, 21, 41, 81, 161] + ([321, 641] if full else [])
    n3 = [5, 11, 21, 41] + ([81] if full else [])
    return rules, n2, n3


# volume cells per N^2 of the generated meshes (tools/ssnv511_mesh; 3D: one layer) and points of the
# classical rule of each (fe/Quadrature.hpp stiffnessRule)
VOLUME_CELLS = {"quad4": (1, 4), "tria3": (2, 1), "hexa8": (1, 8), "tetra4": (6, 1)}


def all_points(rec):
    """Integration points of the whole model: classical cells on their rule plus the volume sub-cells."""
    if rec.get("subcell_points") is None or rec.get("xfem_volume_cells") is None:
        return None
    per_n2, points = VOLUME_CELLS[rec["element"]]
    return (per_n2 * rec["N"] ** 2 - rec["xfem_volume_cells"]) * points + rec["subcell_points"]


def quadrature_label(degree):
    """Label of a sub-cell rule as MODI_MODELE_XFEM logs it."""
    return "catalogue" if degree is None else f"degree {degree}"


def quadrature_rank(label):
    return (1, 0) if label == "catalogue" else (0, int(label.split()[-1]))


def smooth_contacts(element, parts):
    """Contact settings of the grid: open interfaces, exact contact (STANDARD); QUAD4 also the penalty."""
    out = [None] if "open" in parts else []
    if "contact" in parts:
        out.append("STANDARD")
        if element == "quad4":
            out += [("PENALISATION", k) for k in SMOOTH_PENALTIES]
    return out


def contact_rank(label):
    """Table order of the contact labels: open, STANDARD, PENALISATION by coefficient."""
    if label == "open":
        return (0, 0.0)
    if label == "STANDARD":
        return (1, 0.0)
    return (2, float(label.split()[-1]))


def smooth_case(ctx, element, n, solver="MUMPS", contact=None, group="convergence", degree=None):
    """One run of the smooth scene; `degree`: --subcell-quadrature (None: the catalogue's rules)."""
    modelisation, dim = scenes.ELEMENTS[element]
    h = 10.0 / n
    thickness = h if dim == 3 else 1.0
    mesh = ctx.mesh(element, n, zbounds=(0.0, h)) if dim == 3 else ctx.mesh(element, n)
    comm = scenes.smooth_comm(element, solver=solver, contact=contact) + "FIN()\n"
    label = scenes.contact_label(contact)
    options = ("--subcell-quadrature", str(degree)) if degree else ()
    tag = f"smooth_{element}_{n}_{solver.replace(':', '_')}_{label.replace(' ', '_')}_{group}_{degree or 'cat'}"
    rec = ctx.run(tag, comm, mesh, options)
    l2, energy, _, _ = smooth_field.exact_norms(modelisation, thickness=thickness, contact=contact is not None)
    logged = rec.get("quadrature")
    if logged is not None and logged != quadrature_label(degree):
        sys.exit(f"study: {tag}: MODI_MODELE_XFEM logged the sub-cell rule '{logged}', asked "
                 f"'{quadrature_label(degree)}'")
    rec.update(element=element, modelisation=modelisation, contact=label, N=n, h=h, solver=solver, l2_ref_exact=l2,
               energy_ref_exact=energy, group=group, quadrature=quadrature_label(degree), command=ctx.command,
               git=git_head())
    rec["all_points"] = all_points(rec)
    return rec


def read_records(path, default_command=""):
    """Rows of a study CSV with numbers converted back (empty cells dropped); rows written before the
    contact dimension existed are the open scene."""
    import csv
    out = []
    with open(path) as f:
        for row in csv.DictReader(f):
            r = {}
            for k, v in row.items():
                if v is None or v == "":
                    continue
                try:
                    r[k] = int(v)
                except ValueError:
                    try:
                        r[k] = float(v)
                    except ValueError:
                        r[k] = v
            r.setdefault("contact", "open")
            r.setdefault("command", default_command)
            r.setdefault("group", "convergence")
            r.setdefault("quadrature", "catalogue")
            out.append(r)
    return out


def previous_smooth_rows(ctx, parts, groups):
    """Rows of the existing smooth.csv that this run does not redo (partial runs: --contact, --elements,
    --group)."""
    path = os.path.join(ctx.out, "smooth.csv")
    if not os.path.exists(path):
        return []
    made_by = ""
    md = os.path.join(ctx.out, "smooth.md")
    if os.path.exists(md):
        with open(md) as f:
            m = re.search(r"Made by `([^`]*)`", f.read())
            made_by = m.group(1) if m else ""
    redone = lambda r: (r["group"] in groups and r["element"] in ctx.elements
                        and ("open" if r["contact"] == "open" else "contact") in parts)
    return [r for r in read_records(path, made_by) if not redone(r)]


def smooth_rates(base, groups):
    """Least-squares rates in h on the four finest meshes per (element, contact) group."""
    rates = []
    for element, contact in groups:
        rows = [r for r in base if r["element"] == element and r["contact"] == contact]
        pts = sorted((r for r in rows if r.get("l2_rel")), key=lambda r: -r["h"])
        tail = pts[-4:]
        tr = sorted((r for r in rows if r.get("t_commands") and r.get("dofs")), key=lambda r: r["dofs"])
        big = [r for r in tr if r["dofs"] >= 2e4]
        if len(big) < 3:
            big = tr[-3:]
        rates.append({
            "element": element, "modelisation": scenes.ELEMENTS[element][0], "contact": contact,
            "points": f"N = {tail[0]['N']}..{tail[-1]['N']}" if tail else "",
            "energy_rate": report.fit_rate([r["h"] for r in tail], [r["energy_rel"] for r in tail]),
            "l2_rate": report.fit_rate([r["h"] for r in tail], [r["l2_rel"] for r in tail]),
            "time_exponent": report.fit_rate([r["dofs"] for r in big], [r["t_commands"] for r in big]),
            "fact_exponent": report.fit_rate([r["dofs"] for r in big], [r.get("t_factorisation") for r in big]),
            "energy_finest": tail[-1]["energy_rel"] if tail else None,
            "l2_finest": tail[-1]["l2_rel"] if tail else None,
            "contact_iterations": max((r["contact_iterations"] for r in rows if "contact_iterations" in r), default=None),
            "newton": max((r["newton"] for r in rows if "newton" in r), default=None),
        })
    return rates


def study_smooth(ctx):
    n2, n3, solver_points, solvers = smooth_grid(ctx.args.full)
    parts = SMOOTH_PARTS[ctx.args.contact]
    groups_run = SMOOTH_GROUPS[ctx.args.group]
    partial = ctx.args.contact != "all" or ctx.args.elements or ctx.args.group != "all"
    kept = previous_smooth_rows(ctx, parts, groups_run) if partial else []
    records = []
    csv_path = os.path.join(ctx.out, "smooth.csv")
    for element in ctx.elements if "convergence" in groups_run else []:
        ns = n2 if scenes.ELEMENTS[element][1] == 2 else n3
        for contact in smooth_contacts(element, parts):
            for n in ns:
                rec = smooth_case(ctx, element, n, contact=contact)
                records.append(rec)
                report.write_csv(csv_path, kept + records, SMOOTH_COLUMNS)  # progress
                log(f"smooth {element} {rec['contact']} N={n}: {rec.get('dofs')} dofs, "
                    f"L2 {rec.get('l2_rel', float('nan')):.3e}, energy {rec.get('energy_rel', float('nan')):.3e}, "
                    f"contact it. {rec.get('contact_iterations')}, Newton {rec.get('newton')}, {rec['wall']:.1f} s, "
                    f"{rec.get('diagnostic')} {rec.get('failure', '')}")
    if "quadrature" in groups_run:
        rules, q2, q3 = quadrature_grid(ctx.args.full)
        for element in ctx.elements:
            ns = q2 if scenes.ELEMENTS[element][1] == 2 else q3
            for contact in [c for c in (None, "STANDARD") if ("open" if c is None else "contact") in parts]:
                for n in ns:
                    for degree in rules:  # the rules of one mesh back to back: comparable machine load
                        rec = smooth_case(ctx, element, n, contact=contact, group="quadrature", degree=degree)
                        records.append(rec)
                        report.write_csv(csv_path, kept + records, SMOOTH_COLUMNS)  # progress
                        log(f"smooth quadrature {element} {rec['contact']} N={n} {rec['quadrature']}: "
                            f"{rec.get('subcell_points')} sub-cell points, assembly {rec.get('t_assembly')} s, "
                            f"L2 {rec.get('l2_rel', float('nan')):.3e}, "
                            f"energy {rec.get('energy_rel', float('nan')):.3e}, {rec.get('diagnostic')} "
                            f"{rec.get('failure', '')}")
    if "open" in parts and "convergence" in groups_run:
        for element, n in solver_points:
            if element not in ctx.elements:
                continue
            for solver in solvers:
                rec = smooth_case(ctx, element, n, solver)
                records.append(rec)
                log(f"smooth {element} N={n} {solver}: factorisation {rec.get('t_factorisation')} s, "
                    f"energy {rec.get('energy_rel', float('nan')):.3e}, {rec.get('diagnostic')}")
    records = kept + records
    order = {e: i for i, e in enumerate(ALL_ELEMENTS)}
    records.sort(key=lambda r: (r["group"] == "quadrature", r["solver"] != "MUMPS", order.get(r["element"], 9),
                                contact_rank(r["contact"]), r["N"], quadrature_rank(r["quadrature"])))
    report.write_csv(csv_path, records, SMOOTH_COLUMNS)
    base = [r for r in records if r["solver"] == "MUMPS" and r["group"] == "convergence"]
    quad = [r for r in records if r["group"] == "quadrature"]
    groups = []
    for r in base:
        if (r["element"], r["contact"]) not in groups:
            groups.append((r["element"], r["contact"]))
    rates = smooth_rates(base, groups)

    def series(key):
        return {f"{e} {c}": [key(r) for r in base if r["element"] == e and r["contact"] == c and r.get("dofs")]
                for e, c in groups}
    report.plot_error_vs_dofs(os.path.join(ctx.out, "smooth_error_vs_dofs.png"),
                              series(lambda r: (r["dofs"], r["h"], r.get("l2_rel"), r.get("energy_rel"))))
    report.plot_trade(os.path.join(ctx.out, "smooth_error_vs_time.png"),
                      series(lambda r: (r.get("t_commands"), r.get("l2_rel"), r.get("energy_rel"))))
    elements = [e for e in ALL_ELEMENTS if any(g[0] == e for g in groups)]
    report.plot_time_vs_dofs(os.path.join(ctx.out, "smooth_time_vs_dofs.png"),
                             {**{f"{e} {c} total": [(r["dofs"], r.get("t_commands")) for r in base
                                                    if r["element"] == e and r["contact"] == c and r.get("dofs")]
                                 for e, c in groups if c in ("open", "STANDARD")},
                              **{f"{e} factorisation": [(r["dofs"], r.get("t_factorisation")) for r in base
                                                        if r["element"] == e and r["contact"] == "open"
                                                        and r.get("dofs")]
                                 for e in elements[:1]}})

    md = ctx.header("Smooth manufactured scene: convergence with and without contact, cost, solvers")
    commands = {}
    for r in records:
        commands.setdefault(r.get("command") or "unknown", set()).add(
            f"{r['element']} {'open' if r['contact'] == 'open' else 'contact'}"
            + (" (sub-cell quadrature rows)" if r["group"] == "quadrature" else ""))
    if len(commands) > 1 or partial:
        md += "Rows by command (a partial run keeps the other rows of the previous smooth.csv):\n\n"
        for c, what in commands.items():
            md += f"* `{c}`: {', '.join(sorted(what, key=lambda w: (order.get(w.split()[0], 9), w)))}\n"
        md += "\n"
    md += ("Scene: astest/smooth_*.comm and smooth_contact_*.comm (tools/study/scenes.py), four blocks with their "
           "own degree-5 field (tools/study/smooth_field.py), DDL_IMPO of the exact field on the outer boundary, "
           "FORCE_INTERNE = -div sigma. `open`: open traction-free interfaces, no contact. `STANDARD` / "
           "`PENALISATION k`: the closed variant of the field (blocks sliding along the interfaces, continuous "
           "compressive normal traction that jumps at the junction) with DEFI_CONTACT FORMULATION='XFEM' on the "
           "three interfaces (Nitsche, or the penalty with COEF_PENA_CONT = k). 3D: one layer of thickness h "
           "(cubic cells), u_z = 0. Errors are POST_ERREUR's relative errors: L2 = DIFFERENCE/REFERENCE of "
           "DEPL_RELA, energy = sqrt(DIFFERENCE/REFERENCE) of ENER_RELA. `ref. quad.` = relative difference "
           "between POST_ERREUR's REFERENCE (integrated by miniaster) and the exact norm.\n\n")
    md += "## Convergence rates (least squares in h on the four finest points)\n\n"
    md += report.markdown_table(rates, [("element", "element", None), ("modelisation", "model", None),
                                        ("contact", "contact", None), ("points", "fit on", None),
                                        ("energy_rate", "energy rate (theory 1)", "f"),
                                        ("l2_rate", "L2 rate (theory 2)", "f"),
                                        ("energy_finest", "energy err. finest", "e"),
                                        ("l2_finest", "L2 err. finest", "e"),
                                        ("contact_iterations", "contact it. (max)", None),
                                        ("newton", "Newton it. (max)", None),
                                        ("time_exponent", "total time ~ DOFs^", "f"),
                                        ("fact_exponent", "factorisation ~ DOFs^", "f")])
    md += "\n![error vs DOFs](smooth_error_vs_dofs.png)\n\n![error vs time](smooth_error_vs_time.png)\n\n"
    md += "![time vs DOFs](smooth_time_vs_dofs.png)\n\n"
    for r in records:
        if r.get("l2_ref") and r.get("l2_ref_exact"):
            r["l2_ref_q"] = abs(r["l2_ref"] - r["l2_ref_exact"]) / r["l2_ref_exact"]
        if r.get("energy_ref") and r.get("energy_ref_exact"):
            r["energy_ref_q"] = abs(r["energy_ref"] - r["energy_ref_exact"]) / r["energy_ref_exact"]
    cols = [("element", "element", None), ("contact", "contact", None), ("N", "N", None), ("dofs", "DOFs", None),
            ("l2_rel", "L2 err.", "e"), ("energy_rel", "energy err.", "e"), ("t_mesh", "mesh", "t"),
            ("t_xfem", "X-FEM set-up", "t"), ("t_setup", "loads etc.", "t"), ("t_numbering", "numbering", "t"),
            ("t_pattern", "pattern", "t"), ("t_assembly", "assembly", "t"), ("t_factorisation", "factor.", "t"),
            ("t_solve", "solve", "t"), ("t_analysis_other", "forces+stresses", "t"), ("t_post", "post", "t"),
            ("t_commands", "total", "t"), ("peak_mb", "peak MB", "t"), ("contact_iterations", "contact it.", None),
            ("newton", "Newton it.", None), ("penetration", "interpenetration", "e"),
            ("energy_ref_q", "ref. quad.", "e"), ("alarms", "alarms", None), ("diagnostic", "diagnostic", None)]
    md += "## Mesh refinement (MUMPS, RENUM='AUTO')\n\nTimes in seconds.\n\n"
    md += report.markdown_table(base, cols)
    others = [r for r in records if r["solver"] != "MUMPS" and r["group"] == "convergence"]
    if others:
        md += "\n## Linear solvers (open scene)\n\n"
        md += report.markdown_table(others, [("element", "element", None), ("N", "N", None), ("dofs", "DOFs", None),
                                             ("solver", "SOLVEUR", None), ("ordering", "ordering used", None),
                                             ("factor_entries", "factor entries", None),
                                             ("t_factorisation", "factor. (s)", "t"), ("t_solve", "solve (s)", "t"),
                                             ("solver_peak_mb", "solver MB", None), ("peak_mb", "peak MB", "t"),
                                             ("residual", "rel. residual", "e"), ("energy_rel", "energy err.", "e")])
    if quad:
        md += smooth_quadrature_section(ctx, quad)
    write_text(os.path.join(ctx.out, "smooth.md"), md)
    return records


def smooth_quadrature_section(ctx, quad):
    """Markdown, rates and plots of the sub-cell quadrature rows (--subcell-quadrature)."""
    order = {e: i for i, e in enumerate(ALL_ELEMENTS)}
    catalogue = {(r["element"], r["contact"], r["N"]): r for r in quad if r["quadrature"] == "catalogue"}
    for r in quad:
        c = catalogue.get((r["element"], r["contact"], r["N"]))
        if r.get("l2_ref") and r.get("l2_ref_exact"):
            r["l2_ref_q"] = abs(r["l2_ref"] - r["l2_ref_exact"]) / r["l2_ref_exact"]
        if r.get("energy_ref") and r.get("energy_ref_exact"):
            r["energy_ref_q"] = abs(r["energy_ref"] - r["energy_ref_exact"]) / r["energy_ref_exact"]
        if not c:
            continue
        if r.get("all_points") and r.get("subcell_points") is not None:
            r["subcell_share"] = r["subcell_points"] / r["all_points"]
        for key in ("l2_rel", "energy_rel", "t_assembly", "subcell_points", "all_points", "t_analysis_other",
                    "t_post"):
            if r.get(key) and c.get(key):
                r[f"{key}_ratio"] = r[key] / c[key]
    groups = []
    for r in quad:
        if (r["element"], r["contact"], r["quadrature"]) not in groups:
            groups.append((r["element"], r["contact"], r["quadrature"]))
    rates = []
    for element, contact, rule in groups:
        rows = sorted((r for r in quad if (r["element"], r["contact"], r["quadrature"]) == (element, contact, rule)
                       and r.get("l2_rel")), key=lambda r: -r["h"])
        tail = rows[-4:]
        failed = [r for r in quad if (r["element"], r["contact"], r["quadrature"]) == (element, contact, rule)
                  and r.get("exit") != 0]
        rates.append({
            "element": element, "contact": contact, "quadrature": rule,
            "points": f"N = {tail[0]['N']}..{tail[-1]['N']}" if tail else "",
            "energy_rate": report.fit_rate([r["h"] for r in tail], [r["energy_rel"] for r in tail]),
            "l2_rate": report.fit_rate([r["h"] for r in tail], [r["l2_rel"] for r in tail]),
            "energy_finest": tail[-1]["energy_rel"] if tail else None,
            "l2_finest": tail[-1]["l2_rel"] if tail else None,
            "energy_ratio_finest": tail[-1].get("energy_rel_ratio") if tail else None,
            "l2_ratio_finest": tail[-1].get("l2_rel_ratio") if tail else None,
            "failed": ", ".join(f"N={r['N']}: {r.get('diagnostic')}" for r in failed),
        })
    report.plot_quadrature_ratio(os.path.join(ctx.out, "smooth_quadrature_ratio.png"),
                                 {(e, c, q): [(r["dofs"], r.get("l2_rel_ratio"), r.get("energy_rel_ratio"))
                                              for r in quad if (r["element"], r["contact"], r["quadrature"]) == (e, c, q)
                                              and r.get("dofs")]
                                  for e, c, q in groups if q != "catalogue"})
    report.plot_quadrature_error(os.path.join(ctx.out, "smooth_quadrature_error.png"),
                                 {(e, c, q): [(r["dofs"], r.get("l2_rel"), r.get("energy_rel")) for r in quad
                                              if (r["element"], r["contact"], r["quadrature"]) == (e, c, q)
                                              and r.get("dofs")]
                                  for e, c, q in groups if e in ("quad4", "tetra4")})
    rules, q2, q3 = quadrature_grid(ctx.args.full)
    md = ("\n## Sub-cell quadrature (`miniaster run --subcell-quadrature DEGREE`)\n\n"
          "The same scene with the rule of the X-FEM volume sub-cells forced to the lowest code_aster family of "
          "at least that polynomial degree (TRIA3: 1 FPG1, 2 FPG3, 3 FPG4, 4 FPG6, 5 FPG7, 6 FPG12; TETRA4: 1 FPG1, "
          "2 FPG4, 3 FPG5, 4-5 FPG15, 6 FPG24) instead of the catalogue's (TRIA3 FPG12 with one interface, FPG4 "
          "with several; TETRA4 FPG15 / FPG5); skin sub-cells keep the catalogue's rule (docs/xfem.md). The rule "
          "enters the stiffness, the body force, SIEF_ELGA and POST_ERREUR's own integration on the X-FEM "
          "elements only (classical cells keep their rule). The rules of one mesh ran back to back. "
          "`sub-cell points` = integration points on the volume sub-cells (MODI_MODELE_XFEM's log), `share` = "
          "their fraction of all the model's integration points (classical cells on their own rule); `x cat.` = "
          "ratio to the catalogue row of the same mesh; `ref. quad.` = relative error of POST_ERREUR's REFERENCE "
          "(the exact field's energy norm integrated on the same points) against the analytic norm: the "
          "measurement's own quadrature error.\n\n")
    md += "### Rates per rule (least squares in h on the four finest points)\n\n"
    md += report.markdown_table(rates, [("element", "element", None), ("contact", "contact", None),
                                        ("quadrature", "rule", None), ("points", "fit on", None),
                                        ("energy_rate", "energy rate", "f"), ("l2_rate", "L2 rate", "f"),
                                        ("energy_finest", "energy err. finest", "e"),
                                        ("energy_ratio_finest", "x cat.", "f3"),
                                        ("l2_finest", "L2 err. finest", "e"), ("l2_ratio_finest", "x cat.", "f3"),
                                        ("failed", "failed runs", None)])
    md += "\n![error ratio to the catalogue rule](smooth_quadrature_ratio.png)\n\n"
    md += "![error vs DOFs per rule](smooth_quadrature_error.png)\n\n"
    md += "### Every run\n\nTimes in seconds.\n\n"
    rows = sorted(quad, key=lambda r: (order.get(r["element"], 9), contact_rank(r["contact"]), r["N"],
                                      quadrature_rank(r["quadrature"])))
    md += report.markdown_table(rows, [
        ("element", "element", None), ("contact", "contact", None), ("N", "N", None), ("quadrature", "rule", None),
        ("dofs", "DOFs", None), ("subcell_points", "sub-cell points", None), ("subcell_share", "share", "f3"),
        ("t_xfem", "X-FEM set-up", "t"), ("t_assembly", "assembly", "t"), ("t_assembly_ratio", "x cat.", "f"),
        ("t_factorisation", "factor.", "t"), ("t_analysis_other", "forces+stresses", "t"),
        ("t_analysis_other_ratio", "x cat.", "f"), ("t_post", "post", "t"), ("t_post_ratio", "x cat.", "f"),
        ("t_commands", "total", "t"),
        ("peak_mb", "peak MB", "t"), ("contact_iterations", "contact it.", None), ("newton", "Newton it.", None),
        ("l2_rel", "L2 err.", "e"), ("l2_rel_ratio", "x cat.", "f3"), ("energy_rel", "energy err.", "e"),
        ("energy_rel_ratio", "x cat.", "f3"), ("energy_ref_q", "ref. quad.", "e"), ("alarms", "alarms", None),
        ("diagnostic", "diagnostic", None), ("failure", "failure", None)])
    return md


# ----------------------------------------------------------------------------------------------
# stability: extreme inputs on the rigid scene

STAB_COLUMNS = ["family", "label", "element", "N", "offset", "E", "NU", "size", "solver", "algo", "coef", "dofs",
                "l2_rel", "strain_rel", "energy_rel", "error", "verdict", "cond1", "cond2", "diag_ratio", "residual", "min_fraction",
                "dropped", "snapped", "alarms", "diagnostic", "exit", "failure"]


def stability_points(full):
    pts = []
    eps = [10.0 ** -k for k in range(1, 13)]
    for element in (["quad4", "tria3", "hexa8", "tetra4"] if full else ["quad4", "tria3", "hexa8"]):
        n = 10 if scenes.ELEMENTS[element][1] == 2 else 6
        for e in (eps if element in ("quad4", "tria3") or full else [1e-1, 1e-4, 1e-8, 1e-12]):
            pts.append(dict(family="offset", label=f"eps={e:.0e}", element=element, N=n, offset=e))
        pts.append(dict(family="through nodes", label="interfaces on grid lines", element=element, N=n, offset=0.0))
        pts.append(dict(family="cell centres", label="odd N", element=element, N=n + 1, offset=0.0))
    pts += node_row_points(full)
    for E in [1e-3, 1.0, 1e3, 1e6, 1e9, 1e12]:
        pts.append(dict(family="E", label=f"E={E:.0e}", element="quad4", N=11, E=E))
    pts.append(dict(family="units", label="m, N, Pa (E=2e11 Pa)", element="quad4", N=11, E=2e11, size=1.0))
    pts.append(dict(family="units", label="mm, N, MPa (E=2e5 MPa)", element="quad4", N=11, E=2e5, size=1e3))
    for nu in [0.0, 0.2, 0.3, 0.45, 0.49, 0.499, 0.4999]:
        pts.append(dict(family="NU", label=f"NU={nu}", element="quad4", N=11, NU=nu))
        if full:
            pts.append(dict(family="NU", label=f"NU={nu}", element="hexa8", N=7, NU=nu))
    for s in [1e-6, 1e-3, 1.0, 1e3, 1e6]:
        pts.append(dict(family="size", label=f"size={s:.0e}", element="quad4", N=11, size=s))
    if full:
        for solver in ["MULT_FRONT", "LDLT"]:
            for e in [1e-2, 1e-6, 1e-10]:
                pts.append(dict(family="offset " + solver, label=f"eps={e:.0e}", element="quad4", N=10, offset=e,
                                solver=solver))
    return pts + contact_stability_points(full)


def node_row_points(full):
    """The interface X = 0 swept across a node row (grid offset ox of the interior lines, in cells) while
    Y = 0 runs along a node row or through cells, at N = 4, 5, 6: the junction cell and the prescribed
    sides' nodes next to it take every placement relative to the nodes (at N = 4 with X = 0 through the
    cells next to the sides, those nodes sit in cells that see the three interfaces)."""
    pts = []
    for element in ["quad4", "tria3", "hexa8"] + (["tetra4"] if full else []):
        for n in (4, 5, 6):
            row = 0.0 if n % 2 == 0 else 0.5  # grid offset putting a node row on the interface
            for oy, where in ((row, "Y on nodes"), (row + 0.5 - (1.0 if row else 0.0), "Y through cells")):
                for dx in (-0.25, -1e-3, -1e-8, 0.0, 1e-8, 1e-3, 0.25, 0.5):
                    ox = row + dx if abs(row + dx) < 1 else row + dx - 1.0
                    pts.append(dict(family="node row", label=f"X {dx:+g} h from a node row, {where}",
                                    element=element, N=n, offset=ox, offset_y=oy))
    return pts


def contact_stability_points(full):
    """The uniform-compression scene with contact (scenes.compression_comm, ssnv511e-h type), for both
    algorithms; families are prefixed 'contact'. PENALISATION uses COEF_PENA_CONT = 1e4 E / size (1e12 Pa/m
    for the base point), its error is measured beyond the analytic shift p/COEF_PENA_CONT."""
    pts = []
    # 3e-5: the junction's slivers (eps^2 h) just inside CellCut's former 1e-9 merge distance, where the
    # old cut lost the most (energy 5e-9, silently); 1e-5: where the sweep first showed that floor
    eps = sorted([10.0 ** -k for k in range(1, 13)] + [3e-5], reverse=True)
    few = [1e-1, 1e-4, 3e-5, 1e-5, 1e-7, 1e-8, 1e-12]
    for algo in ("STANDARD", "PENALISATION"):
        c = dict(scene="contact", algo=algo)
        for element in ["quad4", "tria3", "hexa8", "tetra4"]:
            dim = scenes.ELEMENTS[element][1]
            n = 10 if dim == 2 else 6
            if dim == 3 and element == "tetra4" and not full:
                continue
            for e in (eps if dim == 2 or full else few):
                pts.append(dict(c, family="contact offset", label=f"eps={e:.0e}", element=element, N=n, offset=e))
            pts.append(dict(c, family="contact through nodes", label="interfaces on grid lines", element=element,
                            N=n, offset=0.0))
            pts.append(dict(c, family="contact cell centres", label="odd N", element=element, N=n + 1, offset=0.0))
        for E in [1e-3, 1.0, 1e3, 1e6, 1e9, 1e12]:
            pts.append(dict(c, family="contact E", label=f"E={E:.0e}", element="quad4", N=11, E=E))
        pts.append(dict(c, family="contact units", label="mm, N, MPa (E=2e5 MPa)", element="quad4", N=11, E=2e5,
                        size=1e3))
        for nu in [0.0, 0.3, 0.45, 0.49, 0.499, 0.4999]:
            for element in ["quad4", "tria3"] + (["hexa8"] if full else []):
                pts.append(dict(c, family="contact NU", label=f"NU={nu}", element=element,
                                N=11 if element != "hexa8" else 7, NU=nu))
        for s in [1e-6, 1e-3, 1.0, 1e3, 1e6]:
            pts.append(dict(c, family="contact size", label=f"size={s:.0e}", element="quad4", N=11, size=s))
            if full:
                pts.append(dict(c, family="contact size", label=f"size={s:.0e}", element="hexa8", N=7, size=s))
    return pts


def contact_stability_case(ctx, p, tag):
    """One point of the compression scene with contact (contact_stability_points)."""
    element = p["element"]
    dim = scenes.ELEMENTS[element][1]
    size = p.get("size", 1.0)
    E, NU = p.get("E", 100.0e6), p.get("NU", 0.3)
    algo = p["algo"]
    coef = 1e4 * E / size if algo == "PENALISATION" else None
    a = 5.0 * size
    kw = dict(bounds=(-a, a, -a, a))
    if dim == 3:
        kw["zbounds"] = (0.0, size)
    if p.get("offset"):
        kw["offset"] = (p["offset"], p["offset"])
    mesh = ctx.mesh(element, p["N"], **kw)
    # pressures scale with E (strains 1e-2 for every E); code_aster's default relative criterion
    comm = scenes.compression_comm(element, algo, coef, E=E, NU=NU, size=size, pressure=1e-2 * E, info=2,
                                   reference="penalised", convergence="RESI_GLOB_RELA=1.0E-6")
    rec = ctx.run(tag, comm, mesh)
    rec.update({k: v for k, v in p.items()}, E=E, NU=NU, size=size, solver="MUMPS", offset=p.get("offset", 0.0),
               coef=coef if coef else "")
    errs = [rec.get("l2_rel"), rec.get("energy_rel")]
    if rec.get("exit") == 1:
        rec["verdict"] = "refused (error)"
    elif None in errs:
        rec["verdict"] = "no result"
    else:
        rec["error"] = max(errs)
        lost = not (rec["error"] <= 1e-9)
        rec["verdict"] = "kept" if not lost else ("lost, alarm" if rec.get("alarms") else "LOST SILENTLY")
    return rec


def stability_case(ctx, p, tag):
    if p.get("scene") == "contact":
        return contact_stability_case(ctx, p, tag)
    element = p["element"]
    dim = scenes.ELEMENTS[element][1]
    size = p.get("size", 1.0)
    E, NU = p.get("E", 100.0e6), p.get("NU", 0.3)
    solver = p.get("solver", "MUMPS")
    a = 5.0 * size
    kw = dict(bounds=(-a, a, -a, a))
    if dim == 3:
        kw["zbounds"] = (0.0, size)
    if p.get("offset") or p.get("offset_y"):
        kw["offset"] = (p.get("offset", 0.0), p.get("offset_y", p.get("offset", 0.0)))
    mesh = ctx.mesh(element, p["N"], **kw)
    rec = ctx.run(tag, scenes.rigid_comm(element, E=E, NU=NU, size=size, solver=solver, info=2), mesh)
    rec.update({k: v for k, v in p.items()}, E=E, NU=NU, size=size, solver=solver, offset=p.get("offset", 0.0))
    # strain error: rms strain of the computed field relative to the rigid motion's u/L = 0.2
    # (energy W = integral of w(sigma_h) ~ E eps^2 / 2)
    volume = (2 * a) ** 2 * (size if dim == 3 else 1.0)
    if "energy_diff" in rec:
        rec["strain_rel"] = math.sqrt(max(rec["energy_diff"], 0.0) * 2.0 / (E * volume)) / 0.2
    errs = [rec.get("l2_rel"), rec.get("strain_rel")]
    if rec.get("exit") == 1:
        rec["verdict"] = "refused (error)"
    elif None in errs:
        rec["verdict"] = "no result"
    else:
        rec["error"] = max(errs)
        lost = not (rec["error"] <= 1e-9)
        if not lost:
            rec["verdict"] = "kept"
        elif rec.get("alarms"):
            rec["verdict"] = "lost, alarm"
        else:
            rec["verdict"] = "LOST SILENTLY"
    return rec


def study_stability(ctx):
    records = []
    for i, p in enumerate(stability_points(ctx.args.full)):
        if p["element"] not in ctx.elements:
            continue
        rec = stability_case(ctx, p, f"stab_{i:03d}")
        records.append(rec)
        log(f"stability {p['family']} {p['label']} {p['element']}: error {rec.get('error', float('nan')):.2e}, "
            f"cond1 {rec.get('cond1', float('nan')):.2e}, alarms [{rec.get('alarms', '')}] -> {rec['verdict']}")
    report.write_csv(os.path.join(ctx.out, "stability.csv"), records, STAB_COLUMNS)
    cols = [("family", "family", None), ("label", "point", None), ("element", "element", None), ("N", "N", None),
            ("dofs", "DOFs", None), ("l2_rel", "L2 rel.", "e"), ("strain_rel", "strain rel.", "e"),
            ("cond1", "MUMPS cond1", "e"), ("cond2", "cond2", "e"), ("residual", "rel. residual", "e"),
            ("min_fraction", "smallest fraction kept", "e"), ("dropped", "dropped", None),
            ("snapped", "LSN snapped", None), ("alarms", "alarms", None), ("verdict", "verdict", None)]
    md = ctx.header("Stability sweep: ssnv511a rigid scene, ssnv511e-h compression with contact")
    md += ("Scene: tools/study/scenes.py `rigid_comm` (ssnv511a loading: DX = -0.25, -0.5, 0.75, 1 per block on "
           "the sides x = +-a, DY = 0), MECA_STATIQUE INFO=2 (MUMPS condition estimates RINFOG(10/11) when MUMPS "
           "is the solver). The exact answer is piecewise rigid for every point. Error = max(L2 relative error "
           "of POST_ERREUR DEPL_RELA, rms strain of the computed field / (u/L)) where the strain comes from "
           "ENER_RELA against sigma = 0. Verdict: `kept` when the error is <= 1e-9, `lost, alarm` when it is "
           "larger and the .mess carries an alarm, **LOST SILENTLY** otherwise (a defect). Offsets: the interior "
           "grid lines are moved by eps cell sizes (tools/ssnv511_mesh --offset eps eps), so that the interfaces "
           "X=0 and Y=0 run eps*h from a row of nodes. Family `node row`: X=0 swept across a node row (offsets "
           "-h/4 ... +h/2) while Y=0 runs along a node row or through cells, N = 4, 5, 6 (the junction and the "
           "prescribed sides' nodes next to it in every placement; tools/ssnv511_mesh --offset OX OY).\n\n")
    silent = [r for r in records if r["verdict"] == "LOST SILENTLY"]
    rigid = [r for r in records if r.get("scene") != "contact"]
    contact = [r for r in records if r.get("scene") == "contact"]
    md += f"**{len(silent)} silent loss(es) of precision out of {len(records)} points** "
    md += f"({len(rigid)} rigid, {len(contact)} with contact).\n\n"
    md += "## Rigid scene (ssnv511a)\n\n"
    md += report.markdown_table(rigid, cols)
    if contact:
        md += ("\n## Uniform compression with contact (ssnv511e-h)\n\nScene: tools/study/scenes.py `compression_comm` "
               "(pressures p = 1e-2 E and 2p on the top and right sides by halves, rollers on the left and bottom "
               "sides, DEFI_CONTACT FORMULATION='XFEM' on the three interfaces, CONTACT_INIT='OUI', INTEGRATION='NOEUD' "
               "(on HEXA8 replaced by TR3 FPG3, exact for the bilinear facet traces: alarm CONTACT_INTEGRATION, "
               "docs/contact.md), STAT_NON_LINE "
               "INFO=2 with code_aster's default RESI_GLOB_RELA = 1e-6; 3D: the one-layer slab z in [0, size], "
               "DZ = 0 on the bottom, free top). Exact answer: uniform stresses per block, closed interfaces. Error = "
               "max(L2 relative error of POST_ERREUR DEPL_RELA, energy-norm relative error of ENER_RELA). "
               "PENALISATION: COEF_PENA_CONT = 1e4 E / size, the reference field includes the analytic rigid shifts "
               "p/COEF_PENA_CONT of the blocks (the error of the method), so the error is what is lost beyond "
               "it.\n\n")
        md += report.markdown_table(contact, [
            ("family", "family", None), ("label", "point", None), ("element", "element", None), ("algo", "ALGO_CONT", None),
            ("N", "N", None), ("dofs", "DOFs", None), ("l2_rel", "L2 rel.", "e"), ("energy_rel", "energy rel.", "e"),
            ("cond1", "MUMPS cond1", "e"), ("residual", "rel. residual", "e"),
            ("contact_iterations", "contact it.", None), ("min_fraction", "smallest fraction kept", "e"),
            ("snapped", "LSN snapped", None), ("alarms", "alarms", None), ("verdict", "verdict", None)])
    for fam, fname, xlabel, key, logx in (("offset", "stability_offset.png", "eps (interface offset / h)", "offset", True),
                                          ("E", "stability_E.png", "E", "E", True),
                                          ("NU", "stability_nu.png", "NU", "NU", False),
                                          ("size", "stability_size.png", "domain size factor", "size", True)):
        series = {}
        for r in records:
            if r["family"].split()[0] == fam and r.get("error") is not None:
                series.setdefault(r["element"] + ("" if r["family"] == fam else " " + r["family"].split()[1]),
                                  []).append((r[key], r["error"], bool(r.get("alarms"))))
        if series:
            report.plot_sweep(os.path.join(ctx.out, fname), f"rigid scene: {fam}", xlabel, series, logx=logx)
            md += f"\n![{fam}]({fname})\n"
    for fam, fname, xlabel, key, logx in (("offset", "stability_contact_offset.png", "eps (interface offset / h)",
                                           "offset", True),
                                          ("E", "stability_contact_E.png", "E (pressure = 1e-2 E)", "E", True),
                                          ("NU", "stability_contact_nu.png", "NU", "NU", False),
                                          ("size", "stability_contact_size.png", "domain size factor", "size", True)):
        series = {}
        for r in contact:
            if r["family"] == "contact " + fam and r.get("error") is not None:
                series.setdefault(f"{r['element']} {r['algo'].lower()}", []).append(
                    (r[key], r["error"], bool(r.get("alarms"))))
        if series:
            report.plot_sweep(os.path.join(ctx.out, fname), f"compression with contact: {fam}", xlabel, series,
                              logx=logx, ylabel="error (max of L2 rel., energy rel.)")
            md += f"\n![contact {fam}]({fname})\n"
    write_text(os.path.join(ctx.out, "stability.md"), md)
    return records


# ----------------------------------------------------------------------------------------------
# penalty: exact contact (STANDARD) against the penalty (PENALISATION, COEF_PENA_CONT) on ssnv511e-h

PENALTY_COLUMNS = ["element", "N", "algo", "coef", "dofs", "l2_rel", "expected_l2", "energy_rel", "penetration",
                   "contact_iterations", "newton", "cond1", "residual", "t_factorisation", "t_commands", "alarms",
                   "diagnostic", "exit", "failure"]


def study_penalty(ctx):
    # Up to 1e24, beyond the 1e20: where the penalty error p/k falls below round-off the error
    # must stay flat (or the run stop with its cause named), never blow up.
    coefs = [10.0 ** k for k in range(4, 25, 2)]
    records = []
    for element in ctx.elements:
        dim = scenes.ELEMENTS[element][1]
        # 3D: the one-layer slab z in [0, 1] (ssnv511g/h), N = 5 (and 11 with --full)
        ns = ([11, 41] if ctx.args.full else [11]) if dim == 2 else ([5, 11] if ctx.args.full else [5])
        for n in ns:
            mesh = ctx.mesh(element, n) if dim == 2 else ctx.mesh(element, n, zbounds=(0.0, 1.0))
            for algo, coef in [("STANDARD", None)] + [("PENALISATION", c) for c in coefs]:
                rec = ctx.run(f"pen_{element}_{n}_{algo}_{coef}", scenes.compression_comm(element, algo, coef), mesh)
                rec.update(element=element, N=n, algo=algo, coef=coef if coef else "")
                if coef and rec.get("l2_ref"):
                    # block measure: 25 (area per unit thickness in 2D; volume of the 1-thick slab in 3D)
                    rec["expected_l2"] = scenes.penalty_expected_l2(coef, rec["l2_ref"], block_measure=25.0)
                records.append(rec)
                log(f"penalty {element} N={n} {algo} {coef or ''}: L2 {rec.get('l2_rel', float('nan')):.3e} "
                    f"(expected {rec.get('expected_l2', 0.0):.3e}), energy {rec.get('energy_rel', float('nan')):.2e}, "
                    f"contact it. {rec.get('contact_iterations')}, [{rec.get('alarms', '')}] {rec.get('diagnostic')}")
    report.write_csv(os.path.join(ctx.out, "penalty.csv"), records, PENALTY_COLUMNS)
    md = ctx.header("Exact contact against the penalty (ssnv511e-h compression)")
    md += ("Scene: tools/study/scenes.py `compression_comm` (ssnv511e loading: pressures 1e6/2e6 on LH and LD, "
           "rollers on LG and LB, DEFI_CONTACT FORMULATION='XFEM' on the three interfaces, CONTACT_INIT='OUI', "
           "INTEGRATION='NOEUD': on HEXA8 replaced by TR3 FPG3, exact for the bilinear facet traces, docs/contact.md), "
           "STAT_NON_LINE; 3D (HEXA8, TETRA4, ssnv511g/h): the one-layer slab z in [0, 1] of tools/ssnv511_mesh, "
           "same loads on the faces x = 5 and y = 5, DZ = 0 on the bottom face, free top face. The exact answer "
           "has uniform stresses per block and closed interfaces. With "
           "PENALISATION every interface is crossed by pressure/COEF_PENA_CONT: `expected L2` is that analytic "
           "rigid shift (the error of the method); the energy error should stay at round-off.\n\n")
    md += report.markdown_table(records, [
        ("element", "element", None), ("N", "N", None), ("algo", "ALGO_CONT", None), ("coef", "COEF_PENA_CONT", "e"),
        ("dofs", "DOFs", None), ("l2_rel", "L2 err.", "e"), ("expected_l2", "expected L2 (p/k)", "e"),
        ("energy_rel", "energy err.", "e"), ("penetration", "interpenetration", "e"),
        ("contact_iterations", "contact it.", None), ("newton", "Newton it.", None), ("cond1", "MUMPS cond1", "e"),
        ("t_commands", "total (s)", "t"), ("alarms", "alarms", None), ("diagnostic", "diagnostic", None)])
    report.plot_penalty(os.path.join(ctx.out, "penalty_error_vs_coef.png"), records)
    md += "\n![penalty](penalty_error_vs_coef.png)\n"
    write_text(os.path.join(ctx.out, "penalty.md"), md)
    return records


# ----------------------------------------------------------------------------------------------
# perf: ssnv511a-type scene refined

PERF_COLUMNS = ["scene", "element", "N", "solver", "dofs", "equations", "nonzeros", "t_mesh", "t_xfem", "t_setup",
                "t_numbering", "t_pattern", "t_assembly", "setup_assembly", "us_per_dof", "ordering", "t_ordering",
                "t_factorisation", "t_mumps_factorisation", "flops", "t_solve", "fact_solve", "t_analysis_other", "t_post", "t_commands", "ratio_total", "ratio_compute", "wall",
                "peak_mb", "solver_peak_mb", "factor_entries", "l2_rel", "residual", "tests_ok", "tests_nook", "tests",
                "load", "diagnostic"]

# code_aster's own command file, read in place (never copied into the project)
SSNV511A_COMM = os.path.join(os.path.dirname(ROOT), "shared", "astest", "ssnv511a.comm")


def perf_figures(rec):
    """The two issue-8 figures of a run: set-up + assembly per DOF, total against factorisation + solve."""
    # set-up + assembly: everything before the factorisation that scales with the mesh
    rec["setup_assembly"] = sum(rec.get(k, 0.0) for k in ("t_mesh", "t_xfem", "t_setup", "t_numbering",
                                                           "t_pattern", "t_assembly"))
    if rec.get("dofs"):
        rec["us_per_dof"] = 1e6 * rec["setup_assembly"] / rec["dofs"]
    rec["fact_solve"] = rec.get("t_factorisation", 0.0) + rec.get("t_solve", 0.0)
    if rec["fact_solve"] > 0:
        rec["ratio_total"] = rec.get("t_commands", 0.0) / rec["fact_solve"]
        rec["ratio_compute"] = (rec.get("t_commands", 0.0) - rec.get("t_post", 0.0)) / rec["fact_solve"]
    log(f"perf {rec['scene']} N={rec['N']}: {rec.get('dofs')} dofs, set-up+assembly {rec['setup_assembly']:.2f} s "
        f"({rec.get('us_per_dof', float('nan')):.2f} us/dof), factorisation+solve {rec['fact_solve']:.2f} s, "
        f"total {rec.get('t_commands', float('nan')):.2f} s ({rec.get('ratio_total', float('nan')):.2f} x), "
        f"load {rec['load']:.1f}{', tests ' + rec['tests'] if rec.get('tests') else ''}")
    return rec


def study_perf(ctx):
    ns = [101, 301, 1001] if ctx.args.full else [101, 301]
    records = []
    for n in ns:
        mesh = ctx.mesh("quad4", n)
        load = os.getloadavg()[0]
        rec = ctx.run(f"perf_{n}", scenes.rigid_comm("quad4", info=1), mesh)
        rec.update(scene="rigid_comm + POST_ERREUR", element="quad4", N=n, solver="MUMPS", load=load)
        records.append(perf_figures(rec))
    # code_aster's ssnv511a.comm itself on the largest mesh, with its own post-processing and checks
    if os.path.exists(SSNV511A_COMM):
        n = ns[-1]
        load = os.getloadavg()[0]
        rec = runner.run_comm_file(ctx.binary, SSNV511A_COMM, ctx.mesh("quad4", n),
                                   os.path.join(ctx.work, f"ssnv511a_{n}"), ctx.args.timeout)
        rec.update(scene="ssnv511a.comm", element="quad4", N=n, solver="MUMPS", load=load)
        records.append(perf_figures(rec))
    else:
        log(f"perf: {SSNV511A_COMM} not found: the ssnv511a.comm row is left out")
    report.write_csv(os.path.join(ctx.out, "perf.csv"), records, PERF_COLUMNS)
    md = ctx.header("Refined ssnv511a scene: set-up and assembly against the factorisation")
    md += ("Scenes, both on tools/ssnv511_mesh QUAD4 N x N (groups SURF, LG, LD as ssnv511a's mesh):\n\n"
           "* `rigid_comm + POST_ERREUR`: tools/study/scenes.py `rigid_comm('quad4')` = ssnv511a's model and loads "
           "(three interfaces with junctions, DDL_IMPO functions, MECA_STATIQUE, MUMPS RENUM='AUTO'), plus "
           "CREA_CHAMP, POST_ERREUR DEPL_RELA/ENER_RELA and IMPR_TABLE as post-processing;\n"
           "* `ssnv511a.comm`: code_aster's own command file, read in place from ../shared/astest, with its own "
           "post-processing (POST_MAIL_XFEM, AFFE_MODELE of the visualisation model, POST_CHAM_XFEM, POST_RELEVE_T, "
           "CALC_TABLE, CREA_CHAMP, POST_ERREUR, IMPR_TABLE, TEST_TABLE); `tests` counts its checks.\n\n"
           "set-up + assembly = LIRE_MAILLAGE + DEFI_FISS_XFEM x3 + MODI_MODELE_XFEM + the other set-up commands + "
           "numbering + matrix pattern + stiffness assembly. Targets (issue 8): set-up + assembly <= 1 us per DOF, "
           "total <= 1.3 x (factorisation + solve); `total/(f+s)` counts every command, `without post` leaves out "
           "the commands after MECA_STATIQUE. `load` is the 1-minute load average when the run started (the "
           "machine's 2 cores are shared).\n\n")
    md += report.markdown_table(records, [
        ("scene", "scene", None), ("N", "N", None), ("dofs", "DOFs", None), ("t_mesh", "mesh", "t"),
        ("t_xfem", "X-FEM set-up", "t"), ("t_setup", "other set-up", "t"), ("t_numbering", "numbering", "t"),
        ("t_pattern", "pattern", "t"), ("t_assembly", "assembly", "t"), ("setup_assembly", "set-up+assembly", "t"),
        ("us_per_dof", "us/DOF", "f"), ("ordering", "ordering", None), ("t_ordering", "METIS", "t"),
        ("t_factorisation", "analysis+factorisation", "t"), ("flops", "flops", "e"), ("t_solve", "solve", "t"),
        ("t_analysis_other", "other analysis", "t"), ("t_post", "post", "t"), ("t_commands", "total", "t"),
        ("ratio_total", "total/(f+s)", "f"), ("ratio_compute", "without post", "f"), ("peak_mb", "peak MB", "t"),
        ("l2_rel", "L2 rel. err.", "e"), ("tests", "tests", None), ("load", "load", "f")])
    write_text(os.path.join(ctx.out, "perf.md"), md)
    return records


# ----------------------------------------------------------------------------------------------
# astest: the small smooth cases with their checks

ASTEST_N = {"quad4": 11, "tria3": 11, "hexa8": 11, "tetra4": 11}


def study_astest(ctx):
    table = os.path.join(ctx.out, "smooth.csv")
    if not os.path.exists(table):
        sys.exit(f"study astest: {table} is missing (run `./miniaster study smooth` first: the error bounds of "
                 "the cases come from the convergence fit)")
    rows = [r for r in read_records(table) if r["solver"] == "MUMPS" and r["group"] == "convergence" and r.get("l2_rel")]
    n2, n3, _, _ = smooth_grid(False)
    for element in ctx.elements:
        modelisation, dim = scenes.ELEMENTS[element]
        for contact in [c for c in (None, "STANDARD") if ("open" if c is None else "contact")
                        in SMOOTH_PARTS[ctx.args.contact]]:
            astest_case(ctx, element, contact, rows, n2 if dim == 2 else n3)


def astest_case(ctx, element, contact, rows, default_ns):
    modelisation, dim = scenes.ELEMENTS[element]
    n = ASTEST_N[element]
    h = 10.0 / n
    label = scenes.contact_label(contact)
    # the fit uses the four finest meshes of the default grid, whatever grid the table holds
    pts = sorted(((r["h"], r["l2_rel"], r["energy_rel"]) for r in rows
                  if r["element"] == element and r["contact"] == label and r["N"] in default_ns), reverse=True)
    tail = pts[-4:]
    if len(tail) < 4:
        sys.exit(f"study astest: smooth.csv has {len(tail)} {element} {label} rows of the default grid (4 needed)")
    bounds = {}
    for idx, name in ((1, "l2"), (2, "energy")):
        p = report.fit_rate([t[0] for t in tail], [t[idx] for t in tail])
        # C from the fitted line through the finest point, then extrapolated to the case's h
        c = tail[-1][idx] / tail[-1][0] ** p
        bounds[name] = (p, c, 1.25 * c * h ** p)
    case = f"smooth_{element}" if contact is None else f"smooth_contact_{element}"
    mesh = os.path.join(ROOT, "astest", case + ".mmed")
    kw = dict(zbounds=(0.0, h)) if dim == 3 else {}
    runner.make_mesh(ctx.build, element, n, mesh, **kw)
    thickness = h if dim == 3 else 1.0
    l2_exact, energy_exact, _, _ = smooth_field.exact_norms(modelisation, thickness=thickness,
                                                            contact=contact is not None)
    base = scenes.smooth_comm(element, title=f"Smooth manufactured scene, project case {case} (N = {n})",
                              contact=contact)
    probe = ctx.run(case + "_probe", base + "FIN()\n", mesh)
    if probe.get("exit") != 0 or "l2_rel" not in probe:
        sys.exit(f"study astest: the probe run of {case} failed: {probe.get('failure')}")
    tests = astest_checks(n, h, bounds, probe, l2_exact, energy_exact)
    write_text(os.path.join(ROOT, "astest", case + ".comm"), base + tests + "\nFIN()\n")
    write_text(os.path.join(ROOT, "astest", case + ".export"),
               f"P time_limit 60\nP memory_limit 256\nP ncpus 1\nP testlist verification sequential\n\n"
               f"F comm {case}.comm D 1\nF mmed {case}.mmed D 20\n")
    final = runner.run_case(ctx.binary, base + tests + "\nFIN()\n", mesh, os.path.join(ctx.work, case), case,
                            ctx.args.timeout)
    log(f"astest {case}: exit {final['exit']}, L2 {probe['l2_rel']:.4e} (bound {bounds['l2'][2]:.3e}), "
        f"energy {probe['energy_rel']:.4e} (bound {bounds['energy'][2]:.3e}), contact it. "
        f"{probe.get('contact_iterations')}, {final.get('t_commands')} s, {final['diagnostic']}")


def astest_checks(n, h, bounds, probe, l2_exact, energy_exact):
    """TEST_TABLE block of an astest smooth case."""
    # POST_ERREUR integrates the reference with the model's rules (not exact for this degree-10
    # integrand): allow 3x the quadrature error seen, at least 1e-6
    tol_l2 = max(1e-6, 3 * abs(probe["l2_ref"] - l2_exact) / l2_exact)
    tol_en = max(1e-6, 3 * abs(probe["energy_ref"] - energy_exact) / energy_exact)
    pl2, cl2, bl2 = bounds["l2"]
    pen, cen, ben = bounds["energy"]
    en_diff_bound = ben ** 2 * energy_exact  # energy error bound as an energy (DIFFERENCE column)
    t = []
    t.append("")
    t.append("# ---- checks (generated by `./miniaster study astest` from docs/study/smooth.csv) ----")
    t.append("# REFERENCE columns: exact norms of the manufactured field (analytic integrals, smooth_field.exact_norms),")
    t.append("# up to the quadrature error of POST_ERREUR's own integration of the degree-10 integrand.")
    t.append(f"# Error bounds: 1.25 x C h^p with (C, p) fitted on the four finest meshes of the default grid")
    t.append(f"# (L2: p = {pl2:.3f}, C = {cl2:.4e}; energy: p = {pen:.3f}, C = {cen:.4e}), h = 10/{n}.")
    t.append(f"L2_EXACT = {l2_exact!r}")
    t.append(f"ENERGY_EXACT = {energy_exact!r}")
    t.append("TEST_TABLE(TABLE=TAB_L2, NOM_PARA='REFERENCE', FILTRE=_F(NOM_PARA='GROUP_MA', VALE_K='TOTAL'),")
    t.append(f"           VALE_CALC={probe['l2_ref']!r}, REFERENCE='ANALYTIQUE', VALE_REFE=L2_EXACT,")
    t.append(f"           CRITERE='RELATIF', PRECISION={tol_l2:.1e})")
    t.append("TEST_TABLE(TABLE=TAB_NRJ, NOM_PARA='REFERENCE', FILTRE=_F(NOM_PARA='GROUP_MA', VALE_K='TOTAL'),")
    t.append(f"           VALE_CALC={probe['energy_ref']!r}, REFERENCE='ANALYTIQUE', VALE_REFE=ENERGY_EXACT,")
    t.append(f"           CRITERE='RELATIF', PRECISION={tol_en:.1e})")
    t.append("# the exact solution has no error: |computed error - 0| <= bound")
    t.append("TEST_TABLE(TABLE=TAB_L2, NOM_PARA='ERREUR RELATIVE', FILTRE=_F(NOM_PARA='GROUP_MA', VALE_K='TOTAL'),")
    t.append(f"           VALE_CALC={probe['l2_rel']!r}, REFERENCE='ANALYTIQUE', VALE_REFE=0.0,")
    t.append(f"           CRITERE='ABSOLU', PRECISION={bl2:.3e})")
    t.append("TEST_TABLE(TABLE=TAB_NRJ, NOM_PARA='DIFFERENCE', FILTRE=_F(NOM_PARA='GROUP_MA', VALE_K='TOTAL'),")
    t.append(f"           VALE_CALC={probe['energy_diff']!r}, REFERENCE='ANALYTIQUE', VALE_REFE=0.0,")
    t.append(f"           CRITERE='ABSOLU', PRECISION={en_diff_bound:.4e})")
    return "\n".join(t) + "\n"


def check_field(_ctx=None):
    failures = []
    for contact in (False, True):
        for modelisation in ("D_PLAN", "C_PLAN", "3D"):
            for E, NU in ((100.0e6, 0.3), (2.0e11, 0.0), (1.0, 0.49)):
                failures += smooth_field.check(modelisation, E, NU, contact=contact)
    failures += smooth_field.check_mutations()
    for contact in (False, True):
        for modelisation in ("D_PLAN", "C_PLAN"):
            l2, energy, _, _ = smooth_field.exact_norms(modelisation, contact=contact)
            print(f"exact norms ({'contact' if contact else 'open'}, {modelisation}, E=1e8, NU=0.3): "
                  f"||u||_L2 = {l2!r}, energy = {energy!r}")
    print("check-field: " + ("FAILED" if failures else "OK"))
    return 1 if failures else 0


def fresh_folder(prefix):
    """A new folder in the current one, so that a run never overwrites earlier figures."""
    stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y%m%d-%H%M%S")
    path = os.path.abspath(f"{prefix}-{stamp}")
    n = 1
    while os.path.exists(path):
        n += 1
        path = os.path.abspath(f"{prefix}-{stamp}-{n}")
    return path


class Arguments(argparse.ArgumentParser):
    def error(self, message):
        """A usage error exits with 1, as every miniaster error does (argparse's 2 means NOOK here)."""
        self.print_usage(sys.stderr)
        self.exit(1, f"{self.prog}: error: {message}\n")


def main():
    ap = Arguments(prog="miniaster study", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("name", choices=["smooth", "stability", "penalty", "perf", "all", "check-field", "astest",
                                     "ssnv513e", "lame", "solvers", "cracks", "ssnp138a"])
    ap.add_argument("--full", action="store_true", help="the big grid (2D up to N=1001, perf at N=1001)")
    ap.add_argument("--out", default=None,
                    help="tables and plots (default: a fresh folder miniaster-study-<name>-<UTC time> in the "
                         "current folder; `--out docs/study` updates the committed figures; astest reads "
                         "docs/study/smooth.csv unless told otherwise)")
    ap.add_argument("--work", default=None, help="keep the runs in this folder (default: temporary, removed)")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--elements", default=None, help="comma-separated subset of quad4,tria3,hexa8,tetra4")
    ap.add_argument("--contact", default="all", choices=sorted(SMOOTH_PARTS),
                    help="smooth/astest: all rows, only the open scene (open) or only the rows with contact "
                         "(only); a partial run keeps the other rows of the existing smooth.csv")
    ap.add_argument("--group", default="all", choices=sorted(SMOOTH_GROUPS),
                    help="smooth: all rows, only the convergence grid and solvers (convergence) or only the "
                         "sub-cell quadrature rows (quadrature); a partial run keeps the other rows of smooth.csv")
    ap.add_argument("--settings", default=None,
                    help="solvers: comma-separated subset of the settings (e.g. 'CG+GAMG,CG+ML')")
    ap.add_argument("--scenes", default=None,
                    help="solvers: comma-separated subset of the scenes (ssnv511a, ssnv511e, 'hexa8 block')")
    ap.add_argument("--timeout", type=float, default=1800.0, help="seconds per run")
    args = ap.parse_args()
    if args.out is None:
        args.out = (os.path.join(ROOT, "docs", "study") if args.name == "astest" else
                    fresh_folder(f"miniaster-study-{args.name}"))
    if args.name == "check-field":
        return check_field()
    if args.name == "ssnv513e":  # refinement study of the family file (docs/family.md)
        import ssnv513e_refinement
        return ssnv513e_refinement.main(["--build", args.build, "--out", args.out])
    if args.name == "ssnp138a":  # refinement study of ssnp138a's inclined cracks (docs/cracks.md)
        import ssnp138a_refinement
        return ssnp138a_refinement.main(["--build", args.build, "--out", args.out])
    if args.name == "cracks":  # K and G of X-FEM cracks against closed forms (docs/cracks.md)
        import cracks
        return cracks.main(["--build", args.build, "--out", args.out])
    if args.name == "lame":  # the Lame ring with a circular interface in contact (docs/contact.md)
        import lame_ring
        return lame_ring.main(["--build", args.build, "--out", args.out])
    ctx = Context(args)
    if not os.path.exists(ctx.binary):
        sys.exit(f"study: {ctx.binary} not found (build first)")
    try:
        if args.name in ("smooth", "all"):
            study_smooth(ctx)
        if args.name in ("stability", "all"):
            study_stability(ctx)
        if args.name in ("penalty", "all"):
            study_penalty(ctx)
        if args.name in ("perf", "all"):
            study_perf(ctx)
        if args.name == "astest":
            study_astest(ctx)
        if args.name == "solvers":  # SOLVEUR settings (docs/solver.md)
            import solvers
            solvers.study_solvers(ctx)
    finally:
        ctx.finish()
    print(f"study {args.name}: tables and plots in {ctx.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
