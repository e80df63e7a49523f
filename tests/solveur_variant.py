#!/usr/bin/env python3
"""Runs an original of ../shared/astest with other SOLVEUR keywords and checks that it gives the same
TEST results as the original run (tests/validation.cmake, docs/solver.md).

The original is never modified: its .export and .comm are copied under WORK, the copy's data files
point back to the originals (absolute paths), and in the copied .comm every MECA_STATIQUE and
STAT_NON_LINE call gets SOLVEUR=_F(<keywords>) (with those of the call's own SOLVEUR it does not set, when the METHODE stays the same). The
copy is then run by tools/run_validation.sh with --same-tests-as the one-process run, and the .mess
must show that the setting reached the solver (--expect).

Usage: solveur_variant.py BINARY RUN_VALIDATION ASTEST_DIR NAME WORK SAME_AS 'KEYWORDS' EXPECT [RUN OPTIONS...]
"""
import pathlib
import re
import subprocess
import sys

COMMANDS = ("MECA_STATIQUE", "STAT_NON_LINE")


def call_end(text, start):
    """Index just past the ')' closing the call whose '(' is at `start` (strings skipped)."""
    depth, i, quote = 0, start, None
    while i < len(text):
        c = text[i]
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c == "#":
            i = text.index("\n", i)
            continue
        elif c == "(":
            depth += 1
        elif c == ")":
            depth -= 1
            if depth == 0:
                return i + 1
        i += 1
    raise SystemExit(f"unbalanced call at offset {start}")


def merged(original, keywords):
    """The original SOLVEUR keywords (e.g. NPREC=-1) kept unless `keywords` sets them."""
    def pairs(text):
        return [p.strip() for p in text.split(",") if "=" in p]
    def method(items):
        return next((p.split("=")[1].strip() for p in items if p.split("=")[0].strip() == "METHODE"), None)
    mine = {p.split("=")[0].strip() for p in pairs(keywords)}
    # Another METHODE: the original's keywords belong to its own method's block (NPREC to MUMPS...).
    if method(pairs(keywords)) not in (None, method(pairs(original))):
        return ", ".join(pairs(keywords))
    kept = [p for p in pairs(original) if p.split("=")[0].strip() not in mine]
    return ", ".join(pairs(keywords) + kept)


def with_solveur(comm, keywords):
    """The command file with SOLVEUR=_F(keywords) in every solving call; the number of calls changed."""
    out, pos, changed = [], 0, 0
    for m in re.finditer(r"\b(%s)\s*\(" % "|".join(COMMANDS), comm):
        if m.start() < pos:
            continue
        open_at = m.end() - 1
        end = call_end(comm, open_at)
        call = comm[open_at + 1:end - 1]
        s = re.search(r"\bSOLVEUR\s*=\s*_F\s*\(", call)
        if s:
            s_end = call_end(call, s.end() - 1)
            call = call[:s.start()] + f"SOLVEUR=_F({merged(call[s.end():s_end - 1], keywords)})" + call[s_end:]
        else:
            call = f"SOLVEUR=_F({keywords}), " + call
        out.append(comm[pos:open_at + 1] + call + ")")
        pos = end
        changed += 1
    out.append(comm[pos:])
    return "".join(out), changed


def main(argv):
    if len(argv) < 9:
        sys.exit(__doc__)
    binary, run, astest, name, work, same_as, keywords, expect = argv[1:9]
    options = argv[9:]
    astest, work = pathlib.Path(astest).resolve(), pathlib.Path(work)
    work.mkdir(parents=True, exist_ok=True)
    lines = []
    for line in (astest / f"{name}.export").read_text().splitlines():
        f = line.split()
        if len(f) >= 4 and f[0] == "F" and f[3] == "D":
            if f[1] == "comm":
                comm, count = with_solveur((astest / f[2]).read_text(), keywords)
                if count == 0:
                    sys.exit(f"{name}: no {' or '.join(COMMANDS)} call to give SOLVEUR to")
                (work / f[2]).write_text(comm)
                print(f"{name}: SOLVEUR=_F({keywords}) in {count} call(s)")
            else:
                f[2] = str(astest / f[2])
                line = " ".join(f)
        lines.append(line)
    export = work / f"{name}.export"
    export.write_text("\n".join(lines) + "\n")
    out = work / "out"
    rc = subprocess.call([run, binary, str(export), str(out), "--same-tests-as", same_as] + options)
    if rc != 0:
        return rc
    mess = (out / f"{name}.mess").read_text()
    for text in (part.strip() for part in expect.split("&&")):
        if text not in mess:
            print(f"FAILED: the .mess does not show the setting reached the solver ('{text}')")
            return 1
        print(f"the .mess shows '{text}'")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
