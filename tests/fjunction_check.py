#!/usr/bin/python3
"""Invariants of the 3D F-junction cases (astest/fjunction_3d.comm, docs/family.md) read from the .mess
of their four ctest runs (fixture 'fjunction': astest.fjunction_{hexa8,tetra4}_n{7,13}).

  fjunction_check.py OUTDIR      OUTDIR/fjunction_<element>_n<N>/fjunction_<element>_n<N>.mess

Per run, the .comm makes two contact solves per slope (s = -0.15, 0.25, 0.7): (A) the uniform pressure,
(B) ssnv513g's stepped loads. At the converged contact iteration of each solve:
  * (A) no interpenetration: the largest penetration of the contact points is round-off (<= 1e-15 m);
  * (B) the contact points' largest penetration (the weak enforcement of Nitsche's method, an error of
    the discretisation) stays below 2e-3 m (2 % of the displacements p L / E = 0.1 m) and decreases from
    N = 7 to N = 13 on each element and slope (the convergence check);
  * every solve converged (0 status changes) within its ITER_CONT_MAXI = 10.
Prints one line per check and exits 1 on any failure.
"""
import os
import re
import sys

SLOPES = (-0.15, 0.25, 0.7)
LINE = re.compile(r"contact iteration (\d+): (\d+) status change\(s\).*?largest penetration ([-+0-9.e]+)")


def solves(mess):
    """[(iterations, penetration)] of each contact solve, in order: its last contact iteration."""
    out, last = [], None
    for m in LINE.finditer(mess):
        it, changed, penetration = int(m.group(1)), int(m.group(2)), float(m.group(3))
        if changed == 0:
            out.append((it, penetration))
        last = (it, changed)
    if last and last[1] != 0:
        out.append((last[0], float("nan")))  # a solve that never settled
    return out


def main():
    root = sys.argv[1]
    failures = 0

    def check(ok, text):
        nonlocal failures
        failures += 0 if ok else 1
        print(("OK   " if ok else "FAIL ") + text)

    penetration = {}
    for element in ("hexa8", "tetra4"):
        for n in (7, 13):
            name = f"fjunction_{element}_n{n}"
            with open(os.path.join(root, name, name + ".mess")) as f:
                found = solves(f.read())
            check(len(found) == 2 * len(SLOPES), f"{name}: {len(found)} converged contact solves of {2 * len(SLOPES)}")
            for k, (iterations, pen) in enumerate(found[: 2 * len(SLOPES)]):
                slope, case = SLOPES[k // 2], "AB"[k % 2]
                check(iterations <= 10, f"{name} s={slope} ({case}): converged in {iterations} contact iteration(s)")
                if case == "A":
                    check(pen <= 1e-15, f"{name} s={slope} (A): largest penetration {pen:.3e} m (round-off)")
                else:
                    check(pen < 2e-3, f"{name} s={slope} (B): largest penetration {pen:.3e} m < 2e-3 m")
                    penetration[(element, n, slope)] = pen
    for element in ("hexa8", "tetra4"):
        for slope in SLOPES:
            coarse, fine = penetration.get((element, 7, slope)), penetration.get((element, 13, slope))
            if coarse is None or fine is None:
                continue
            check(fine < coarse, f"{element} s={slope} (B): penetration N=7 {coarse:.3e} -> N=13 {fine:.3e} m")
    print("fjunction invariants: " + ("FAILED" if failures else "OK"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
