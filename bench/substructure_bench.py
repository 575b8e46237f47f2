#!/usr/bin/env python3
"""Substructure benchmark: a linear block reduced to the DOFs its gap supports and loads act on,
then solved with its contact problem on the reduced model, against the full model.

The model: a quarter block of C3D8 (symmetry planes x = 0 and y = 0) resting on GAPUNI supports to
fixed ground nodes, under vertical and lateral loads at top nodes, in two steps (load, then most of
it released, so that gaps close and open). Clearances are graded with the distance from the
centre, so the contact set grows over the increments (automatic incrementation, initial increment
0.1 of the step).

Three decks, run one after the other in a scratch folder:
  gen.inp   *SUBSTRUCTURE GENERATE: the block reduced onto the supported and loaded nodes
  use.inp   the reduced block (one Z1 element) with the gaps and loads
  full.inp  the block meshed, with the same gaps and loads

It prints the wall times (generation, usage, full), the speed-up of the contact problem
(full / usage) and how well the answers agree (gap forces, closed gaps, displacements at the
supported nodes).

  python3 bench/substructure_bench.py --n 40 --gaps 500        # ~200k DOFs, 500 gaps
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def decks(n, nz, n_gaps, n_loads):
    """The three decks. n x n x nz elements of side 1 (quarter model)."""
    def nid(i, j, k):
        return 1 + i + (n + 1) * (j + (n + 1) * k)

    nodes = []
    for k in range(nz + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                nodes.append((nid(i, j, k), float(i), float(j), float(k)))
    mesh = ["*NODE, NSET=NALL\n"] + [f"{a}, {x}, {y}, {z}\n" for a, x, y, z in nodes]
    mesh.append("*ELEMENT, TYPE=C3D8, ELSET=BLOCK\n")
    e = 1
    for k in range(nz):
        for j in range(n):
            for i in range(n):
                c = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                     nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                     nid(i, j + 1, k + 1)]
                mesh.append(f"{e}, " + ", ".join(map(str, c)) + "\n")
                e += 1
    mesh.append("*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n")
    mesh.append("*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL\n")
    sym = ["*NSET, NSET=XSYM\n"] + [f"{nid(0, j, k)}\n" for k in range(nz + 1) for j in range(n + 1)]
    sym += ["*NSET, NSET=YSYM\n"] + [f"{nid(i, 0, k)}\n" for k in range(nz + 1) for i in range(n + 1)]
    # supported nodes: bottom nodes off the symmetry planes, on a regular sub-grid
    candidates = [nid(i, j, 0) for j in range(1, n + 1) for i in range(1, n + 1)]
    step = len(candidates) / min(n_gaps, len(candidates))
    bottom = [candidates[int(k * step)] for k in range(min(n_gaps, len(candidates)))]
    ml = max(1, int(math.ceil(math.sqrt(n * n / n_loads))))
    top = [nid(i, j, nz) for j in range(1, n + 1, ml) for i in range(1, n + 1, ml)][:n_loads]
    R = math.hypot(n, n)
    coords = {a: (x, y, z) for a, x, y, z in nodes}
    r0 = min(math.hypot(coords[b][0], coords[b][1]) for b in bottom)  # the first support: closed
    ground, gaps, elsets = [], [], []
    for g, b in enumerate(bottom):
        x, y, z = coords[b]
        ground.append(f"{900000 + g}, {x}, {y}, {z - 1.0}\n")
        gaps.append(f"{800000 + g}, {b}, {900000 + g}\n")
        d = 2e-3 * ((math.hypot(x, y) - r0) / R) ** 2
        elsets.append(f"*ELSET, ELSET=G{g}\n{800000 + g}\n*GAP, ELSET=G{g}\n{d:.6g}, 0., 0., -1.\n")
    contact = ["*NODE, NSET=GROUND\n"] + ground + ["*ELEMENT, TYPE=GAPUNI, ELSET=GAPS\n"] + gaps + elsets
    total = 10.0 * n * n  # a pressure of 10 on the top face
    steps = []
    for f in (1.0, 0.2):
        steps.append("*STEP, INC=200\n*STATIC\n0.1, 1.\n*CLOAD\n")
        for t in top:
            steps.append(f"{t}, 3, {-f * total / len(top):.9g}\n{t}, 1, {f * 0.02 * total / len(top):.9g}\n")
        steps.append("*END STEP\n")
    gen = ["*HEADING\nblock reduced to its supports and load points\n"] + mesh + sym
    gen.append("*BOUNDARY\nXSYM, 1, 1\nYSYM, 2, 2\n*STEP\n*SUBSTRUCTURE GENERATE, TYPE=Z1\n"
               "*RETAINED NODAL DOFS\n")
    retained = bottom + top
    gen += [f"{r}, 1, 3\n" for r in retained] + ["*END STEP\n"]
    use = ["*HEADING\nreduced block on gaps\n*NODE, NSET=RETAINED\n"]
    use += [f"{r}, {coords[r][0]}, {coords[r][1]}, {coords[r][2]}\n" for r in sorted(retained)]
    use.append("*ELEMENT, TYPE=Z1, ELSET=SUB, FILE=gen\n1")
    for i, r in enumerate(sorted(retained)):
        use.append((",\n" if i % 12 == 11 else ", ") + str(r))
    use.append("\n*SUBSTRUCTURE PROPERTY, ELSET=SUB\n0., 0., 0.\n")
    use += contact + ["*BOUNDARY\nGROUND, 1, 3\n"] + steps
    full = ["*HEADING\nfull block on gaps\n"] + mesh + sym + contact
    full += ["*BOUNDARY\nXSYM, 1, 1\nYSYM, 2, 2\nGROUND, 1, 3\n"] + steps
    dofs = 3 * len(nodes)
    return "".join(gen), "".join(use), "".join(full), dofs, 3 * len(retained), len(bottom)


def run(gapfem, deck, cwd, extra=()):
    t = time.time()
    p = subprocess.run([gapfem, "-q", *extra, deck], cwd=cwd, capture_output=True, text=True)
    dt = time.time() - t
    if p.returncode != 0:
        sys.exit(f"{deck} failed ({p.returncode}):\n{p.stderr}")
    return dt


def gap_forces(path):
    doc = json.load(open(path))
    out = []
    for step in doc["steps"]:
        last = step["frames"][-1]
        f = {k: v["gap"]["normal_force"] for k, v in last["elements"].items() if "gap" in v}
        out.append(f)
    return doc, out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--gapfem", default=os.path.join(HERE, "..", "build", "release", "gapfem"))
    ap.add_argument("--n", type=int, default=40, help="elements along x and y")
    ap.add_argument("--nz", type=int, default=None, help="elements through the height (default n)")
    ap.add_argument("--gaps", type=int, default=500)
    ap.add_argument("--loads", type=int, default=100, help="loaded top nodes")
    ap.add_argument("--work", default="/tmp/gapfem-substructure-bench")
    ap.add_argument("--skip-full", action="store_true")
    a = ap.parse_args()
    gapfem = os.path.abspath(a.gapfem)
    os.makedirs(a.work, exist_ok=True)
    gen, use, full, dofs, retained, n_gaps = decks(a.n, a.nz or a.n, a.gaps, a.loads)
    for name, text in (("gen.inp", gen), ("use.inp", use), ("full.inp", full)):
        open(os.path.join(a.work, name), "w").write(text)
    print(f"model: {dofs} DOFs, {n_gaps} GAPUNI, {retained} retained DOFs")
    t_gen = run(gapfem, "gen.inp", a.work)
    print(f"generation (reduction, written to gen_Z1.sub): {t_gen:.2f} s")
    t_use = run(gapfem, "use.inp", a.work)
    print(f"usage (the contact problem on the reduced block): {t_use:.2f} s")
    if a.skip_full:
        return
    t_full = run(gapfem, "full.inp", a.work)
    print(f"full model: {t_full:.2f} s")
    du, fu = gap_forces(os.path.join(a.work, "use.results.json"))
    df, ff = gap_forces(os.path.join(a.work, "full.results.json"))
    for s, (x, y) in enumerate(zip(fu, ff)):
        scale = max(abs(v) for v in y.values()) or 1.0
        diff = max(abs(x[k] - y[k]) for k in y) / scale
        closed_u = sum(1 for v in x.values() if v > 0)
        closed_f = sum(1 for v in y.values() if v > 0)
        print(f"step {s + 1}: closed gaps {closed_u} (reduced) / {closed_f} (full), largest gap "
              f"force difference {diff:.2e} of the largest force")
    su, sf = du["summary"], df["summary"]
    for label, d in (("reduced", su), ("full", sf)):
        print(f"  {label}: {d.get('increments')} increments, {d.get('iterations')} iterations, "
              f"{d.get('factorizations')} factorisations; "
              + ", ".join(f"{k} {v:.2f} s" for k, v in d["seconds"].items() if v > 0.005))
    print(f"speed-up of the contact problem: {t_full / t_use:.1f}x "
          f"(full {t_full:.2f} s / reduced {t_use:.2f} s); with the generation: "
          f"{t_full / (t_use + t_gen):.1f}x")


if __name__ == "__main__":
    main()
