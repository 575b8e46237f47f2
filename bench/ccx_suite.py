#!/usr/bin/env python3
"""Run gapfem on every deck of a CalculiX test suite and count what runs and what blocks.

The CalculiX test decks are third-party files: this script reads them from a checkout the user
provides (e.g. the public repository Dhondtguido/CalculiX, folder test/) and never copies them.
For each deck it runs `gapfem --check`-like: the real solver with a time limit, and classifies

  ran         exit 0 (completed) or 2 (the analysis stopped: convergence, limits)
  input       exit 1: an input error; the first message is parsed for the keyword or element
              type that blocks the deck (the counts name what to implement next)
  timeout     the time limit was reached
  crash       any other exit status

and prints the counts, the blocking keywords and element types by frequency, and (with --list)
every deck with its outcome. Example:

  python3 bench/ccx_suite.py /path/to/CalculiX/test --gapfem build/release/gapfem --timeout 20
"""
import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile


def classify(message):
    """The blocking construct of an input error: an unknown keyword, element type or parameter."""
    m = re.search(r"the keyword (\*[A-Z][A-Z _-]*) is not supported", message)
    if m:
        return "keyword " + m.group(1).strip()
    m = re.search(r"element type ([A-Z0-9]+)", message)
    if m:
        return "element " + m.group(1)
    m = re.search(r"(\*[A-Z][A-Z _-]*): (?:the )?parameter ([A-Z][A-Z _-]*)", message)
    if m:
        return "parameter " + m.group(1).strip() + ", " + m.group(2).strip()
    m = re.search(r"(\*[A-Z][A-Z _-]*):", message)
    if m:
        return "other " + m.group(1).strip()
    return "other"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("suite", help="folder with the .inp decks (e.g. CalculiX/test)")
    ap.add_argument("--gapfem", default="build/release/gapfem")
    ap.add_argument("--timeout", type=float, default=20.0)
    ap.add_argument("--list", action="store_true", help="print every deck's outcome")
    args = ap.parse_args()
    decks = sorted(f for f in os.listdir(args.suite) if f.endswith(".inp"))
    outcome = {}
    blockers = collections.Counter()
    first_lines = {}
    with tempfile.TemporaryDirectory() as out:
        for deck in decks:
            path = os.path.join(args.suite, deck)
            try:
                p = subprocess.run([args.gapfem, "-q", "-o", out, path], capture_output=True,
                                   text=True, timeout=args.timeout)
                code = p.returncode
                msg = (p.stderr or p.stdout).strip().splitlines()
            except subprocess.TimeoutExpired:
                outcome[deck] = "timeout"
                continue
            if code in (0, 2):
                outcome[deck] = "ran" if code == 0 else "ran (stopped)"
            elif code == 1:
                first = next((l for l in msg if "error" in l.lower() or ".inp:" in l), msg[0] if msg else "")
                what = classify(first)
                outcome[deck] = "input: " + what
                blockers[what] += 1
                first_lines[deck] = first
            else:
                outcome[deck] = f"crash (exit {code})"
    counts = collections.Counter(v.split(":")[0] for v in outcome.values())
    print(f"{len(decks)} decks: " + ", ".join(f"{k} {v}" for k, v in counts.most_common()))
    print("blocking constructs (first input error of each deck):")
    for what, n in blockers.most_common():
        print(f"  {n:4d}  {what}")
    if args.list:
        for deck in decks:
            print(f"{deck}: {outcome[deck]}" + (f"  [{first_lines[deck]}]" if deck in first_lines else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
