#!/usr/bin/env bash
# ssnv511h.comm, unmodified, on its own nodes re-split conformingly (tools/resplit_layer): the
# energy error of its uniform stresses with contact is round-off (≤ 1e-12), every reference check OK
# (tools/run_validation.sh, exit 2 only from code_aster's inexact NON_REGRESSION values), and
# LIRE_MAILLAGE raises no MAILLAGE_NON_CONFORME. On code_aster's mesh itself, non-conforming, the
# same file gives 0.1326 (docs/mesh.md "Conformity").
# Usage: resplit_check.sh MINIASTER RESPLIT_LAYER ASTEST_DIR OUTDIR
set -u
bin=$1 resplit=$2 astest=$3 out=$4
rm -rf "$out" && mkdir -p "$out"
"$resplit" "$astest/ssnv511h.mmed" "$out/ssnv511h_conforming.med" || { echo "FAILED: resplit_layer"; exit 1; }
printf 'P testlist verification\nF comm %s D 1\nF mmed %s D 20\n' "$(readlink -f "$astest/ssnv511h.comm")" \
       "$out/ssnv511h_conforming.med" > "$out/ssnv511h.export"
"$(dirname "$0")/../tools/run_validation.sh" "$bin" "$out/ssnv511h.export" "$out/run" --allow-nonregression-nook ||
  exit 1
mess="$out/run/ssnv511h.mess"
# All 26 of the file's reference checks ran (run_validation.sh asks for at least one).
grep -Eq '^ *reference checks +26 +0 ' "$mess" || { echo "FAILED: not 26 reference checks OK"; exit 1; }
if grep -q MAILLAGE_NON_CONFORME "$mess"; then echo "FAILED: the re-split mesh is reported non-conforming"; exit 1; fi
energy=$(grep -m1 'ERREUR EN NORME ENERGIE' "$mess" | sed 's/.*ERREUR RELATIVE = //')
echo "energy ERREUR RELATIVE = $energy"
python3 -c "import sys; sys.exit(0 if float('$energy') <= 1e-12 else 1)" || { echo "FAILED: energy error above 1e-12"; exit 1; }
echo "PASSED"
