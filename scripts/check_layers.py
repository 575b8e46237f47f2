#!/usr/bin/env python3
"""The layers of gapfem (docs/architecture.md) checked from the #include lines of src/.

A file may include headers of its own layer and of the layers below it, never above. The layers,
lowest first, are the LAYERS table; a file's layer is the first entry whose prefix matches its
path under src/. Prints every include that runs upward and exits 1 when there is one (CI runs it);
`--graph` prints the include counts between layers instead.

Also checked (issue 44): `getenv` is read only in the application layer (apps/ and src/app/), so
every switch deeper down is an option passed down to it.
"""
import argparse
import pathlib
import re
import sys

# (name, path prefixes under src/), lowest first
LAYERS = [
    ("common", ["common/"]),
    ("model", ["model/"]),
    ("fe", ["fe/"]),  # quadrature, shape functions, element faces: below the elements
    ("elements", ["elements/"]),
    ("linalg", ["linalg/"]),
    ("parallel", ["parallel/"]),
    ("fem", ["fem/"]),
    ("results", ["results/"]),  # frames and the writers' interface: below solver and output
    ("solver", ["solver/"]),
    ("output", ["output/"]),  # writers format what they are given; they never solve
    ("io", ["io/"]),
    ("app", ["app/"]),
]

# Pairs that are not allowed although the first is above the second: writers format the frames
# they are given and never run the analysis.
FORBIDDEN = {("output", "solver")}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
GETENV = re.compile(r"\bgetenv\s*\(")


def layer_of(rel: str):
    for rank, (name, prefixes) in enumerate(LAYERS):
        if any(rel.startswith(p) for p in prefixes):
            return rank, name
    return None, None


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=pathlib.Path(__file__).resolve().parent.parent)
    ap.add_argument("--graph", action="store_true", help="print include counts between layers")
    args = ap.parse_args()
    src = pathlib.Path(args.root) / "src"
    violations, counts, unknown = [], {}, []
    getenv_uses = []
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".hpp", ".cpp", ".h"):
            continue
        rel = path.relative_to(src).as_posix()
        rank, name = layer_of(rel)
        if rank is None:
            unknown.append(rel)
            continue
        text = path.read_text(errors="replace")
        if name != "app":
            for m in GETENV.finditer(text):
                line = text.count("\n", 0, m.start()) + 1
                getenv_uses.append(f"src/{rel}:{line}")
        for m in INCLUDE.finditer(text):
            inc = m.group(1)
            if not (src / inc).exists():
                continue  # a header outside src/ (include/gapfem/plugin.hpp, generated files)
            irank, iname = layer_of(inc)
            if irank is None:
                continue
            counts[(name, iname)] = counts.get((name, iname), 0) + 1
            if irank > rank or (name, iname) in FORBIDDEN:
                line = text.count("\n", 0, m.start()) + 1
                violations.append(f"src/{rel}:{line}: {name} includes {iname} ({inc})")
    if args.graph:
        for (a, b), n in sorted(counts.items()):
            print(f"{a:>9} -> {b:<9} {n}")
        return 0
    for u in unknown:
        print(f"src/{u}: in no layer of scripts/check_layers.py (add its folder to LAYERS)")
    for v in violations:
        print(v)
    for g in getenv_uses:
        print(f"{g}: getenv outside the application layer (pass the setting down as an option)")
    bad = len(violations) + len(unknown) + len(getenv_uses)
    order = " < ".join(n for n, _ in LAYERS)
    print(f"layers {order}: {len(violations)} upward includes, {len(getenv_uses)} getenv "
          f"outside the application layer, {len(unknown)} files in no layer")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
