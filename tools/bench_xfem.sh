#!/usr/bin/env bash
# Benchmark of the X-FEM four-block case (not a test): astest/xfem_quad4.comm (ssnv511
# configuration, D_PLAN, a rigid translation per block) on a QUAD4 square with N x N cells from
# the ssnv511 mesh generator. Prints the X-FEM set-up log, the solver lines (scaling, residual,
# backward error), the TEST summary (the lips at 1e-13 relative; refined meshes sit on a round-off
# floor that grows with N, see docs/xfem.md), per-command times and the peak memory.
#
#   tools/bench_xfem.sh [N] [BUILD_DIR]
#
# Results are recorded in docs/xfem.md (validation).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
n=${1:-501}
build=${2:-$here/build}
work=$(mktemp -d /tmp/bench_xfem.XXXXXX)
trap 'rm -rf "$work"' EXIT

"$build/tools/ssnv511_mesh" --type quad4 --n "$n" -o "$work/mesh.med" > /dev/null
cp "$here/astest/xfem_quad4.comm" "$work/case.comm"
printf 'P time_limit 3600\nF comm case.comm D 1\nF mmed mesh.med D 20\nF rmed case.rmed R 80\n' > "$work/case.export"
echo "N = $n, QUAD4, $(( (n + 1) * (n + 1) )) nodes"
rc=0
/usr/bin/time -v "$build/miniaster" run "$work/case.export" --out-dir "$work" > "$work/log.txt" 2> "$work/time.txt" || rc=$?
grep -E "smallest retained|enriched nodes|diagonal scaling|MUMPS \(|MUMPS solve|ERREUR RELATIVE =" "$work/case.mess" || true
sed -n '/TEST SUMMARY/,/TIMING SUMMARY/p' "$work/case.mess" | grep -E "checks|NOOK" | cut -c1-200 | head -12
grep -E "^  (DEFI_FISS_XFEM|MODI_MODELE_XFEM|MECA_STATIQUE|POST_MAIL_XFEM|POST_CHAM_XFEM|IMPR_RESU|POST_RELEVE_T|POST_ERREUR|TOTAL)" "$work/case.mess"
grep -E "Elapsed \(wall|Maximum resident" "$work/time.txt"
echo "exit status $rc (2 = some TEST NOOK)"
