#!/usr/bin/env python3
"""Functions in src/ longer than a limit (issue 44: none over 120 lines), found from the text.

A function is a definition whose line ends with `{` after a parameter list, at any depth, up to
its matching `}`; lambdas and control statements are not counted. Prints each long one with its
length and exits 1 when there is one; CI runs it (scripts/test.sh).
"""
import argparse
import pathlib
import re
import sys

DEFINITION = re.compile(
    r"\)\s*(const)?\s*(noexcept)?\s*(override)?\s*(final)?\s*(->\s*[\w:<>&* ]+)?\s*\{\s*$")
CONTROL = re.compile(r"\s*(if|for|while|switch|else|do|catch|return)\b")


def code_of(line: str) -> str:
    line = re.sub(r"//.*", "", line)
    line = re.sub(r'"(\\.|[^"\\])*"', '""', line)
    return re.sub(r"'(\\.|[^'\\])'", "''", line)


def long_functions(path: pathlib.Path, limit: int):
    depth, start, start_depth, name = 0, None, 0, ""
    for i, line in enumerate(path.read_text(errors="replace").split("\n")):
        code = code_of(line)
        opens, closes = code.count("{"), code.count("}")
        if (start is None and opens > closes and DEFINITION.search(code)
                and not CONTROL.match(code) and "=" not in code.split("(")[0]
                and "[" not in code.split("(")[0]):
            start, start_depth, name = i, depth, line.strip()
        depth += opens - closes
        if start is not None and depth <= start_depth:
            if i - start + 1 > limit:
                yield i - start + 1, start + 1, name
            start = None


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--limit", type=int, default=120)
    ap.add_argument("--root", default=pathlib.Path(__file__).resolve().parent.parent)
    args = ap.parse_args()
    src = pathlib.Path(args.root) / "src"
    found = []
    for path in sorted(src.rglob("*.[ch]pp")):
        for n, line, name in long_functions(path, args.limit):
            found.append((n, f"src/{path.relative_to(src).as_posix()}:{line}", name[:70]))
    for n, where, name in sorted(found, reverse=True):
        print(f"{where}: {n} lines: {name}")
    print(f"{len(found)} functions longer than {args.limit} lines")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
