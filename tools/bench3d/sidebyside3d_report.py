#!/usr/bin/python3
"""Table of a sidebyside3d.sh run (called by it; also usable on an old run folder).

usage: sidebyside3d_report.py RUN_DIR
       sidebyside3d_report.py --selftest

RUN_DIR holds info.txt (key=value lines written by sidebyside3d.sh) and, per repetition i:
  mini_<i>.time, mini_<i>/   miniaster: `/usr/bin/time -v -o` output, --out-dir (.mess, .resu)
  gf_<i>.time, gf_<i>.json   GetFEM: `/usr/bin/time -v -o` output, its JSON line on stdout

Dofs: GetFEM's `dofs` is its enriched displacement space (every Q1 function whose support is cut
has one copy per zone it meets); miniaster's `active dofs` are its model's dofs less the Heaviside
slots no element uses (code_aster keeps H1..H3 on every node of a junction element and pins the
unused ones to 0), which counts the same functions. The systems differ: GetFEM adds Lagrange
multipliers for the Dirichlet faces and factors displacement + multipliers; miniaster eliminates
the imposed dofs and factors the free ones ('equations').
"""
import json
import re
import statistics
import sys
from pathlib import Path

NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?"


def parse_time_v(path):
    """(wall s, peak RSS MB, exit status) of a `/usr/bin/time -v -o path` file."""
    try:
        text = Path(path).read_text(errors="replace")
    except OSError:
        return None, None, None
    wall = rss = status = None
    for line in text.splitlines():
        line = line.strip()
        if line.startswith("Elapsed (wall clock) time"):
            secs = 0.0
            for part in line.rsplit(": ", 1)[-1].split(":"):
                secs = secs * 60 + float(part)
            wall = secs
        elif line.startswith("Maximum resident set size"):
            rss = int(line.rsplit(":", 1)[-1]) / 1024.0
        elif line.startswith("Exit status:"):
            status = int(line.rsplit(":", 1)[-1])
        elif line.startswith("Command terminated by signal"):
            status = 128 + int(re.findall(r"\d+", line)[0])
    return wall, rss, status


def resu_l2_error(text):
    """'ERREUR RELATIVE' of the TOTAL row of the first table that has that column, else None."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if not re.search(r"ERREUR[ _]RELATIVE", line):
            continue
        for row in lines[i + 1:]:
            toks = [t.strip("'\"") for t in re.split(r"[\s|,;]+", row.strip()) if t]
            if not toks or row.lstrip().startswith("#"):
                break
            if toks[0].upper() == "TOTAL" and re.fullmatch(NUM, toks[-1]):
                return float(toks[-1].replace("D", "E").replace("d", "e"))
    return None


def mess_facts(text):
    """Dofs, system size and timings that miniaster's .mess reports for the MECA_STATIQUE."""
    facts = {}
    m = re.search(r"model \S+: .*?(\d+) dofs \(components", text)
    if m:
        facts["dofs_model"] = int(m.group(1))
    m = re.search(r"(\d+) inactive Heaviside slots", text)
    if m and "dofs_model" in facts:
        facts["dofs_active"] = facts["dofs_model"] - 3 * int(m.group(1))  # 3 components a slot
    m = re.search(r"matrix pattern: (\d+) equations", text)
    if m:
        facts["equations"] = int(m.group(1))
    for cmd in ("MECA_STATIQUE", "MODI_MODELE_XFEM", "POST_ERREUR", "LIRE_MAILLAGE"):
        m = re.search(r"^\s*%s\s+\d+\s+(%s)\s+(%s)\s*$" % (cmd, NUM, NUM), text, re.M)
        if m:
            facts["t_" + cmd] = float(m.group(1))
    m = re.search(r"^\s*TOTAL \(commands\)\s+(%s)\s+(%s)" % (NUM, NUM), text, re.M)
    if m:
        facts["t_commands"] = float(m.group(1))
    return facts


def med(vals):
    vals = [v for v in vals if v is not None]
    return statistics.median(vals) if vals else None


def fmt(v, spec):
    return "-" if v is None else format(v, spec)


def read_info(run):
    info = {}
    path = run / "info.txt"
    if path.exists():
        for line in path.read_text().splitlines():
            if "=" in line:
                k, v = line.split("=", 1)
                info[k.strip()] = v.strip()
    return info


def miniaster_row(run, reps):
    walls, rsss, per, facts, l2 = [], [], [], {}, None
    for i in range(1, reps + 1):
        w, r, st = parse_time_v(run / f"mini_{i}.time")
        summed = run / f"mini_{i}.rss"  # several MPI processes: the sum of their peaks (tree_rss.py)
        if summed.exists():
            r = float(summed.read_text().split()[0])
        out = run / f"mini_{i}"
        err = None
        for resu in sorted(out.glob("*.resu")):
            err = resu_l2_error(resu.read_text(errors="replace"))
        for mess in sorted(out.glob("*.mess")):
            facts = mess_facts(mess.read_text(errors="replace")) or facts
        per.append(f"#{i}: {fmt(w, '.2f')} s, {fmt(r, '.0f')} MB, exit {st}"
                   + ("" if err is not None else ", no ERREUR RELATIVE found"))
        if st == 0:
            walls.append(w)
            rsss.append(r)
            l2 = err if err is not None else l2
    row = dict(tool="miniaster", ok=len(walls), wall=med(walls), wmin=min(walls, default=None),
               wmax=max(walls, default=None), rss=med(rsss), l2=l2, maxerr=None,
               dofs=facts.get("dofs_active"), system=facts.get("equations"), internal=facts.get("t_commands"))
    note = "miniaster runs: " + "; ".join(per)
    if facts:
        note += (f" | model dofs {facts.get('dofs_model')} (active {facts.get('dofs_active')}),"
                 f" equations {facts.get('equations')}; last run: MECA_STATIQUE {fmt(facts.get('t_MECA_STATIQUE'), '.2f')} s,"
                 f" MODI_MODELE_XFEM {fmt(facts.get('t_MODI_MODELE_XFEM'), '.2f')} s,"
                 f" POST_ERREUR {fmt(facts.get('t_POST_ERREUR'), '.2f')} s")
    return row, note


def getfem_row(run, reps):
    walls, rsss, internal, per, js = [], [], [], [], {}
    for i in range(1, reps + 1):
        w, r, st = parse_time_v(run / f"gf_{i}.time")
        j = None
        try:
            lines = [ln for ln in (run / f"gf_{i}.json").read_text().splitlines() if ln.startswith("{")]
            j = json.loads(lines[-1]) if lines else None
        except (OSError, ValueError):
            j = None
        per.append(f"#{i}: {fmt(w, '.2f')} s, {fmt(r, '.0f')} MB, exit {st}"
                   + (f", t_total {j.get('t_total_s')} s" if j else ", no JSON"))
        if st == 0 and j:
            walls.append(w)
            rsss.append(r)
            internal.append(j.get("t_total_s"))
            js = j
    row = dict(tool="GetFEM", ok=len(walls), wall=med(walls), wmin=min(walls, default=None),
               wmax=max(walls, default=None), rss=med(rsss), l2=js.get("err_rel_l2"),
               maxerr=js.get("err_max_disp"), dofs=js.get("dofs"), system=js.get("dofs_total"),
               internal=med(internal))
    note = "GetFEM runs: " + "; ".join(per)
    if js:
        note += (f" | dofs {js.get('dofs')} + {js.get('dofs_multipliers')} multipliers, nodes by copies"
                 f" {js.get('nodes_by_copies')}, last run phases {js.get('t_phases_s')}, BLAS {js.get('blas')}")
    return row, note


def print_table(rows, reps):
    head = ["tool", "ok", "wall median [s]", "(min-max)", "peak RSS median [MB]", "rel. error L2",
            "max disp. error", "displ. dofs", "system size", "internal total [s]"]
    table = [head]
    for r in rows:
        table.append([r["tool"], f"{r['ok']}/{reps}", fmt(r["wall"], ".2f"),
                      f"{fmt(r['wmin'], '.2f')}-{fmt(r['wmax'], '.2f')}", fmt(r["rss"], ".0f"),
                      fmt(r["l2"], ".3e"), fmt(r["maxerr"], ".3e"), fmt(r["dofs"], "d"),
                      fmt(r["system"], "d"), fmt(r["internal"], ".3f")])
    if len(rows) == 2:
        m, g = rows

        def ratio(a, b, spec=".2f"):
            return "-" if a is None or b is None or b == 0 else format(a / b, spec)
        table.append(["GetFEM/miniaster", "", ratio(g["wall"], m["wall"]), "", ratio(g["rss"], m["rss"]),
                      ratio(g["l2"], m["l2"], ".3g"), "", ratio(g["dofs"], m["dofs"], ".3f"),
                      ratio(g["system"], m["system"], ".3f"), ratio(g["internal"], m["internal"])])
    widths = [max(len(row[c]) for row in table) for c in range(len(head))]
    print()
    for k, row in enumerate(table):
        print("| " + " | ".join(cell.ljust(widths[c]) for c, cell in enumerate(row)) + " |")
        if k == 0:
            print("|" + "|".join("-" * (w + 2) for w in widths) + "|")
    print()


def report(run_dir):
    run = Path(run_dir)
    info = read_info(run)
    reps = int(info.get("reps", "0")) or max([int(p.stem.split("_")[1]) for p in run.glob("*_*.time")] or [0])
    n = info.get("n", "?")
    rows, notes = [], []
    if info.get("miniaster", "no") == "yes":
        row, note = miniaster_row(run, reps)
        rows.append(row)
        notes.append(note)
    if info.get("getfem", "no") == "yes":
        row, note = getfem_row(run, reps)
        rows.append(row)
        notes.append(note)
    cells = f"{n}x{n}x{n}" if n != "?" else "?"
    print(f"\nssnv511c side by side (3D): N = {n} ({cells} HEXA8, box [-5,5]^2 x [0,{info.get('depth', '1')}],"
          f" grid offset {info.get('offset', '0')}), {reps} repetition(s) per tool"
          + (", alternating (miniaster, GetFEM)" if len(rows) == 2 else ""))
    for k in ("miniaster_solveur", "getfem_solver", "machine", "loadavg_start", "getfem_blas", "miniaster_blas",
              "work_dir"):
        side = k.split("_")[0]
        if k in info and (side not in ("miniaster", "getfem") or info.get(side) == "yes"):
            print(f"  {k.replace('_', ' ')}: {info[k]}")
    print_table(rows, reps)
    for line in notes:
        print("  " + line)
    for side in ("miniaster", "getfem"):
        if info.get(side, "no") != "yes":
            print(f"  {side} side not run: {info.get(side + '_reason', '')}")
    return 0 if rows and all(r["ok"] == reps for r in rows) else 1


SAMPLE_RESU = """
#--------------------------------------------------------------------------------
##ERREUR EN NORME L2 DU DEPLACEMENT
GROUP_MA DIFFERENCE   REFERENCE    ERREUR RELATIVE
VOLU      3.12900E-13  6.84653E+00    -
TOTAL     3.12900E-13  6.84653E+00     4.57020E-14
"""
SAMPLE_MESS = """
    model MODEL: 125 elements, 0 boundary elements, 216 nodes with unknowns, 1800 dofs (components DX DY DZ)
    X-FEM model with 3 interface(s): 120 enriched nodes, 216 inactive Heaviside slots
    matrix pattern: 864 equations (864 free dofs, 936 eliminated, 0 multipliers), 119808 non-zeros
  MECA_STATIQUE               1        0.180               84.0
  TOTAL (commands)                     0.375               84.9
"""


def selftest():
    assert resu_l2_error(SAMPLE_RESU) == 4.5702e-14
    f = mess_facts(SAMPLE_MESS)
    assert f == {"dofs_model": 1800, "dofs_active": 1152, "equations": 864, "t_MECA_STATIQUE": 0.18,
                 "t_commands": 0.375}, f
    print("selftest OK")
    return 0


def main():
    args = sys.argv[1:]
    if args == ["--selftest"]:
        return selftest()
    if len(args) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    return report(args[0])


if __name__ == "__main__":
    sys.exit(main())
