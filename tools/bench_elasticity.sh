#!/usr/bin/env bash
# Benchmark of the linear elasticity engine (not a test): a plane-strain QUAD4 square from the
# ssnv511 mesh generator with N x N cells (2 (N+1)^2 unknowns; N = 710 gives 1.01e6 dofs),
# rollers on two sides and pressure on the other two, solved by MECA_STATIQUE with MUMPS (or
# the METHODE given). Prints the per-phase times of the engine and the peak memory of the run.
#
#   tools/bench_elasticity.sh [N] [METHODE] [BUILD_DIR] [RENUM]
#
# Results are recorded in docs/fe.md.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
n=${1:-710}
method=${2:-MUMPS}
build=${3:-$here/build}
renum=${4:-AUTO}
work=$(mktemp -d /tmp/bench_elasticity.XXXXXX)
trap 'rm -rf "$work"' EXIT

"$build/tools/ssnv511_mesh" --type quad4 --n "$n" -o "$work/square.med" > /dev/null
cat > "$work/bench.comm" <<COMM
DEBUT()
MA = LIRE_MAILLAGE(FORMAT='MED')
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=('SURF', 'LD', 'LH'), PHENOMENE='MECANIQUE',
                                      MODELISATION='D_PLAN'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=100.0E6, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=ACIER))
CH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='LG', DX=0.0), _F(GROUP_MA='LB', DY=0.0)),
                    PRES_REP=_F(GROUP_MA=('LD', 'LH'), PRES=1.0E6))
RES = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH), SOLVEUR=_F(METHODE='$method'$([ "$method" = MUMPS ] && echo ", RENUM='$renum'")))
FIN()
COMM
echo "N = $n, $((2 * (n + 1) * (n + 1))) dofs, METHODE = $method, RENUM = $renum"
/usr/bin/time -v "$build/miniaster" run "$work/bench.comm" --mesh "$work/square.med" --out-dir "$work/out" --verbose \
    > "$work/log.txt" 2> "$work/time.txt" || { tail -40 "$work/log.txt"; exit 1; }
grep -E "model MO|matrix pattern|stiffness assembled|MUMPS|Eigen|Newton iteration|MECA_STATIQUE:|LIRE_MAILLAGE  |TOTAL" "$work/log.txt"
grep -E "Elapsed \(wall|Maximum resident" "$work/time.txt"
