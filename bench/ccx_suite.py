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
its outcome.

Decks of CalculiX's own physics, which gapfem does not set out to have, are out of scope and
counted apart (scope_of): fluid networks and CFD, design sensitivity and optimisation (with its
Green functions and robust design), mesh refinement, crack propagation and fatigue, and
electromagnetics. Every in-scope deck that stops on an input error gets its first blocker's
class (kind_of): a physics construct of a later issue (procedure, material, contact, element)
or "not physics" (a reader convenience, an output request, a model feature this project still
owes). Example:

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


# CalculiX's physics outside gapfem's scope: (class, keywords that mark it, element types)
OUT_OF_SCOPE = [
    ("fluid networks and CFD",
     {"*FLUID SECTION", "*FLUID SECTIONS", "*FLUID CONSTANTS", "*CFD", "*NETWORK MPC",
      "*SPECIFIC GAS CONSTANT", "*VALUES AT INFINITY"}, r"^(D|F[23]D\d+)$"),
    ("design sensitivity and optimisation",
     {"*SENSITIVITY", "*DESIGNVARIABLES", "*DESIGN VARIABLES", "*DESIGN RESPONSE", "*OBJECTIVE",
      "*FEASIBLE DIRECTION", "*FILTER", "*CONSTRAINT", "*ROBUST DESIGN", "*CORRELATION LENGTH",
      "*GEOMETRIC TOLERANCES", "*GREEN"}, None),
    ("mesh refinement", {"*REFINE MESH", "*USE REFINED MESH"}, None),
    ("crack propagation and fatigue", {"*CRACK PROPAGATION", "*HCF"}, None),
    ("electromagnetics", {"*ELECTROMAGNETICS", "*MAGNETIC PERMEABILITY",
                          "*ELECTRICAL CONDUCTIVITY"}, None),
]

# The first blocker's class for an in-scope deck: constructs of the later issues by keyword
PHYSICS = {
    "material": {"*PLASTIC", "*CREEP", "*USER MATERIAL", "*DEPVAR", "*HYPERELASTIC", "*HYPERFOAM",
                 "*DEFORMATION PLASTICITY", "*MOHR COULOMB", "*MOHR COULOMB HARDENING",
                 "*RATE DEPENDENT", "*CYCLIC HARDENING", "*DAMAGE INITIATION", "*CHANGE PLASTIC",
                 "*CHANGE MATERIAL", "*VISCOELASTIC", "*ORIENTATION", "*USER SECTION",
                 "*INITIAL STRAIN INCREASE"},
    "contact": {"*CONTACT PAIR", "*SURFACE INTERACTION", "*SURFACE BEHAVIOR", "*CONTACT DAMPING",
                "*CLEARANCE", "*PRE-TENSION SECTION", "*CHANGE FRICTION", "*CHANGE CONTACT TYPE",
                "*CHANGE SURFACE BEHAVIOR", "*GAP CONDUCTANCE", "*GAP HEAT GENERATION",
                "*CONTACT PRINT", "*CONTACT FILE", "*CONTACT OUTPUT", "*CONTACT CONTROLS",
                "*CONTACT INTERFERENCE"},
    "procedure": {"*VISCO", "*COMPLEX FREQUENCY", "*SELECT CYCLIC SYMMETRY MODES",
                  "*UNCOUPLED TEMPERATURE-DISPLACEMENT"},
}


def deck_keywords(path):
    """The keywords (upper case, without parameters) and element types a deck uses."""
    keywords, types = set(), set()
    with open(path, errors="replace") as f:
        for line in f:
            if not line.startswith("*") or line.startswith("**"):
                continue
            kw = line.split(",")[0].strip().upper()
            keywords.add(re.sub(r"\s+", " ", kw))
            m = re.search(r"TYPE\s*=\s*([A-Za-z0-9]+)", line)
            if kw == "*ELEMENT" and m:
                types.add(m.group(1).upper())
    return keywords, types


def scope_of(path):
    """None for an in-scope deck, else the class of CalculiX physics outside gapfem's scope."""
    keywords, types = deck_keywords(path)
    for name, marks, element in OUT_OF_SCOPE:
        if keywords & marks or (element and any(re.match(element, t) for t in types)):
            return name
    return None


def kind_of(blocker):
    """physics (procedure, material, contact, element) or not physics, for a blocker of
    classify()."""
    if blocker.startswith("element "):
        return "physics: element"
    if blocker.startswith("procedure "):
        return "physics: procedure"
    m = re.match(r"(?:keyword|parameter|other) (\*[A-Z][A-Z0-9 _-]*)", blocker)
    kw = m.group(1).strip() if m else ""
    for kind, marks in PHYSICS.items():
        if kw in marks:
            return "physics: " + kind
    if kw == "*FRICTION" or (kw == "*ELASTIC" and "TYPE" in blocker):
        return "physics: " + ("contact" if kw == "*FRICTION" else "material")
    return "not physics"


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
    scope = {d: scope_of(os.path.join(args.suite, d)) for d in decks}
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
    out_of_scope = collections.Counter(v for v in scope.values() if v)
    inside = [d for d in decks if not scope[d]]
    print(f"out of scope (CalculiX's own physics): {sum(out_of_scope.values())}: " +
          ", ".join(f"{k} {v}" for k, v in out_of_scope.most_common()))
    in_counts = collections.Counter(outcome[d] for d in inside)
    print(f"in scope: {len(inside)}: " + ", ".join(f"{k} {v}" for k, v in in_counts.most_common()))
    kinds = collections.Counter(kind_of(per_deck[d][0]) for d in inside
                                if outcome[d] == "input" and per_deck.get(d))
    print("first blocker of the in-scope decks that stop on input: " +
          ", ".join(f"{k} {v}" for k, v in kinds.most_common()))
    print("in-scope decks whose first blocker is not physics:")
    for d in inside:
        if outcome[d] == "input" and per_deck.get(d) and kind_of(per_deck[d][0]) == "not physics":
            print(f"  {d:28s} {per_deck[d][0]}")
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
            where = f"out of scope ({scope[deck]})" if scope[deck] else "in scope"
            first = (f" first blocker: {kind_of(per_deck[deck][0])}" if per_deck.get(deck)
                     else "")
            print(f"{deck}: {where}: {outcome[deck]}{first}" + (f"  [{extra}]" if extra else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
