#!/usr/bin/python3
"""The miniaster half of the 3D side by side on a small box, as a ctest (bench3d.miniaster_n4).

usage: check_miniaster.py MINIASTER_BINARY SSNV511_MESH WORK_DIR [N]

Writes the N x N x N HEXA8 mesh of refined_c.comm (interior grid lines moved by half a cell for
even N, as sidebyside3d.sh does), runs `MINIASTER_BINARY run` on refined_c.comm and checks:
- exit status 0;
- POST_ERREUR's relative L2 error against the rigid-block field below 1e-12;
- miniaster's active displacement dofs (model dofs less the unused Heaviside slots) equal to the
  count of GetFEM's enriched space, 3 (N+1)^3 + 12 (N+1)(N+2) (README.md), and its .mess line
  names the four-block enrichment (every node next to the junction line carries 3 Heaviside slots).
"""
import shutil
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import sidebyside3d_report as rep  # noqa: E402
import scaling  # noqa: E402


def main():
    if len(sys.argv) not in (4, 5):
        print(__doc__, file=sys.stderr)
        return 2
    binary, mesher, work = sys.argv[1], sys.argv[2], Path(sys.argv[3])
    n = int(sys.argv[4]) if len(sys.argv) == 5 else 4
    offset = "0.5" if n % 2 == 0 else "0"
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    mesh = work / ("hexa_%d.med" % n)
    subprocess.run([mesher, "--type", "hexa8", "--n", str(n), "--layers", str(n), "--offset", offset, offset,
                    "-o", str(mesh)], check=True, stdout=subprocess.DEVNULL)
    shutil.copy(HERE / "refined_c.comm", work / "refined_c.comm")
    (work / "refined_c.export").write_text(
        "P time_limit 120\nP memory_limit 1024\nP ncpus 1\nP mpi_nbcpu 1\n\n"
        "F comm refined_c.comm D 1\nF mmed %s D 20\n" % mesh.name)
    out = work / "out"
    proc = subprocess.run([binary, "run", str(work / "refined_c.export"), "--out-dir", str(out)],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    failures = []
    if proc.returncode != 0:
        failures.append("exit status %d:\n%s" % (proc.returncode, proc.stdout[-2000:]))
    resu = out / "refined_c.resu"
    mess = out / "refined_c.mess"
    err = rep.resu_l2_error(resu.read_text()) if resu.is_file() else None
    facts = rep.mess_facts(mess.read_text()) if mess.is_file() else {}
    expected = scaling.dofs_of(n)
    print("N = %d: POST_ERREUR L2 relative error %s, active dofs %s (GetFEM's count %d), equations %s"
          % (n, err, facts.get("dofs_active"), expected, facts.get("equations")))
    if err is None or not err < 1e-12:
        failures.append("POST_ERREUR relative L2 error %s, expected < 1e-12" % err)
    if facts.get("dofs_active") != expected:
        failures.append("active dofs %s, expected 3 (N+1)^3 + 12 (N+1)(N+2) = %d" % (facts.get("dofs_active"), expected))
    junction_nodes = 4 * (n + 1)  # the 2 x 2 node columns around the junction line x = y = 0
    text = mess.read_text() if mess.is_file() else ""
    if "(%d with several Heaviside enrichments)" % junction_nodes not in text:
        failures.append("the .mess does not report %d nodes with several Heaviside enrichments" % junction_nodes)
    for f in failures:
        print("FAILED: " + f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
