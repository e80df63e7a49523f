#!/usr/bin/env bash
# Runs one .export with the miniaster binary and checks the exit status against the
# `P expected_diag` line of the .export (default: OK, i.e. exit 0; NOOK_TEST_RESU: exit 2).
# Usage: run_validation.sh BINARY CASE.export OUTDIR
set -u
bin=$1 export_file=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
expected=0
if grep -Eq '^P +expected_diag +NOOK_TEST_RESU' "$export_file"; then expected=2; fi
"$bin" run "$export_file" --out-dir "$out" > "$out/stdout.txt" 2>&1
rc=$?
tail -n 30 "$out/stdout.txt"
if [ "$rc" -ne "$expected" ]; then
  echo "FAILED: $export_file exited with $rc, expected $expected"
  exit 1
fi
echo "exit status $rc as expected"
