#!/usr/bin/env python3
"""Fuzz test of the run as a whole (issue 17): random bit flips and truncations of the shared and
project meshes, random mutations of the project's command files. Fixed seeds, bounded time.
Issue 28's classes too: outputs that are links, inputs, special files or each other (refused: exit
1, the file linked to untouched), hostile Python in a command file (values without end, signals,
a timer, a segfault, a fork, the .mess's descriptor closed, a sleep past the time limit), inputs
that mislead (a level set returning a text, the same interface twice, a result name at the file
system's limit).

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


# Python inserted before FIN() of a project command file (issue 28 item 7; item 8's FORMULE).
HOSTILE_PYTHON = [
    "v = 1.0\nfor i in range(100000):\n    v = [v]\nDEFI_LIST_REEL(VALE=v)",
    "v = [1.0]\nv.append(v)\nDEFI_LIST_REEL(VALE=v)",
    "f = _F(JUSQU_A=1.0, NOMBRE=2)\nf['PAS'] = f\nDEFI_LIST_REEL(DEBUT=0., INTERVALLE=f)",
    "import ctypes\nctypes.string_at(0)",
    "import os, time\nos.kill(os.getpid(), SIG)\ntime.sleep(10)",
    "import signal, time\nsignal.alarm(1)\ntime.sleep(10)",
    "import os\npid = os.fork()\nif pid == 0:\n    print('CHILD')\nelse:\n    os.waitpid(pid, 0)",
    "import os\nfor fd in os.listdir('/proc/self/fd'):\n    try:\n        t = os.readlink('/proc/self/fd/' + fd)\n"
    "    except OSError:\n        continue\n    if t.endswith('.mess'):\n        os.close(int(fd))\n"
    "mine = open(os.devnull, 'w')",
    "import time\ntime.sleep(30)",
    "F_TEXT = FORMULE(VALE='str(X)', NOM_PARA='X')\nF_TEXT(1.0)",
]
SIGNALS = [3, 5, 10, 12, 14, 26, 27, 29, 30, 31]  # QUIT TRAP USR1 USR2 ALRM VTALRM PROF IO PWR SYS
# Outputs that must be refused before the first command (issue 28 item 5); {M} is the input mesh.
HOSTILE_OUTPUTS = ["mess-link", "resu-link", "rmed-link", "F mess same.txt R 6\nF resu same.txt R 8",
                   "F rmed a.rmed R 80\nF rmed ./a.rmed R 81", "F rmed {LINK}/mesh.mmed R 80", "F rmed fifo.rmed R 80",
                   "F rmed /dev/null R 80"]


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


def hostile_outputs(work, kind):
    """Sets up the hostile output `kind` in `work`; the .export lines it adds."""
    out = os.path.join(work, "out")
    os.makedirs(out)
    victim = os.path.join(work, "inputs", "victim.txt")
    with open(victim, "w") as f:
        f.write("somebody's file\n")
    if kind.endswith("-link"):
        name = {"mess": "case.mess", "resu": "case.resu", "rmed": "link.rmed"}[kind[:4]]
        os.symlink(victim, os.path.join(out, name))
        return "F rmed link.rmed R 80\n" if kind == "rmed-link" else ""
    if "fifo" in kind:
        os.mkfifo(os.path.join(out, "fifo.rmed"))
    os.symlink(os.path.join(work, "inputs"), os.path.join(work, "link"))
    return kind.replace("{LINK}", os.path.join(work, "link")) + "\n"


def run_case(binary, case):
    """One fuzz case in a fresh folder: inputs/ (never to be touched) and out/."""
    name, export_text, inputs = case[:3]
    outputs = case[3] if len(case) > 3 else None
    work = tempfile.mkdtemp(prefix="miniaster-fuzz-")
    try:
        os.makedirs(os.path.join(work, "inputs"))
        for fname, data in inputs.items():
            with open(os.path.join(work, "inputs", fname), "wb") as f:
                f.write(data)
        if outputs:
            export_text += hostile_outputs(work, outputs)
        export = os.path.join(work, "inputs", "case.export")
        with open(export, "w") as f:
            f.write(export_text)
        before = snapshot(os.path.join(work, "inputs"))
        try:
            p = subprocess.run([binary, "run", export, "--out-dir", os.path.join(work, "out")], cwd=work,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=RUN_TIMEOUT)
        except subprocess.TimeoutExpired:
            return "%s: no end within %d s" % (name, RUN_TIMEOUT), None
        text = p.stdout.decode("utf-8", "replace")
        problems = []
        if p.returncode not in (0, 1, 2):
            problems.append("exit status %d" % p.returncode)
        if outputs and p.returncode != 1:
            problems.append("a hostile output (%s) was not refused before the run" % outputs)
        for pattern in FORBIDDEN:
            m = pattern.search(text)
            if m:
                problems.append("output holds %r: ...%s..." % (m.group(0), text[max(0, m.start() - 300):m.end() + 100]))
        left = [os.path.join(r, f) for r, ds, fs in os.walk(work) for f in fs + ds if ".miniaster-tmp." in f]
        if left:
            problems.append("temporaries left: %s" % left)
        if snapshot(os.path.join(work, "inputs")) != before:
            problems.append("an input file was changed")
        outside = sorted(set(os.listdir(work)) - {"inputs", "out", "link"})
        if outside:
            problems.append("files outside the output folder: %s" % outside)
        return ("%s: %s\n%s" % (name, "; ".join(problems), text[-1500:]) if problems else None), p.returncode
    finally:
        shutil.rmtree(work, ignore_errors=True)


def same_interface_twice(lines, rng):
    """The first interface of MODI_MODELE_XFEM listed twice, or a copy of it whose level set is
    -3 times its own (the same zero set), listed after it."""
    if rng.random() < 0.5:
        return [re.sub(r"FISSURE=\((\w+),", r"FISSURE=(\1, \1,", l) for l in lines]
    for i, l in enumerate(lines):
        m = re.match(r"(\w+) = DEFI_FISS_XFEM\((.*)FONC_LN=(\w+)\)\)\s*$", l)
        if m and "JONCTION" not in l:
            copy = "%s_BIS = DEFI_FISS_XFEM(%sFONC_LN=FORMULE(VALE='-3.0 * %s(X, Y)', NOM_PARA=['X', 'Y'], %s=%s)))" % (
                m.group(1), m.group(2), m.group(3), m.group(3), m.group(3))
            lines = lines[:i + 1] + [copy] + lines[i + 1:]
            return [re.sub(r"FISSURE=\((%s)," % m.group(1), r"FISSURE=(\1, \1_BIS,", l) for l in lines]
    return lines


def hostile_case(comms, rng, k):
    """A project command file with hostile Python before its FIN(), or a misleading input."""
    c, text, rest = rng.choice(comms)
    header = "P time_limit 5\nP memory_limit 1024\n"
    lines = text.split("\n")
    fin = max([i for i, l in enumerate(lines) if l.startswith("FIN(")] or [len(lines)])
    choice = rng.randrange(len(HOSTILE_PYTHON) + 3)
    if choice < len(HOSTILE_PYTHON):
        snippet = HOSTILE_PYTHON[choice].replace("SIG", str(rng.choice(SIGNALS)))
        lines.insert(fin, snippet)
        what = snippet.split("\n")[-1][:40]
    elif choice == len(HOSTILE_PYTHON):  # the same interface twice (X-FEM cases only change)
        lines = same_interface_twice(lines, rng)
        what = "same interface twice"
    elif choice == len(HOSTILE_PYTHON) + 1:  # a level set returning a text
        lines = [re.sub(r"FORMULE\(VALE='([^']*)'", r"FORMULE(VALE='str(\1)'", l) for l in lines]
        what = "FORMULE returning a text"
    else:  # a result name at the file system's limit
        rest = [re.sub(r" (\S+)\.(rmed|resu|mess|txt) R ", lambda m: " %s.%s R " % ("r" * (254 - len(m.group(2))),
                                                                                      m.group(2)), l) for l in rest]
        what = "result names of 255 bytes"
    return ("%s.comm hostile (%s) #%d" % (c, what, k), header + "F comm case.comm D 1\n" + "\n".join(rest) + "\n",
            {"case.comm": "\n".join(lines).encode("latin-1", "replace")})


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
        what = k % 6
        if what == 4:
            cases.append(hostile_case(comms, rng, k))
            continue
        if what == 5:
            kind = rng.choice(HOSTILE_OUTPUTS)
            cases.append(("hostile output %s #%d" % (kind.split("\n")[0], k),
                          header + "F comm case.comm D 1\nF mmed mesh.mmed D 20\n",
                          {"case.comm": MESH_COMM.encode(), "mesh.mmed": open(meshes[0], "rb").read()}, kind))
            continue
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
