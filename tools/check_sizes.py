#!/usr/bin/env python3
"""Size limits of the code (brief: one concept per file, no function that needs scrolling).

Checks every .cpp/.hpp under src/, parser/ and med_io/ of the checkout given as argument (default:
this script's checkout): no file over 600 lines, no function body over 80 lines. Functions are
found by a brace-matching scan with comments, string and character literals removed: a '{' at
namespace or class level whose header (the text since the previous ';', '{' or '}') has a
parenthesis and is no class, struct, union, enum or namespace opens a function; its length is the
number of lines from that '{' to the matching '}'. Lambdas and local classes count in the function
that holds them. Prints each violation; exit status 1 if any.
"""
import re
import sys
from pathlib import Path

MAX_FILE_LINES = 600
MAX_FUNCTION_LINES = 80
FOLDERS = ("src", "parser", "med_io")


def strip_code(text):
    """The text with comments and literals blanked (newlines kept, so line numbers hold)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'R"([^()\\\s]{0,16})\(', text[i:])
            if not m:
                out.append(c)
                i += 1
                continue
            end = text.find(")" + m.group(1) + '"', i + m.end())
            end = n if end < 0 else end + len(m.group(1)) + 2
            out.append('""' + "\n" * text.count("\n", i, end))
            i = end
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum() and not text[i - 1].isalpha():
                out.append(c)  # digit separator 1'000
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


CLASS_LIKE = re.compile(r"^\s*(template\s*<.*>\s*)?(typedef\s+)?(class|struct|union|enum|namespace)\b|\bextern\s*$", re.S)


def is_function_header(header):
    h = " ".join(header.split())
    if "(" not in h or h.endswith("="):
        return False
    h = re.sub(r"^template\s*<[^(){};]*>\s*", "", h)
    if re.match(r"(class|struct|union|enum|namespace)\b", h) or h.startswith('extern ""'):
        return False
    return True


def functions(code):
    """(first line, last line) of every function body."""
    found = []
    stack = []  # per open brace: "scope" (namespace/class level), "function" or "block"
    header_start = 0
    line = 1
    open_line = []
    # A constructor's brace initialisers (a_{x}) look like a function before the body: a '{' right
    # after such a block (only initialisers between) continues it.
    continued = None  # (depth, index in found) of the last function closed at scope level
    for i, c in enumerate(code):
        if c == "\n":
            line += 1
        elif c in ";{}":
            if c == "{":
                inside = any(kind != "scope" for kind in stack)
                header = code[header_start:i]
                if inside:
                    stack.append("block")
                    open_line.append(line)
                elif continued and continued[0] == len(stack) and (not header.strip() or header.strip().startswith(",")):
                    first, _ = found.pop(continued[1])
                    stack.append("function")
                    open_line.append(first)
                else:
                    stack.append("function" if is_function_header(header) else "scope")
                    open_line.append(line)
                continued = None
            elif c == "}":
                continued = None
                if stack:
                    kind = stack.pop()
                    start = open_line.pop()
                    if kind == "function":
                        found.append((start, line))
                        if not any(k != "scope" for k in stack):
                            continued = (len(stack), len(found) - 1)
            else:
                continued = None
            header_start = i + 1
    return sorted(found)


def check(root):
    problems = []
    for folder in FOLDERS:
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in (".cpp", ".hpp", ".h") or not path.is_file():
                continue
            text = path.read_text(encoding="utf-8", errors="replace")
            rel = path.relative_to(root)
            lines = text.count("\n") + (0 if text.endswith("\n") else 1)
            if lines > MAX_FILE_LINES:
                problems.append(f"{rel}: {lines} lines (at most {MAX_FILE_LINES})")
            for first, last in functions(strip_code(text)):
                length = last - first + 1
                if length > MAX_FUNCTION_LINES:
                    problems.append(f"{rel}:{first}: function of {length} lines (at most {MAX_FUNCTION_LINES})")
    return problems


def self_test():
    """The scanner on small sources whose function lengths are known."""
    def body(lines):  # a function whose body spans `lines` lines, '{' and '}' included
        return "int f(int x) {\n" + "    x += 1;\n" * (lines - 2) + "}\n"
    cases = [
        (body(80), [80]),
        (body(81), [81]),
        # braces in comments, strings, characters and raw strings do not count
        ('void g() {\n  // {\n  /* { */ const char* s = "{{";\n  char c = \'{\';\n  auto r = R"x({)x";\n}\n', [6]),
        # namespaces and classes are scopes; inline methods and lambdas inside functions
        ("namespace a {\nstruct S {\n  int m() const {\n    return 1;\n  }\n};\n}\n", [3]),
        ("void h() {\n  auto l = [] {\n    return 0;\n  };\n}\n", [5]),
        ("template <class T>\nstruct B {\n  T v{};\n};\nconstexpr int k[] = {1, 2};\n", []),
        ("A::A(int x) : a_(x), b_{x}, c_{x} {\n  go();\n}\nvoid k() {\n}\nvoid m() {\n}\n", [3, 2, 2]),
    ]
    failures = 0
    for source, expected in cases:
        got = [last - first + 1 for first, last in functions(strip_code(source))]
        if got != expected:
            failures += 1
            print(f"self-test: expected {expected}, got {got} for:\n{source}")
    print(f"check_sizes self-test: {len(cases) - failures}/{len(cases)} cases")
    return 1 if failures else 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    root = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent
    problems = check(root)
    for p in problems:
        print(p)
    print(f"check_sizes: {len(problems)} violation(s) in {', '.join(FOLDERS)} of {root}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
