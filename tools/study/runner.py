"""Runs one miniaster case and reads back what the run logged (.mess) and printed (.resu).

Everything is parsed from the documented log lines (docs/fe.md, docs/xfem.md, docs/supervisor.md):
the per-command TIMING SUMMARY, the engine's phase lines (numbering, matrix pattern, assembly,
factorisation, solve, Newton), MUMPS condition estimates (INFO=2), the X-FEM conditioning and
sub-cell quadrature lines of MODI_MODELE_XFEM, alarms, and the POST_ERREUR tables printed by
IMPR_TABLE.
"""
import math
import os
import re
import subprocess
import time

NUM = r"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|nan|inf)"

# command -> phase of the study tables
PHASES = {
    "LIRE_MAILLAGE": "mesh", "DEFI_GROUP": "mesh",
    "DEFI_FISS_XFEM": "xfem", "MODI_MODELE_XFEM": "xfem",
    "AFFE_MODELE": "setup", "DEFI_MATERIAU": "setup", "AFFE_MATERIAU": "setup", "FORMULE": "setup",
    "AFFE_CHAR_MECA": "setup", "AFFE_CHAR_MECA_F": "setup", "DEFI_LIST_REEL": "setup", "DEFI_FONCTION": "setup",
    "DEFI_CONTACT": "setup", "DEBUT": "setup",
    "MECA_STATIQUE": "analysis", "STAT_NON_LINE": "analysis",
    "CREA_CHAMP": "post", "POST_ERREUR": "post", "IMPR_TABLE": "post", "POST_MAIL_XFEM": "post",
    "POST_CHAM_XFEM": "post", "POST_RELEVE_T": "post", "CALC_TABLE": "post", "TEST_TABLE": "post", "FIN": "post",
}


def _f(s):
    return float(s)


def parse_mess(text):
    """Numbers of one run's message log; missing items are absent from the dict."""
    r = {}
    m = re.search(r"model \S+: .*?(\d+) dofs .*?set-up " + NUM + " s", text)
    if m:
        r["dofs"] = int(m.group(1))
        r["t_numbering"] = _f(m.group(2))
    m = re.search(r"matrix pattern: (\d+) equations \((\d+) free dofs, (\d+) eliminated, (\d+) multipliers\), "
                  r"(\d+) non-zeros, " + NUM + " s", text)
    if m:
        r["equations"], r["free_dofs"], r["eliminated"], r["multipliers"], r["nonzeros"] = map(int, m.groups()[:5])
        r["t_pattern"] = _f(m.group(6))
    assembly = re.findall(r"stiffness assembled: .*?" + NUM + r" s \(cpu", text)
    if assembly:
        r["t_assembly"] = sum(map(_f, assembly))
        r["assemblies"] = len(assembly)
    # MUMPS: the ordering line, then per factorisation "MUMPS factorisation T s: F flops ..., factor
    # entries = E, peak memory M MB (INFOG(22)); analysis + factorisation T s" (t_factorisation
    # counts the analysis, the ordering included, as before the two were logged apart).
    orderings = re.findall(r"MUMPS \(.*?\): n = \d+, non-zeros \(upper triangle\) = \d+, ordering (\S+)", text)
    fact = re.findall(r"MUMPS factorisation " + NUM + r" s: (\S+) flops .*?factor entries = (\d+), peak memory (\d+) MB"
                      r" \(INFOG\(22\)\); analysis \+ factorisation " + NUM + r" s", text)
    if fact:
        r["ordering"] = orderings[0] if orderings else "?"
        r["factor_entries"] = int(fact[0][2])
        r["flops"] = _f(fact[0][1])
        r["t_factorisation"] = sum(_f(f[4]) for f in fact)
        r["t_mumps_factorisation"] = sum(_f(f[0]) for f in fact)
        r["solver_peak_mb"] = max(int(f[3]) for f in fact)
        r["factorisations"] = len(fact)
    metis = re.findall(r"METIS_NodeND on the matrix graph .*? edges\) " + NUM + " s", text)
    if metis:
        r["t_ordering"] = sum(map(_f, metis))
    eig = re.findall(r"Eigen (\S+) \((.*?)\): n = \d+.*?factorisation " + NUM + " s", text)
    if eig:
        r["ordering"] = eig[0][1].split(",")[0] if eig[0][1] else eig[0][0]
        r["t_factorisation"] = r.get("t_factorisation", 0.0) + sum(_f(e[2]) for e in eig)
        r["factorisations"] = r.get("factorisations", 0) + len(eig)
    solves = re.findall(r"(?:MUMPS|Eigen\S*|\w+) solve " + NUM + r" s, relative residual \|\|Ku-f\|\|/\|\|f\|\| = " + NUM,
                        text)
    if solves:
        r["t_solve"] = sum(_f(s[0]) for s in solves)
        r["solves"] = len(solves)
        r["residual"] = max(_f(s[1]) for s in solves)
    m = re.findall(r"cond1 = " + NUM + ", cond2 = " + NUM, text)
    if m:
        r["cond1"] = max(_f(c[0]) for c in m)
        r["cond2"] = max(_f(c[1]) for c in m)
    m = re.search(r"diagonal scaling D\^-1/2 K D\^-1/2: \|K_ii\| from " + NUM + " to " + NUM, text)
    if m:
        r["diag_ratio"] = _f(m.group(1)) / _f(m.group(2)) if _f(m.group(2)) > 0 else float("nan")
    contact = re.findall(r"increment \d+ \(INST [^)]*\): (\d+) contact iteration", text)
    if contact:
        r["contact_iterations"] = sum(int(c) for c in contact)
    m = re.findall(r"largest interpenetration " + NUM, text)
    if m:
        r["penetration"] = max(_f(x) for x in m)
    newton = re.findall(r"converged after (\d+) iteration", text)
    if newton:
        r["newton"] = sum(int(n) for n in newton)
    m = re.search(r"smallest retained enrichment support fraction " + NUM + r" \(criterion " + NUM + r"\), (\d+) enrichment",
                  text)
    if m:
        r["min_fraction"] = _f(m.group(1))
        r["dropped"] = int(m.group(3))
    # sub-cell rules of MODI_MODELE_XFEM (catalogue or --subcell-quadrature) and their points
    m = re.search(r"sub-cell quadrature: (catalogue|degree \d+)", text)
    if m:
        r["quadrature"] = m.group(1)
    m = re.search(r"sub-cell integration points: (\d+) \(volume (\d+) in (\d+) elements, skin (\d+) in (\d+)\)",
                  text)
    if m:
        r["subcell_points"] = int(m.group(2))
        r["xfem_volume_cells"] = int(m.group(3))
        r["skin_points"] = int(m.group(4))
    m = re.findall(r"(\d+) level-set values adjusted", text)
    if m:
        r["snapped"] = sum(int(x) for x in m)
    alarms = [a for a in re.findall(r"! <A> <(\w+)>", text) if not a.startswith("TEST0_")]
    r["alarms"] = " ".join(sorted(set(alarms)))
    # per-command timing summary
    summary = text.split("TIMING SUMMARY", 1)
    phases = {}
    if len(summary) == 2:
        for line in summary[1].splitlines():
            m = re.match(r"\s+([A-Z_]+)\s+(\d+)\s+" + NUM + r"\s+" + NUM + r"\s*$", line)
            if m:
                cmd = m.group(1)
                phases[PHASES.get(cmd, "other")] = phases.get(PHASES.get(cmd, "other"), 0.0) + _f(m.group(3))
                r[f"cmd_{cmd}"] = _f(m.group(3))
            m = re.match(r"\s+TOTAL \(commands\)\s+" + NUM + r"\s+" + NUM, line)
            if m:
                r["t_commands"] = _f(m.group(1))
                r["peak_mb"] = _f(m.group(2))
    # Set-up kind of commands run after the analysis (AFFE_MODELE of a visualisation model, as in
    # ssnv511a.comm) are post-processing: moved there from the per-command totals.
    ends = re.findall(r"# end of ([A-Z_]+) \(line \d+\): elapsed " + NUM + " s", text)
    last_analysis = max((i for i, (cmd, _) in enumerate(ends) if PHASES.get(cmd) == "analysis"), default=None)
    if last_analysis is not None:
        for cmd, t in ends[last_analysis + 1:]:
            phase = PHASES.get(cmd, "other")
            if phase in ("mesh", "xfem", "setup") and phase in phases:
                phases[phase] -= _f(t)
                phases["post"] = phases.get("post", 0.0) + _f(t)
    for k, v in phases.items():
        r[f"t_{k}"] = v
    # what the analysis command spent besides numbering, pattern, assembly, factorisation and solve
    # (external forces incl. FORMULE evaluation, residuals, stresses)
    if "t_analysis" in r:
        inner = sum(r.get(k, 0.0) for k in ("t_numbering", "t_pattern", "t_assembly", "t_factorisation", "t_solve"))
        r["t_analysis_other"] = max(0.0, r["t_analysis"] - inner)
    m = re.search(r"DIAGNOSTIC JOB : (\S+)", text)
    r["diagnostic"] = m.group(1) if m else "none"
    m = re.search(r"<F> <[A-Z_]+> (.*)", text)
    if m:
        r["failure"] = m.group(1)[:200]
    return r


def parse_tests(text):
    """TEST_RESU / TEST_TABLE lines of a .resu: counts of OK and NOOK checks, per reference kind
    (NON_REGRESSION, ANALYTIQUE, ...) -> tests_ok, tests_nook, tests (e.g. 'ANALYTIQUE 6/18, NON_REGRESSION 16/16')."""
    counts = {}
    for line in text.splitlines():
        m = re.match(r"\s*(OK|NOOK)\s+([A-Z_]+)\s", line)
        if m:
            ok, total = counts.get(m.group(2), (0, 0))
            counts[m.group(2)] = (ok + (m.group(1) == "OK"), total + 1)
    r = {}
    if counts:
        r["tests_ok"] = sum(c[0] for c in counts.values())
        r["tests_nook"] = sum(c[1] - c[0] for c in counts.values())
        r["tests"] = ", ".join(f"{k} {ok}/{total} OK" for k, (ok, total) in sorted(counts.items()))
    return r


def parse_error_tables(text):
    """POST_ERREUR tables printed by IMPR_TABLE: TOTAL rows of the L2 (DEPL_RELA) and energy
    (ENER_RELA) tables -> l2_diff, l2_ref, energy_diff, energy_ref, and the relative errors
    l2_rel = diff/ref, energy_rel = sqrt(diff/ref) (energy norm)."""
    r = {}
    current = None
    for line in text.splitlines():
        if "NORME ENERGIE" in line:
            current = "energy"
        elif "NORME L2" in line:
            current = "l2"
        tok = line.split()
        if current and tok and tok[0] == "TOTAL" and len(tok) >= 3:
            try:
                r[f"{current}_diff"], r[f"{current}_ref"] = float(tok[1]), float(tok[2])
            except ValueError:
                pass
            current = None
    if r.get("l2_ref", 0) > 0:
        r["l2_rel"] = r["l2_diff"] / r["l2_ref"]
    if r.get("energy_ref", 0) > 0:
        r["energy_rel"] = math.sqrt(max(r["energy_diff"], 0.0) / r["energy_ref"])
    return r


def make_mesh(build, element, n, path, bounds=None, zbounds=None, offset=None, layers=None):
    cmd = [os.path.join(build, "tools", "ssnv511_mesh"), "--type", element, "--n", str(n), "-o", path]
    if bounds:
        cmd += ["--bounds"] + [repr(float(b)) for b in bounds]
    if zbounds:
        cmd += ["--zbounds"] + [repr(float(z)) for z in zbounds]
    if offset:
        cmd += ["--offset"] + [repr(float(o)) for o in offset]
    if layers:
        cmd += ["--layers", str(int(layers))]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def run_comm_file(binary, comm, mesh, workdir, timeout=900):
    """Runs an existing command file where it is (`miniaster run comm --mesh mesh`, outputs in
    workdir); returns the parsed record as run_case, plus the TEST counts of its .resu."""
    os.makedirs(workdir, exist_ok=True)
    name = os.path.splitext(os.path.basename(comm))[0]
    t0 = time.monotonic()
    try:
        proc = subprocess.run([binary, "run", comm, "--mesh", mesh, "--out-dir", workdir], stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL, timeout=timeout)
        rc = proc.returncode
    except subprocess.TimeoutExpired:
        rc = "timeout"
    rec = {"exit": rc, "wall": time.monotonic() - t0}
    for ext, parse in ((".mess", parse_mess), (".mess", parse_error_tables), (".resu", parse_tests)):
        path = os.path.join(workdir, name + ext)
        if os.path.exists(path):
            with open(path, errors="replace") as f:
                rec.update(parse(f.read()))
    return rec


def run_case(binary, comm_text, mesh, workdir, name, timeout=900, options=()):
    """Runs `miniaster run name.comm --mesh mesh [options]` in workdir; returns the parsed record
    (exit status, wall time seen from outside, everything from the .mess and the error tables).
    `options`: extra run options, e.g. ("--subcell-quadrature", "2")."""
    os.makedirs(workdir, exist_ok=True)
    comm = os.path.join(workdir, name + ".comm")
    with open(comm, "w") as f:
        f.write(comm_text)
    t0 = time.monotonic()
    try:
        proc = subprocess.run([binary, "run", comm, "--mesh", mesh, "--out-dir", workdir, *options],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=timeout)
        rc = proc.returncode
    except subprocess.TimeoutExpired:
        rc = "timeout"
    wall = time.monotonic() - t0
    rec = {"exit": rc, "wall": wall}
    mess = os.path.join(workdir, name + ".mess")
    if os.path.exists(mess):
        with open(mess, errors="replace") as f:
            text = f.read()
        rec.update(parse_mess(text))
        rec.update(parse_error_tables(text))
    return rec
