#!/usr/bin/env python3
"""Peak memory of a process tree: the sum over its processes of each one's peak resident size.

usage: tree_rss.py OUT -- COMMAND [ARGS...]

Runs COMMAND, and every 0.05 s reads VmHWM and VmRSS of every process below it (mpirun's ranks
included) from /proc; writes to OUT the sum over the processes of the largest value each showed, in
MB, and exits with COMMAND's status. With several MPI processes GNU time's "Maximum resident set
size" is the largest single process, not their sum: this is the figure for a side by side. The
processes' peaks may fall at different moments, so the sum is an upper bound of the tree's peak.
"""
import os
import subprocess
import sys
import time


def children():
    """parent pid -> child pids, from /proc/*/stat."""
    tree = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        tree.setdefault(int(fields[1]), []).append(int(entry))
    return tree


def below(root, tree):
    out, todo = [], [root]
    while todo:
        pid = todo.pop()
        out.append(pid)
        todo.extend(tree.get(pid, []))
    return out


def resident_kb(pid):
    """max(VmHWM, VmRSS) of pid in kB, None once it is gone."""
    best = None
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith(("VmHWM:", "VmRSS:")):
                    best = max(best or 0, int(line.split()[1]))
    except OSError:
        return None
    return best


def main(argv):
    if len(argv) < 4 or argv[2] != "--":
        sys.stderr.write(__doc__)
        return 2
    out = argv[1]
    child = subprocess.Popen(argv[3:])
    peaks = {}
    while child.poll() is None:
        for pid in below(child.pid, children()):
            kb = resident_kb(pid)
            if kb is not None:
                peaks[pid] = max(peaks.get(pid, 0), kb)
        time.sleep(0.05)
    with open(out, "w") as f:
        f.write(f"{sum(peaks.values()) / 1024.0:.1f} MB summed over {len(peaks)} processes\n")
    return child.returncode


if __name__ == "__main__":
    sys.exit(main(sys.argv))
