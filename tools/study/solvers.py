"""`./miniaster study solvers`: time, peak memory and POST_ERREUR error of each SOLVEUR setting
(docs/solver.md) on the refined ssnv511a scene (rigid blocks, MECA_STATIQUE), the refined ssnv511e
scene (compression with contact, STAT_NON_LINE) and a 3D HEXA8 block N x N x N (the rigid scene);
a table (solvers.csv, solvers.md) and a plot of time against error (solvers_time_vs_error.png)."""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import report  # noqa: E402
import runner  # noqa: E402
import scenes  # noqa: E402

# label -> SOLVEUR keywords. RESI_RELA=1e-12 for the Krylov settings that aim at the direct solver's
# accuracy (POST_ERREUR <= 1e-9); 'CG+GAMG 1e-8' shows what a looser tolerance buys.
KRYLOV = {
    "FGMRES+LDLT_SP": "METHODE='PETSC', PRE_COND='LDLT_SP', RESI_RELA=1e-12",
    "CG+GAMG": "METHODE='PETSC', ALGORITHME='CG', PRE_COND='GAMG', RESI_RELA=1e-12",
    "CG+BOOMER": "METHODE='PETSC', ALGORITHME='CG', PRE_COND='BOOMER', RESI_RELA=1e-12",
    "CG+ML": "METHODE='PETSC', ALGORITHME='CG', PRE_COND='ML', RESI_RELA=1e-12",
}
SETTINGS = {
    "ssnv511a": {"MUMPS": "METHODE='MUMPS'", **KRYLOV,
                 "GCPC+LDLT_INC": "METHODE='GCPC', PRE_COND='LDLT_INC', RESI_RELA=1e-12",
                 "CG+GAMG 1e-8": "METHODE='PETSC', ALGORITHME='CG', PRE_COND='GAMG', RESI_RELA=1e-8"},
    # STAT_NON_LINE: MIXER_PRECISION exists there only (code_aster's catalogue).
    "ssnv511e": {"MUMPS": "METHODE='MUMPS'", "MUMPS mixed": "METHODE='MUMPS', MIXER_PRECISION='OUI'",
                 "FGMRES+LDLT_SP": KRYLOV["FGMRES+LDLT_SP"], "CG+GAMG": KRYLOV["CG+GAMG"],
                 "GCPC+LDLT_INC": "METHODE='GCPC', PRE_COND='LDLT_INC', RESI_RELA=1e-12"},
    "hexa8 block": {"MUMPS": "METHODE='MUMPS'", **KRYLOV},
}
COLUMNS = ["scene", "N", "setting", "solveur", "dofs", "exit", "wall", "t_commands", "t_solver", "iterations",
           "peak_mb", "l2_rel", "load", "failure"]


def grid(full):
    """2D N and 3D N (the block has N x N x N HEXA8)."""
    return ([251, 501, 1001] if full else [101, 251]), ([16, 24, 32] if full else [8, 12, 20])


def solver_seconds(mess):
    """Factorisation + solves, or the Krylov solves and preconditioner set-ups, from the .mess."""
    import re
    built = [float(x) for x in re.findall(r"preconditioner built in ([0-9.]+) s", mess)]
    if built:  # Krylov: the set-ups (MUMPS's factorisation of LDLT_SP included) and the Krylov solves
        return sum(built) + sum(float(x) for x in re.findall(r"\) solve ([0-9.]+) s:", mess)), \
            sum(int(x) for x in re.findall(r"solve [0-9.]+ s: (\d+) iterations", mess))
    t = sum(float(x) for x in re.findall(r"analysis \+ factorisation ([0-9.]+) s", mess))
    t += sum(float(x) for x in re.findall(r"solve ([0-9.]+) s,", mess))
    its = sum(int(x) for x in re.findall(r"solve [0-9.]+ s: (\d+) iterations", mess))
    steps = sum(int(x) for x in re.findall(r"after (\d+) refinement step", mess))
    return t, its if its else steps


def run_one(ctx, scene, n, label, keywords):
    if scene == "ssnv511a":
        comm, mesh = scenes.rigid_comm("quad4", solver=keywords, info=1), ctx.mesh("quad4", n)
    elif scene == "ssnv511e":
        comm, mesh = scenes.compression_comm("quad4", solver=keywords), ctx.mesh("quad4", n)
    else:
        comm = scenes.rigid_comm("hexa8", solver=keywords, info=1)
        mesh = ctx.mesh("hexa8", n, zbounds=(-5.0, 5.0), layers=n)
    load = os.getloadavg()[0]
    tag = f"solvers_{scene.replace(' ', '_')}_{n}_{label.replace(' ', '_').replace('+', '_')}"
    rec = ctx.run(tag, comm, mesh)
    mess_path = os.path.join(ctx.work, tag, "case.mess")
    if os.path.exists(mess_path):
        with open(mess_path, errors="replace") as f:
            rec["t_solver"], rec["iterations"] = solver_seconds(f.read())
    rec.update(scene=scene, N=n, setting=label, solveur=keywords, load=load)
    print(f"solvers {scene} N={n} {label}: exit {rec.get('exit')}, {rec.get('dofs')} dofs, "
          f"{rec.get('t_commands', float('nan')):.2f} s, {rec.get('peak_mb', float('nan')):.0f} MB, "
          f"L2 {rec.get('l2_rel', float('nan')):.2e}", flush=True)
    return rec


# One colour per setting in every panel.
LABELS = list(dict.fromkeys(label for settings in SETTINGS.values() for label in settings))
COLOURS = {label: plt.get_cmap("tab10")(i % 10) for i, label in enumerate(LABELS)}


def plot(path, records):
    scenes_run = sorted({r["scene"] for r in records})
    fig, axes = plt.subplots(1, len(scenes_run), figsize=(6 * len(scenes_run), 5.5), squeeze=False)
    for ax, scene in zip(axes[0], scenes_run):
        for label in SETTINGS[scene]:
            pts = sorted((float(r["t_commands"]), float(r["l2_rel"]), int(r["N"])) for r in records
                         if r["scene"] == scene and r["setting"] == label and r.get("l2_rel") and r.get("t_commands"))
            if pts:
                ax.loglog([p[0] for p in pts], [max(p[1], 1e-17) for p in pts], "o-", label=label,
                          color=COLOURS[label])
                for t, e, n in pts:
                    ax.annotate(f"N={n}", (t, max(e, 1e-17)), fontsize=6)
        ax.axhline(1e-9, color="grey", ls=":", lw=1)
        ax.set_xlabel("wall time of the commands (s)")
        ax.set_ylabel("POST_ERREUR relative L2 error")
        ax.set_title(scene)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def study_solvers(ctx):
    n2, n3 = grid(ctx.args.full)
    records = []
    wanted = ctx.args.settings.split(",") if ctx.args.settings else None
    scenes_wanted = ctx.args.scenes.split(",") if ctx.args.scenes else None
    for scene, ns in (("ssnv511a", n2), ("ssnv511e", n2), ("hexa8 block", n3)):
        if scenes_wanted and scene not in scenes_wanted:
            continue
        for n in ns:
            for label, keywords in SETTINGS[scene].items():
                if wanted and label not in wanted:
                    continue
                # hypre's BoomerAMG took 206 s at ssnv511a N = 251 (GAMG: 16 s): the small grid runs it
                # on its smallest N only.
                if "BOOMER" in label and not ctx.args.full and n != ns[0]:
                    continue
                records.append(run_one(ctx, scene, n, label, keywords))
    write_outputs(ctx.out, ctx.header("SOLVEUR settings: time, memory and error (docs/solver.md)"), records)
    return records


def write_outputs(out, header, records):
    report.write_csv(os.path.join(out, "solvers.csv"), records, COLUMNS)
    plot(os.path.join(out, "solvers_time_vs_error.png"), records)
    md = header
    md += ("Scenes: `ssnv511a` = tools/study/scenes.py `rigid_comm('quad4')` (MECA_STATIQUE) on QUAD4 N x N; "
           "`ssnv511e` = `compression_comm('quad4')` (STAT_NON_LINE with contact) on QUAD4 N x N; `hexa8 block` = "
           "`rigid_comm('hexa8')` on HEXA8 N x N x N ([-5,5]^3). `wall` is seen from outside, `t_commands` the "
           "TIMING SUMMARY total, `t_solver` the factorisations + solves (or preconditioner set-ups + Krylov "
           "solves) from the .mess, `iterations` the Krylov iterations (or the refinement steps of MUMPS), "
           "`peak_mb` the process's resident peak, `l2_rel` POST_ERREUR DEPL_RELA against the exact field, "
           "`load` the 1-minute load average at the start (2 shared cores). A run that stops on an error "
           "(exit 1: the solver's message names why) has no L2 error value, and its commands' total leaves out the "
           "command that failed: its wall time says what it cost.\n\n")
    md += report.markdown_table(records, [
        ("scene", "scene", None), ("N", "N", None), ("dofs", "DOFs", None), ("setting", "setting", None),
        ("exit", "exit", None), ("wall", "wall s", "t"), ("t_commands", "commands s", "t"), ("t_solver", "solver s", "t"),
        ("iterations", "iterations", None), ("peak_mb", "peak MB", "t"), ("l2_rel", "L2 rel. err.", "e"),
        ("load", "load", "f")])
    md += "\n![time against error](solvers_time_vs_error.png)\n"
    with open(os.path.join(out, "solvers.md"), "w") as f:
        f.write(md)
