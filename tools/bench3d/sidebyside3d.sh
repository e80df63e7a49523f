#!/usr/bin/env bash
# sidebyside3d.sh -- miniaster vs GetFEM 5.4 on the refined ssnv511c scene (3D, HEXA8).
#
# usage: MAIN=<miniaster checkout> sidebyside3d.sh N [REPS]
#   N     cells along x, y and z of the HEXA8 box [-5,5] x [-5,5] x [0,DEPTH] (N x N x N)
#   REPS  runs per tool, default 3, alternating miniaster, GetFEM, miniaster, ...
#
# Builds the N x N x N mesh with miniaster's tools/ssnv511_mesh (`--type hexa8 --n N --layers N
# --zbounds 0 DEPTH --offset O O`, cached), writes an .export (refined_c.comm on unit 1, the mesh
# on unit 20) and runs `$MAIN/build/miniaster run refined_c.export --out-dir DIR` (the binary the
# launcher $MAIN/miniaster runs, brought up to date once before the timed runs) and
# `/usr/bin/python3 ssnv511c_getfem.py --n N --offset O --depth DEPTH`, each whole process under
# /usr/bin/time -v. Prints per tool the median wall time and peak RSS, the relative L2 error each
# reports (miniaster: 'ERREUR RELATIVE' of the TOTAL row of POST_ERREUR in its .resu; GetFEM: its
# JSON, with its max displacement error at the nodes and on both sides of the cut cells), the
# displacement dofs each has (enriched ones included) and the size of the system each factors,
# and the ratios GetFEM/miniaster (sidebyside3d_report.py). Without $MAIN/miniaster only the
# GetFEM side runs; SIDES=miniaster runs miniaster alone (the big sizes GetFEM cannot reach).
#
# Environment (all optional):
#   MAIN             miniaster checkout, configured (./miniaster build): its build/ has miniaster and
#                    tools/ssnv511_mesh (both brought up to date, untimed, by cmake --build)
#   SIDES            both (default) | miniaster | getfem
#   MINI_SOLVEUR     keywords that replace METHODE='MUMPS' in SOLVEUR=_F(...) of refined_c.comm, e.g.
#                    "METHODE='PETSC', PRE_COND='LDLT_SP'" or "METHODE='PETSC', PRE_COND='GAMG'"
#                    (default: none, the command file as it is: MUMPS, code_aster's default)
#   GF_SOLVER        mumps (default, GetFEM's direct solver) | superlu
#   OFFSET           interior grid lines moved by this fraction of a cell, both tools (default 0 for
#                    odd N, 0.5 for even N: x = 0 and y = 0 then cross the cells at mid-width)
#   DEPTH            box depth along z (default 1, ssnv511c's box)
#   GF_BLAS          openblas (default when GF_OPENBLAS names a folder) | system (the BLAS ld finds)
#   GF_OPENBLAS      folder put first on GetFEM's LD_LIBRARY_PATH when GF_BLAS=openblas
#   SIDEBYSIDE3D_DIR cache and work root (default: ssnv511c_sidebyside in the temp dir)
#   MESHER           mesh generator (default: $MAIN/build/tools/ssnv511_mesh, built if missing)
#   MINI_NP          MPI processes of miniaster (export 'P mpi_nbcpu', default 1); above 1 its peak
#                    memory is the sum of its processes' peaks (tree_rss.py), not GNU time's largest one
#   TIME_LIMIT       export 'P time_limit' in s (default 3600)
#   MEMORY_LIMIT     export 'P memory_limit' in MB (default: the machine's memory)
#   NCPUS            export 'P ncpus' (default: nproc)
#   GF_PYTHON        interpreter for GetFEM's script (default /usr/bin/python3)
#   TIME_BIN         GNU time (default /usr/bin/time, Debian package 'time')
#   MESS_TAIL        lines of the last miniaster .mess shown (per-command summary; default 20, 0: none)
#
# Needs: python3-getfem (GetFEM 5.4, not a miniaster dependency), time. The machine is shared:
# compare the ratios of one run, not absolute times across runs.
set -u

here=$(cd "$(dirname "$0")" && pwd)
prog=$(basename "$0")

usage() {
    sed -n '4,6p' "$0" | sed 's/^# \{0,1\}//' >&2
    echo "(see the header of $prog for the environment variables)" >&2
    exit 2
}

[ $# -ge 1 ] && { [ "$1" = -h ] || [ "$1" = --help ]; } && usage
[ $# -eq 1 ] || [ $# -eq 2 ] || usage
n=$1
reps=${2:-3}
[[ "$n" =~ ^[0-9]+$ ]] && [ "$((10#$n))" -ge 1 ] || { echo "$prog: N must be a whole number >= 1, got '$n'" >&2; usage; }
[[ "$reps" =~ ^[0-9]+$ ]] && [ "$((10#$reps))" -ge 1 ] || { echo "$prog: REPS must be a whole number >= 1, got '$reps'" >&2; usage; }
n=$((10#$n)); reps=$((10#$reps))
name=refined_c
comm=$here/$name.comm
gf_script=$here/ssnv511c_getfem.py
py=${GF_PYTHON:-/usr/bin/python3}
timer=${TIME_BIN:-/usr/bin/time}
sides=${SIDES:-both}
depth=${DEPTH:-1}
if [ -n "${OFFSET:-}" ]; then offset=$OFFSET; elif [ $((n % 2)) -eq 0 ]; then offset=0.5; else offset=0; fi
gf_solver=${GF_SOLVER:-mumps}

case "$sides" in both|miniaster|getfem) ;; *) echo "$prog: SIDES must be both, miniaster or getfem" >&2; exit 2 ;; esac
case "$gf_solver" in mumps|superlu) ;; *) echo "$prog: GF_SOLVER must be mumps or superlu" >&2; exit 2 ;; esac
[ -x "$timer" ] || { echo "$prog: $timer not found (Debian package 'time')" >&2; exit 1; }
[ -f "$comm" ] || { echo "$prog: $comm not found" >&2; exit 1; }
if [ "$offset" = 0 ] && [ $((n % 2)) -eq 0 ]; then
    echo "$prog: even N=$n with OFFSET=0 puts grid planes on the interfaces x=0, y=0" >&2; exit 2
fi

# ---- which sides run
run_mini=no; mini_reason=
if [ "$sides" = getfem ]; then
    mini_reason="SIDES=getfem"
elif [ -z "${MAIN:-}" ]; then
    mini_reason="MAIN is not set"
elif [ ! -f "$MAIN/build/build.ninja" ] && [ ! -f "$MAIN/build/Makefile" ]; then
    mini_reason="$MAIN/build is not configured (run $MAIN/miniaster build)"
else
    run_mini=yes
fi
run_gf=no; gf_reason=
if [ "$sides" = miniaster ]; then
    gf_reason="SIDES=miniaster"
elif [ ! -f "$gf_script" ]; then
    gf_reason="$gf_script not found"
elif ! "$py" -c 'import getfem' 2>/dev/null; then
    gf_reason="$py cannot import getfem (Debian: apt-get install python3-getfem)"
else
    run_gf=yes
fi
[ "$run_mini" = no ] && echo "$prog: miniaster side skipped: $mini_reason" >&2
[ "$run_gf" = no ] && echo "$prog: GetFEM side skipped: $gf_reason" >&2
if [ "$run_mini" = no ] && [ "$run_gf" = no ]; then
    echo "$prog: nothing to run" >&2; exit 1
fi

openblas=${GF_OPENBLAS:-/nonexistent}
gf_blas=${GF_BLAS:-}
[ -z "$gf_blas" ] && { if [ -d "$openblas" ]; then gf_blas=openblas; else gf_blas=system; fi; }
case "$gf_blas" in
    openblas)
        [ -d "$openblas" ] || { echo "$prog: GF_BLAS=openblas needs GF_OPENBLAS=DIR (an OpenBLAS folder)" >&2; exit 1; }
        gf_env=(env "LD_LIBRARY_PATH=$openblas${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}") ;;
    system) gf_env=(env) ;;
    *) echo "$prog: GF_BLAS must be openblas or system" >&2; exit 2 ;;
esac

base=${SIDEBYSIDE3D_DIR:-$(dirname "$(mktemp -u)")/ssnv511c_sidebyside}
mkdir -p "$base/meshes" || exit 1

# ---- miniaster and the mesher up to date (untimed: a commit relinks the binary, see git_version)
if [ "$run_mini" = yes ]; then
    targets=(miniaster)
    [ -z "${MESHER:-}" ] && targets+=(ssnv511_mesh)
    cmake --build "$MAIN/build" --target "${targets[@]}" > "$base/build.log" 2>&1 \
        || { echo "$prog: cmake --build $MAIN/build --target ${targets[*]} failed (see $base/build.log)" >&2; exit 1; }
    [ "$(id -u)" -eq 0 ] && export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi

# ---- mesh (cached)
mesh=$base/meshes/hexa_${n}_d${depth}_o${offset}.med
if [ "$run_mini" = yes ]; then
    mesher=${MESHER:-$MAIN/build/tools/ssnv511_mesh}
    [ -x "$mesher" ] || { echo "$prog: mesher $mesher is not executable" >&2; exit 1; }
    if [ ! -s "$mesh" ] || [ "$mesher" -nt "$mesh" ]; then
        tmp=$mesh.tmp.$$
        "$mesher" --type hexa8 --n "$n" --layers "$n" --zbounds 0 "$depth" --offset "$offset" "$offset" -o "$tmp" >&2 \
            && mv -f "$tmp" "$mesh" || { rm -f "$tmp"; echo "$prog: mesh generation failed" >&2; exit 1; }
    else
        echo "$prog: using cached mesh $mesh" >&2
    fi
fi

# ---- run directory, export
run=$(mktemp -d "$base/run_c_${n}_XXXXXX") || exit 1
if [ "$run_mini" = yes ]; then
    cp "$comm" "$run/$name.comm"
    if [ -n "${MINI_SOLVEUR:-}" ]; then
        sed -i "s|SOLVEUR=_F(METHODE='MUMPS')|SOLVEUR=_F(${MINI_SOLVEUR})|" "$run/$name.comm"
        grep -qF "SOLVEUR=_F(${MINI_SOLVEUR})" "$run/$name.comm" || { echo "$prog: MINI_SOLVEUR not applied" >&2; exit 2; }
    fi
    ln -s "$mesh" "$run/$(basename "$mesh")"
    mem=${MEMORY_LIMIT:-$(awk '/^MemTotal:/ {printf "%d", $2 / 1024}' /proc/meminfo)}
    {
        printf 'P time_limit %s\n' "${TIME_LIMIT:-3600}"
        printf 'P memory_limit %s\n' "$mem"
        printf 'P ncpus %s\n' "${NCPUS:-$(nproc)}"
        printf 'P mpi_nbcpu %s\n\n' "${MINI_NP:-1}"
        printf 'F comm %s D 1\n' "$name.comm"
        printf 'F mmed %s D 20\n' "$(basename "$mesh")"
    } > "$run/$name.export"
fi
{
    echo "reps=$reps"
    echo "name=$name"
    echo "n=$n"
    echo "depth=$depth"
    echo "offset=$offset"
    echo "miniaster=$run_mini"
    echo "miniaster_reason=$mini_reason"
    echo "miniaster_solveur=${MINI_SOLVEUR:-METHODE='MUMPS' (default)}"
    echo "miniaster_processes=${MINI_NP:-1}"
    echo "getfem=$run_gf"
    echo "getfem_reason=$gf_reason"
    echo "getfem_solver=$gf_solver"
    echo "machine=$(awk -F': *' '/^model name/ {print $2; exit}' /proc/cpuinfo), nproc $(nproc), $(awk '/^MemTotal:/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo)"
    echo "loadavg_start=$(cut -d' ' -f1-3 /proc/loadavg)"
    [ "$run_gf" = yes ] && echo "getfem_blas=$gf_blas"
    [ "$run_mini" = yes ] && echo "miniaster_blas=$(ldd "$MAIN/build/miniaster" 2>/dev/null | awk '/blas|lapack|mkl/ {print $1}' | sort -u | tr '\n' ' ')"
    echo "work_dir=$run"
} > "$run/info.txt"

# ---- runs, alternating
for i in $(seq "$reps"); do
    if [ "$run_mini" = yes ]; then
        echo "$prog: [$i/$reps] miniaster run $name.export (N=$n)" >&2
        mkdir -p "$run/mini_$i"
        tree=()
        [ "${MINI_NP:-1}" -gt 1 ] && tree=("$py" "$here/tree_rss.py" "$run/mini_$i.rss" --)
        (cd "$run" && "$timer" -v -o "$run/mini_$i.time" "${tree[@]}" \
            "$MAIN/build/miniaster" run "$run/$name.export" --out-dir "$run/mini_$i" \
            > "$run/mini_$i.stdout" 2>&1)
        st=$?
        [ $st -ne 0 ] && echo "$prog: miniaster exited with $st (see $run/mini_$i.stdout)" >&2
    fi
    if [ "$run_gf" = yes ]; then
        echo "$prog: [$i/$reps] GetFEM --n $n --offset $offset ($gf_solver, $gf_blas BLAS)" >&2
        (cd "$run" && "$timer" -v -o "$run/gf_$i.time" \
            "${gf_env[@]}" "$py" "$gf_script" --n "$n" --offset "$offset" --depth "$depth" --solver "$gf_solver" \
            > "$run/gf_$i.json" 2> "$run/gf_$i.stderr")
        st=$?
        [ $st -ne 0 ] && echo "$prog: GetFEM exited with $st (see $run/gf_$i.stderr)" >&2
    fi
done

"$py" "$here/sidebyside3d_report.py" "$run"
rc=$?
if [ "$run_mini" = yes ] && [ "${MESS_TAIL:-20}" -gt 0 ]; then
    mess=$(ls -t "$run"/mini_*/*.mess 2>/dev/null | head -1)
    if [ -n "$mess" ]; then
        echo
        echo "  last ${MESS_TAIL:-20} lines of $mess (miniaster's per-command summary):"
        tail -n "${MESS_TAIL:-20}" "$mess" | sed 's/^/    /'
    else
        echo "  no .mess found under $run/mini_*"
    fi
fi
exit $rc
