#!/usr/bin/env python3
"""Fuzz test of the run as a whole (issue 17): random bit flips and truncations of the shared and
project meshes, random mutations of the project's command files. Fixed seeds, bounded time.

Every run must end with exit status 0, 1 or 2 (never a signal, never a hang), print no C++ library
message (`std::`) and no Python traceback, leave no temporary file and touch no file outside its
output folder.

usage: fuzz_faults.py MINIASTER_BINARY SOURCE_DIR SHARED_DIR [--cases N] [--budget SECONDS]
"""
import argparse
import concurrent.futures
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

# Small, fast project cases whose command files are mutated (with their .export).
COMM_CASES = ["fe_patch_quad4", "fe_patch_tria3", "tables_chain", "xfem_quad4_n7", "fe_stat_non_line"]
MESH_COMM = "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED')\nMA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, " \
            "CREA_GROUP_NO=_F(TOUT_GROUP_MA='OUI'))\nFIN()\n"
RUN_TIMEOUT = 60  # seconds of wall time for one run (the .export says 20 s of CPU)
FORBIDDEN = [re.compile(r"std::"), re.compile(r"Traceback \(most recent call last\)")]
NUMBERS = ["0", "-1", "1e300", "-1e300", "1e-300", "2**31", "float('nan')", "float('inf')", "0.5", "-0.0"]


def mutate_bits(data, rng):
    data = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        pos = rng.randrange(len(data))
        data[pos] ^= 1 << rng.randrange(8)
    return bytes(data)


def truncate(data, rng):
    return data[: rng.randrange(1, len(data))]


def mutate_comm(text, rng):
    lines = text.split("\n")
    kind = rng.choice(["delete", "duplicate", "number", "string", "char", "truncate", "swap"])
    k = rng.randrange(len(lines))
    if kind == "delete":
        del lines[k]
    elif kind == "duplicate":
        lines.insert(k, lines[k])
    elif kind == "swap" and len(lines) > 1:
        j = rng.randrange(len(lines))
        lines[k], lines[j] = lines[j], lines[k]
    elif kind == "number":
        spots = [(i, m) for i, l in enumerate(lines) for m in re.finditer(r"(?<![\w.])\d+\.?\d*(?:[eE][-+]?\d+)?", l)]
        if spots:
            i, m = rng.choice(spots)
            lines[i] = lines[i][: m.start()] + rng.choice(NUMBERS) + lines[i][m.end():]
    elif kind == "string":
        spots = [(i, m) for i, l in enumerate(lines) for m in re.finditer(r"'[^']*'", l)]
        if spots:
            i, m = rng.choice(spots)
            lines[i] = lines[i][: m.start()] + rng.choice(["''", "'X'", "'TOUT'", "'" + "A" * 40 + "'"]) + \
                lines[i][m.end():]
    elif kind == "char":
        line = lines[k]
        pos = rng.randrange(len(line) + 1)
        lines[k] = line[:pos] + rng.choice("()[]=,'\"_:#\\\x00é") + line[pos:]
    else:
        return "\n".join(lines)[: rng.randrange(1, max(2, len(text)))]
    return "\n".join(lines)


def export_lines(export_path):
    """F lines of a project .export with absolute paths, the command file apart."""
    folder = os.path.dirname(export_path)
    comm, rest = None, []
    for line in open(export_path):
        t = line.split()
        if len(t) == 5 and t[0] == "F":
            path = os.path.join(folder, t[2])
            if t[1] == "comm":
                comm = path
            elif "D" in t[3]:
                rest.append("F %s %s %s %s" % (t[1], path, t[3], t[4]))
            else:
                rest.append("F %s %s %s %s" % (t[1], t[2], t[3], t[4]))  # results: in the out dir
    return comm, rest


def snapshot(folder):
    out = {}
    for root, _, files in os.walk(folder):
        for f in files:
            p = os.path.join(root, f)
            st = os.stat(p)
            out[p] = (st.st_size, st.st_mtime_ns)
    return out


def run_case(binary, case):
    """One fuzz case in a fresh folder: inputs/ (never to be touched) and out/."""
    name, export_text, inputs = case
    work = tempfile.mkdtemp(prefix="miniaster-fuzz-")
    try:
        os.makedirs(os.path.join(work, "inputs"))
        for fname, data in inputs.items():
            with open(os.path.join(work, "inputs", fname), "wb") as f:
                f.write(data)
        export = os.path.join(work, "inputs", "case.export")
        with open(export, "w") as f:
            f.write(export_text)
        before = snapshot(os.path.join(work, "inputs"))
        try:
            # --verbose: the whole log on stdout, searched for the forbidden texts below.
            p = subprocess.run([binary, "run", export, "--out-dir", os.path.join(work, "out"), "--verbose"], cwd=work,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=RUN_TIMEOUT)
        except subprocess.TimeoutExpired:
            return "%s: no end within %d s" % (name, RUN_TIMEOUT), None
        text = p.stdout.decode("utf-8", "replace")
        problems = []
        if p.returncode not in (0, 1, 2):
            problems.append("exit status %d" % p.returncode)
        for pattern in FORBIDDEN:
            m = pattern.search(text)
            if m:
                problems.append("output holds %r: ...%s..." % (m.group(0), text[max(0, m.start() - 300):m.end() + 100]))
        left = [os.path.join(r, f) for r, ds, fs in os.walk(work) for f in fs + ds if ".miniaster-tmp." in f]
        if left:
            problems.append("temporaries left: %s" % left)
        if snapshot(os.path.join(work, "inputs")) != before:
            problems.append("an input file was changed")
        outside = sorted(set(os.listdir(work)) - {"inputs", "out"})
        if outside:
            problems.append("files outside the output folder: %s" % outside)
        return ("%s: %s\n%s" % (name, "; ".join(problems), text[-1500:]) if problems else None), p.returncode
    finally:
        shutil.rmtree(work, ignore_errors=True)


def make_cases(source, shared, count, seed):
    rng = random.Random(seed)
    meshes = sorted(os.path.join(d, f) for d in (os.path.join(shared, "astest"), os.path.join(source, "astest"))
                    for f in os.listdir(d) if f.endswith(".mmed"))
    meshes = [m for m in meshes if os.path.getsize(m) < 2_000_000]  # big meshes: slow runs, same code
    comms = []
    for c in COMM_CASES:
        comm, rest = export_lines(os.path.join(source, "astest", c + ".export"))
        comms.append((c, open(comm, "rb").read().decode("latin-1"), rest))
    header = "P time_limit 20\nP memory_limit 1024\n"
    cases = []
    for k in range(count):
        what = k % 4
        if what < 3:
            mesh = rng.choice(meshes)
            data = open(mesh, "rb").read()
            data, how = (mutate_bits(data, rng), "bits") if what < 2 else (truncate(data, rng), "truncated")
            cases.append(("%s %s #%d" % (os.path.basename(mesh), how, k),
                          header + "F comm case.comm D 1\nF mmed mesh.mmed D 20\n",
                          {"case.comm": MESH_COMM.encode(), "mesh.mmed": data}))
        else:
            c, text, rest = rng.choice(comms)
            mutated = mutate_comm(text, rng)
            cases.append(("%s.comm mutated #%d" % (c, k), header + "F comm case.comm D 1\n" + "\n".join(rest) + "\n",
                          {"case.comm": mutated.encode("latin-1", "replace")}))
    return cases


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("source")
    parser.add_argument("shared")
    parser.add_argument("--cases", type=int, default=240)
    parser.add_argument("--budget", type=float, default=50.0, help="seconds; later cases are not started")
    parser.add_argument("--seed", type=int, default=17)
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    args.binary = os.path.abspath(args.binary)
    cases = make_cases(args.source, args.shared, args.cases, args.seed)
    start = time.monotonic()
    failures, done, statuses = [], 0, {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        pending = set()
        it = iter(cases)
        while True:
            while len(pending) < args.jobs and time.monotonic() - start < args.budget:
                case = next(it, None)
                if case is None:
                    break
                pending.add(pool.submit(run_case, args.binary, case))
            if not pending:
                break
            finished, pending = concurrent.futures.wait(pending, return_when=concurrent.futures.FIRST_COMPLETED)
            for f in finished:
                done += 1
                failure, status = f.result()
                statuses[status] = statuses.get(status, 0) + 1
                if failure:
                    failures.append(failure)
    elapsed = time.monotonic() - start
    print("fuzz: %d of %d cases run in %.1f s (seed %d), %d failure(s); exit statuses %s" % (
        done, len(cases), elapsed, args.seed, len(failures), dict(sorted(statuses.items(), key=str))))
    for f in failures:
        print("FAIL", f)
    if done < min(len(cases), 40):
        print("fuzz: fewer than 40 cases ran within the budget: the machine is too loaded to judge")
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
