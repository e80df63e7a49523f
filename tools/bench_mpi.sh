#!/usr/bin/env bash
# bench_mpi.sh -- miniaster on K MPI processes (issue 16, item 4): wall time per phase and peak
# resident memory per process, for the refined ssnv511a/e scenes (2D) and a 3D HEXA8 box with four
# stacked X-FEM interfaces in contact, each with K = 1, 2, 4.
#
# usage: tools/bench_mpi.sh [--n "501 1001"] [--box "30x60x15 40x80x20"] [--np "1 2 4"] [--out FILE.md]
#
# 2D: ../shared/bench/refined_a.comm and refined_e.comm on tools/ssnv511_mesh QUAD4 N x N meshes
# (as ../shared/bench/sidebyside.sh). 3D: astest/xfem_four_stacked_contact_3d.comm on
# tools/box_mail.py HEXA8 boxes NXxNYxNZ of [0,2]x[0,4]x[0,1], with its RESI_GLOB_RELA 1e-14 relaxed to
# 1e-12 (round-off of the larger boxes' residual reaches 2e-14). Each run: ./miniaster run --np K;
# the table is read from its .mess (TOTAL, MUMPS analysis/factorisation/solve, "MUMPS on K
# processes ... resident peak per process"). On a machine with fewer cores than K the processes
# share them (oversubscribed): the wall times then say nothing about speed-up, the memory per
# process does. Work folder: $BENCH_MPI_DIR (default: a fresh one under the temp dir), kept.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
shared=$(cd "$here/../shared" 2>/dev/null && pwd) || { echo "bench_mpi.sh: ../shared not found beside $here" >&2; exit 1; }
sizes="501 1001"; boxes="30x60x15 40x80x20"; nps="1 2 4"; out=""
while [ $# -gt 0 ]; do
    case "$1" in
        --n) sizes=$2; shift 2 ;;
        --box) boxes=$2; shift 2 ;;
        --np) nps=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        *) sed -n '4,6p' "$0" >&2; exit 2 ;;
    esac
done
work=${BENCH_MPI_DIR:-$(mktemp -d "${TMPDIR:-/tmp}/bench_mpi.XXXXXX")}
mkdir -p "$work"
"$here/miniaster" build >/dev/null
mesher="$here/build/tools/ssnv511_mesh"

# The .mess of one run -> "wall | analysis | factorisation | solve | peaks".
summary() {
    local mess=$1
    local wall ana fac sol peaks
    wall=$(grep -oE 'TOTAL \(commands\) +[0-9.]+' "$mess" | grep -oE '[0-9.]+$' || echo '?')
    ana=$(grep -oE 'MUMPS analysis [0-9.]+ s' "$mess" | head -1 | grep -oE '[0-9.]+' || echo '?')
    fac=$(grep -oE 'MUMPS factorisation [0-9.]+ s' "$mess" | head -1 | grep -oE '[0-9.]+' || echo '?')
    sol=$(grep -oE 'MUMPS solve [0-9.]+ s' "$mess" | head -1 | grep -oE '[0-9.]+' || echo '?')
    peaks=$(grep -oE 'resident peak per process \(MB\):[ 0-9]+' "$mess" | head -1 | sed 's/.*://; s/^ //' || true)
    [ -n "$peaks" ] || peaks=$(grep -E '^ +TOTAL \(commands\)' "$mess" | awk '{print $NF}')
    echo "$wall | $ana | $fac | $sol | $peaks"
}

run_case() {  # label comm meshfile meshunit-keyword
    local label=$1 comm=$2 mesh=$3 kind=$4
    for k in $nps; do
        local dir="$work/${label// /_}_np$k"
        mkdir -p "$dir"
        printf 'P time_limit 3600\nP memory_limit 20000\nP ncpus %s\n\nF comm %s D 1\nF %s %s D 20\n' \
            "$(nproc)" "$comm" "$kind" "$mesh" > "$dir/case.export"
        local status=0
        "$here/miniaster" run --np "$k" "$dir/case.export" --out-dir "$dir" > "$dir/stdout.txt" 2>&1 || status=$?
        local mess
        mess=$(ls "$dir"/*.mess | head -1)
        printf '| %s | %s | %s | %s |\n' "$label" "$k" "$(summary "$mess")" "$([ $status -eq 0 ] && echo ok || echo "exit $status")" | tee -a "$work/table.md"
    done
}

{
    echo "| scene | K | wall, all commands (s) | MUMPS analysis (s) | factorisation (s) | solve (s) | peak resident per process (MB) | run |"
    echo "|---|---|---|---|---|---|---|---|"
} > "$work/table.md"
echo "machine: $(nproc) cores, $(free -g | awk '/Mem:/ {print $2}') GB; load $(cut -d' ' -f1-3 /proc/loadavg); git $(git -C "$here" rev-parse --short HEAD)" | tee "$work/machine.txt"
cat "$work/table.md"
for n in $sizes; do
    [ -f "$work/quad_$n.med" ] || "$mesher" --type quad4 --n "$n" -o "$work/quad_$n.med" >/dev/null
    for c in a e; do run_case "refined ssnv511$c N=$n" "$shared/bench/refined_$c.comm" "$work/quad_$n.med" mmed; done
done
sed 's/RESI_GLOB_RELA=1e-14/RESI_GLOB_RELA=1e-12/' "$here/astest/xfem_four_stacked_contact_3d.comm" > "$work/box_contact_3d.comm"
for box in $boxes; do
    IFS=x read -r nx ny nz <<< "$box"
    [ -f "$work/box_$box.mail" ] || /usr/bin/python3 "$here/tools/box_mail.py" hexa8 "$nx" "$ny" "$nz" "$work/box_$box.mail" --size 2 4 1 >/dev/null
    run_case "3D HEXA8 $box, 4 interfaces in contact" "$work/box_contact_3d.comm" "$work/box_$box.mail" mail
done
[ -z "$out" ] || { cat "$work/machine.txt"; echo; cat "$work/table.md"; } > "$out"
echo "bench_mpi.sh: runs kept in $work"
