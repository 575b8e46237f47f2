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

and prints the counts, the blocking keywords and element types by frequency, the agreement of the
displacements with the deck's .dat.ref for every deck that ran, and (with --list) every deck with
its outcome. Example:

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
    """The construct an input error names: an unknown keyword, element type or parameter."""
    m = re.search(r"the keyword (\*[A-Z][A-Z0-9 _-]*) is not supported", message)
    if m:
        return "keyword " + m.group(1).strip()
    m = re.search(r"the procedure (\*[A-Z][A-Z0-9 _-]*) is not supported", message)
    if m:
        return "procedure " + m.group(1).strip()
    m = re.search(r"TYPE=([A-Z0-9]+): gapfem does not know this element type", message)
    if m:
        return "element " + m.group(1)
    m = re.search(r"(\*[A-Z][A-Z0-9 _-]*): ([A-Z][A-Z0-9 _-]*)(=[^:]*)?: this parameter is not supported", message)
    if m:
        return "parameter " + m.group(1).strip() + ", " + m.group(2).strip()
    m = re.search(r"(\*[A-Z][A-Z0-9 _-]*): (.*)", message)
    if m:
        return "other " + m.group(1).strip() + ": " + re.sub(r"(?<![A-Za-z])[-+]?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?", "#", m.group(2))[:70]
    return "other"


def blockers_of(lines):
    """The distinct constructs named by the error lines of one run (the summary line skipped)."""
    found = []
    for line in lines:
        if "input errors; fix each of them" in line or not re.search(r"\.inp:\d+:", line):
            continue
        what = classify(line)
        if what not in found:
            found.append(what)
    return found


def reference_displacements(path):
    """Last 'displacements (vx,vy,vz)' block of each step of a CalculiX .dat(.ref) file:
    {step: {node: (ux, uy, uz)}}."""
    out, step, block = {}, 0, None
    with open(path, errors="replace") as f:
        for line in f:
            m = re.match(r"\s*S T E P\s+(\d+)", line)
            if m:
                step, block = int(m.group(1)), None
                continue
            if re.match(r"\s*displacements \(vx,vy,vz\)", line):
                block = {}
                out[step] = block
                continue
            if block is None:
                continue
            fields = line.split()
            if len(fields) == 4 and re.match(r"^\d+$", fields[0]):
                try:
                    block[int(fields[0])] = tuple(float(v.replace("D", "E")) for v in fields[1:])
                except ValueError:
                    block = None
            elif fields:
                block = None
    return out


def global_u(node, to_global):
    """U of a JSON node entry; nodes with "axes" report their local system, turned to global
    components when the deck prints with GLOBAL=YES."""
    u = list(node["U"]) + [0.0] * (3 - len(node["U"]))
    q = node.get("axes")
    if not q or not to_global:
        return tuple(u)
    return tuple(q[j] * u[0] + q[3 + j] * u[1] + q[6 + j] * u[2] for j in range(3))


def gapfem_displacements(path, to_global=False):
    """{step: {node: (u1, u2, u3)}} from job.results.json (the last frame of each step)."""
    import json
    with open(path) as f:
        data = json.load(f)
    out = {}
    for st in data.get("steps", []):
        frames = st.get("frames", [])
        if not frames:
            continue
        nodes = frames[-1].get("nodes", {})
        out[st["step"]] = {int(k): global_u(v, to_global) for k, v in nodes.items()
                           if k.isdigit() and "U" in v}
    return out


def agreement(ref, got):
    """Largest |u - u_ref| over the reference's nodes and steps, relative to the largest |u_ref|."""
    err, scale, n = 0.0, 0.0, 0
    for step, nodes in ref.items():
        mine = got.get(step)
        if mine is None:
            return None
        for node, u in nodes.items():
            if node not in mine:
                continue
            n += 1
            scale = max(scale, max(abs(c) for c in u))
            err = max(err, max(abs(a - b) for a, b in zip(mine[node], u)))
    if n == 0:
        return None
    return err / scale if scale > 0 else err


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("suite", help="folder with the .inp decks (e.g. CalculiX/test)")
    ap.add_argument("--gapfem", default="build/release/gapfem")
    ap.add_argument("--timeout", type=float, default=20.0)
    ap.add_argument("--list", action="store_true", help="print every deck's outcome")
    args = ap.parse_args()
    decks = sorted(f for f in os.listdir(args.suite) if f.endswith(".inp"))
    outcome = {}
    per_deck = {}
    compared = {}
    with tempfile.TemporaryDirectory() as out:
        for deck in decks:
            path = os.path.join(args.suite, deck)
            try:
                p = subprocess.run([args.gapfem, "-q", "-o", out, path], capture_output=True,
                                   text=True, timeout=args.timeout)
            except subprocess.TimeoutExpired:
                outcome[deck] = "timeout"
                continue
            code = p.returncode
            if code in (0, 2):
                outcome[deck] = "ran" if code == 0 else "ran (stopped)"
                ref = os.path.join(args.suite, deck[:-4] + ".dat.ref")
                res = os.path.join(out, deck[:-4] + ".results.json")
                if code == 0 and os.path.exists(ref) and os.path.exists(res):
                    r = reference_displacements(ref)
                    with open(os.path.join(args.suite, deck), errors="replace") as f:
                        to_global = re.search(r"^\*NODE PRINT[^\n]*GLOBAL=YES", f.read(),
                                              re.I | re.M) is not None
                    compared[deck] = (agreement(r, gapfem_displacements(res, to_global))
                                      if r else None)
            elif code == 1:
                per_deck[deck] = blockers_of((p.stderr + p.stdout).splitlines())
                outcome[deck] = "input"
            else:
                outcome[deck] = f"crash (exit {code})"
    counts = collections.Counter(outcome.values())
    print(f"{len(decks)} decks: " + ", ".join(f"{k} {v}" for k, v in counts.most_common()))
    appears = collections.Counter(b for bs in per_deck.values() for b in bs)
    alone = collections.Counter(bs[0] for bs in per_deck.values() if len(bs) == 1)
    print("constructs that stop decks (decks naming it / decks it alone stops):")
    for what, n in appears.most_common():
        print(f"  {n:4d} {alone.get(what, 0):4d}  {what}")
    print("agreement with .dat.ref (max |u - u_ref| / max |u_ref| over the printed nodes, last "
          "increment of each step) for the decks that ran:")
    for deck, rel in sorted(compared.items()):
        print(f"  {deck:28s} " + ("no displacement table to compare" if rel is None
                                  else f"{rel:.2e}"))
    if args.list:
        for deck in decks:
            extra = "; ".join(per_deck.get(deck, []))
            print(f"{deck}: {outcome[deck]}" + (f"  [{extra}]" if extra else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
