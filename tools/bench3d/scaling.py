#!/usr/bin/python3
"""Growth of GetFEM's (and miniaster's) time and memory on the refined ssnv511c scene, fitted on
small sidebyside3d.sh runs, and the N that gives a target number of dofs.

usage: scaling.py [--target DOFS ...] RUN_DIR [RUN_DIR ...]

Each RUN_DIR is a sidebyside3d.sh run folder (different N). For every phase of GetFEM's JSON
(t_phases_s), its total, its peak RSS above the interpreter's own start (RSS - BASE_MB) and the
wall / peak RSS of both tools under /usr/bin/time, fits t = a * dofs^p on the median over the
repetitions (least squares in log-log) and extrapolates to the targets. Dofs are the displacement
dofs, enriched ones included (the same for both tools): 3 (N+1)^3 + 12 (N+1)(N+2) on the
N x N x N box with the interfaces inside cells (README.md).
"""
import argparse
import json
import math
import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import sidebyside3d_report as rep  # noqa: E402

BASE_MB = 60.0  # python3 + getfem imported, before any mesh


def dofs_of(n):
    return 3 * (n + 1) ** 3 + 12 * (n + 1) * (n + 2)


def n_for(dofs, odd=True):
    n = 1
    while dofs_of(n) < dofs:
        n += 1
    if odd and n % 2 == 0:
        n += 1
    return n


def fit(xs, ys):
    """(a, p) of y = a x^p, least squares in log-log; None with fewer than 2 positive points."""
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x and y and y > 0]
    if len(pts) < 2:
        return None
    mx = statistics.mean(p[0] for p in pts)
    my = statistics.mean(p[1] for p in pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    p = sum((q[0] - mx) * (q[1] - my) for q in pts) / sxx
    return math.exp(my - p * mx), p


def collect(run_dirs):
    """{series name: {dofs: median value}}"""
    series = {}

    def put(name, dofs, vals):
        vals = [v for v in vals if v is not None]
        if dofs and vals:
            series.setdefault(name, {})[dofs] = statistics.median(vals)

    for d in map(Path, run_dirs):
        info = rep.read_info(d)
        reps = int(info.get("reps", "1"))
        gf = []
        for i in range(1, reps + 1):
            try:
                lines = [ln for ln in (d / f"gf_{i}.json").read_text().splitlines() if ln.startswith("{")]
                gf.append(json.loads(lines[-1]))
            except (OSError, ValueError, IndexError):
                pass
        if gf:
            dofs = gf[0]["dofs"]
            for phase in gf[0]["t_phases_s"]:
                put("GetFEM " + phase + " [s]", dofs, [j["t_phases_s"].get(phase) for j in gf])
            put("GetFEM t_total [s]", dofs, [j["t_total_s"] for j in gf])
            put("GetFEM peak RSS - %g MB [MB]" % BASE_MB, dofs, [j["peak_rss_mb"] - BASE_MB for j in gf])
            put("GetFEM wall [s]", dofs, [rep.parse_time_v(d / f"gf_{i}.time")[0] for i in range(1, reps + 1)])
        if info.get("miniaster") == "yes":
            row, _ = rep.miniaster_row(d, reps)
            put("miniaster wall [s]", row["dofs"], [rep.parse_time_v(d / f"mini_{i}.time")[0]
                                                   for i in range(1, reps + 1)])
            put("miniaster peak RSS [MB]", row["dofs"], [rep.parse_time_v(d / f"mini_{i}.time")[1]
                                                        for i in range(1, reps + 1)])
    return series


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--target", type=float, action="append", help="dofs to extrapolate to (default 4e5, 2e6)")
    ap.add_argument("runs", nargs="+")
    args = ap.parse_args()
    targets = args.target or [4e5, 2e6]
    series = collect(args.runs)
    if not series:
        print("scaling.py: no GetFEM JSON or miniaster run found", file=sys.stderr)
        return 1
    print("targets: " + ", ".join("%.3g dofs -> N = %d (odd; %d dofs)" % (t, n_for(t), dofs_of(n_for(t)))
                                  for t in targets))
    head = "| series | " + " | ".join("%d dofs" % k for k in sorted({k for s in series.values() for k in s})) \
        + " | exponent p | " + " | ".join("at %d dofs" % dofs_of(n_for(t)) for t in targets) + " |"
    all_dofs = sorted({k for s in series.values() for k in s})
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    phase_sum = [0.0] * len(targets)
    for name, pts in series.items():
        f = fit(list(pts), list(pts.values()))
        cells = ["%.3g" % pts[k] if k in pts else "-" for k in all_dofs]
        ext = [f[0] * dofs_of(n_for(t)) ** f[1] if f else None for t in targets]
        if f and name.startswith("GetFEM ") and name.endswith(" [s]") and "total" not in name and "wall" not in name:
            phase_sum = [a + b for a, b in zip(phase_sum, ext)]
        print("| %s | %s | %s | %s |" % (name, " | ".join(cells), "%.2f" % f[1] if f else "-",
                                         " | ".join("-" if e is None else "%.3g" % e for e in ext)))
    print("| GetFEM sum of the phases' extrapolations [s] | %s | | %s |"
          % (" | ".join("" for _ in all_dofs), " | ".join("%.3g" % e for e in phase_sum)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
