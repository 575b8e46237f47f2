#!/usr/bin/env python3
"""Generate the natural-frequency benchmark deck: bench/gen_block.py's quarter block of C3D8 on its
GAPUNI foundation (or with a fixed base, --no-gaps), given a density, a first general *STATIC step
that presses the block onto its supports with gen_block.py's top pressure (a central patch of gaps
closes, the outer gaps stay open), then a natural-frequency step about that base state:

    *STEP, PERTURBATION
    *FREQUENCY
    20
    *END STEP

The deck runs unchanged in gapfem and in CalculiX (ccx). ccx takes the end of the preceding
*STATIC step as the base state of the frequency step when that step has PERTURBATION (without it
ccx 2.20 also runs, but its frequencies of the C3D20 deck below are then ~1e-4 off gapfem's and
its own PERTURBATION answer: of the order of p / E, as if the preload's initial stress were left
out); gapfem treats *FREQUENCY as a perturbation step with or without the parameter. With
--penalty the gaps carry CalculiX's penalty fields 6-7 (the form ccx runs; gapfem then uses the
same law, whose tangent dF/dg at the base state enters the eigenproblem in both codes); without it
they are exact hard gaps (gapfem only: closed gaps become constraint rows of the eigenproblem,
docs/theory/frequency.md §2).

With gaps the static step has NLGEOM (ccx iterates on GAPUNI only in a nonlinear step), so both
codes include the initial-stress stiffness of the preload in the frequency step. Without NLGEOM
they differ: gapfem, as Abaqus documents, then uses the small-strain stiffness, while ccx adds the
preload's initial-stress stiffness in a PERTURBATION step anyway (a relative difference of about
p / E in the frequencies: 6e-5 with the default pressure and E); the --no-gaps suite cases
therefore set --nlgeom yes.

The symmetry planes x = 0 and y = 0 and the closed gaps hold every rigid-body motion, so there is
no zero eigenvalue.

gapfem's C3D8 is Abaqus's B-bar element, ccx's is fully integrated: on a coarse mesh that alone
puts the two codes' frequencies a few per cent apart. --element C3D20 writes the same block with
20-node bricks instead (this script's own mesh: the same grid with mid-side nodes, a GAPUNI at
every bottom node, corner and mid-side, and the same clearance rule), an element both codes
integrate alike (3x3x3 Gauss, consistent mass), for a comparison of the eigenproblem itself.
--element C3D8I swaps the type of gen_block.py's mesh (incompatible modes; on the 6x6x6 fixed-base
block ccx's C3D8I frequencies are 2-14 % below gapfem's, not investigated).

Usage: gen_frequency_block.py --nx 6 --nz 6 --penalty 1e7 -o job.inp
"""
import argparse
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def quadratic_block(a):
    """gen_block.py's deck (gaps or fixed base, NLGEOM with gaps, pressure on the top) with C3D20
    elements: (deck text, summary line). Nodes on the grid of half the element size that have at
    most one odd index (the corner and mid-side nodes of serendipity bricks)."""
    nx, ny, nz = a.nx, a.nx, a.nz
    L, H = 1.0, 1.0
    ids = {}
    coords = []
    for k in range(2 * nz + 1):
        for j in range(2 * ny + 1):
            for i in range(2 * nx + 1):
                if (i % 2) + (j % 2) + (k % 2) <= 1:
                    ids[(i, j, k)] = len(coords) + 1
                    coords.append((L * i / (2 * nx), L * j / (2 * ny), H * k / (2 * nz)))
    n_block = len(coords)
    lines = ["*HEADING",
             f"Quarter block {nx}x{ny}x{nz} C3D20 {'fixed base' if a.no_gaps else 'on a GAPUNI foundation'}",
             "*NODE, NSET=NALL"]
    lines += [f"{n}, {x:.9g}, {y:.9g}, {z:.9g}" for n, (x, y, z) in enumerate(coords, 1)]
    base = [(i, j) for j in range(2 * ny + 1) for i in range(2 * nx + 1) if (i, j, 0) in ids]
    if not a.no_gaps:
        lines.append("*NODE, NSET=GROUND")
        lines += [f"{n_block + ids[(i, j, 0)]}, {L * i / (2 * nx):.9g}, {L * j / (2 * ny):.9g}, -1."
                  for i, j in base]
    lines.append("*ELEMENT, TYPE=C3D20, ELSET=BLOCK")
    e = 0
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                e += 1
                I, J, K = 2 * i, 2 * j, 2 * k
                c = [(I, J, K), (I + 2, J, K), (I + 2, J + 2, K), (I, J + 2, K),
                     (I, J, K + 2), (I + 2, J, K + 2), (I + 2, J + 2, K + 2), (I, J + 2, K + 2)]
                mid = lambda p, q: tuple((u + v) // 2 for u, v in zip(c[p], c[q]))
                edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4),
                         (0, 4), (1, 5), (2, 6), (3, 7)]
                n = [ids[p] for p in c] + [ids[mid(p, q)] for p, q in edges]
                lines.append(f"{e}, " + ", ".join(map(str, n[:15])) + ",")
                lines.append(", ".join(map(str, n[15:])))
    n_solid = e
    lines += [f"*ELSET, ELSET=TOP, GENERATE\n{n_solid - nx * ny + 1}, {n_solid}, 1",
              "*SURFACE, NAME=STOP, TYPE=ELEMENT\nTOP, S2",
              f"*MATERIAL, NAME=STEEL\n*ELASTIC\n{a.E:.9g}, 0.3",
              "*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL"]

    def nset(name, members):
        lines.append(f"*NSET, NSET={name}")
        lines.extend(", ".join(map(str, members[s:s + 16])) for s in range(0, len(members), 16))

    nset("XSYM", [n for (i, j, k), n in ids.items() if i == 0])
    nset("YSYM", [n for (i, j, k), n in ids.items() if j == 0])
    nset("BASE", [ids[(i, j, 0)] for i, j in base])
    if not a.no_gaps:
        levels = {}
        radius = L * 2 ** 0.5
        n_levels = 20
        for i, j in base:
            r = L * ((i / (2 * nx)) ** 2 + (j / (2 * ny)) ** 2) ** 0.5
            level = min(n_levels - 1, int(round((n_levels - 1) * (r / radius) ** 2)))
            levels.setdefault(level, []).append(ids[(i, j, 0)])
        ge = n_solid
        for level in sorted(levels):
            lines.append(f"*ELEMENT, TYPE=GAPUNI, ELSET=G{level}")
            for n in levels[level]:
                ge += 1
                lines.append(f"{ge}, {n}, {n_block + n}")
        lines.append(f"*ELSET, ELSET=GAPS, GENERATE\n{n_solid + 1}, {ge}, 1")
        for level in sorted(levels):
            line = f"{a.dmax * level / (n_levels - 1):.9g}, 0., 0., -1."
            if a.penalty is not None:
                line += f", , {a.penalty:.9g}"
                if a.tension is not None:
                    line += f", {a.tension:.9g}"
            lines.append(f"*GAP, ELSET=G{level}\n{line}")
    lines.append("*BOUNDARY\nXSYM, 1, 1\nYSYM, 2, 2\n" + ("BASE, 3, 3" if a.no_gaps else "GROUND, 1, 3"))
    static = f"{0.1:.6g}, 1." + (f", , {a.max_inc:.6g}" if a.max_inc else "")
    nlgeom = (a.nlgeom or ("no" if a.no_gaps else "yes")) == "yes"
    lines.append(f"*STEP{', NLGEOM' if nlgeom else ''}, INC=1000\n*STATIC\n{static}")
    lines.append(f"*DSLOAD\nSTOP, P, {a.pressure:.9g}")
    lines.append(f"*NODE PRINT, NSET={'BASE' if a.no_gaps else 'GROUND'}, TOTALS=YES\nRF\n*END STEP")
    n_xsym = sum(1 for (i, j, k) in ids if i == 0)
    n_ysym = sum(1 for (i, j, k) in ids if j == 0)
    eqs = 3 * n_block - n_xsym - n_ysym - (len(base) if a.no_gaps else 0)
    summary = f"equations {eqs}, C3D20 {n_solid}, gaps {0 if a.no_gaps else len(base)}"
    return "\n".join(lines) + "\n", summary


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--nx", type=int, default=10)
    ap.add_argument("--nz", type=int, default=10)
    ap.add_argument("--penalty", type=float, default=None, help="GAPUNI penalty (ccx fields 6-7)")
    ap.add_argument("--tension", type=float, default=None,
                    help="ccx field 7: tension of an open penalty gap (ccx default 1e-3)")
    ap.add_argument("--no-gaps", action="store_true", help="fixed base, linear static preload")
    ap.add_argument("--pressure", type=float, default=10.0)
    ap.add_argument("--E", type=float, default=2.0e5)
    ap.add_argument("--dmax", type=float, default=2.0e-4, help="clearance at the corner")
    ap.add_argument("--rho", type=float, default=1.0)
    ap.add_argument("--modes", type=int, default=20, help="eigenvalues requested")
    ap.add_argument("--element", default="C3D8", choices=["C3D8", "C3D8I", "C3D20"],
                    help="solid element type (C3D20: this script's quadratic mesh)")
    ap.add_argument("--max-inc", type=float, default=None, help="gen_block.py's --max-inc")
    ap.add_argument("--nlgeom", choices=["yes", "no"], default=None,
                    help="NLGEOM on the static step (default: yes with gaps, no without)")
    ap.add_argument("-o", "--output", default="-")
    a = ap.parse_args()
    cmd = [sys.executable, os.path.join(HERE, "gen_block.py"), "--nx", str(a.nx), "--nz", str(a.nz),
           "--pressure", repr(a.pressure), "--E", repr(a.E), "--dmax", repr(a.dmax)]
    if a.no_gaps:
        cmd.append("--no-gaps")
    if a.penalty is not None:
        cmd += ["--penalty", repr(a.penalty)]
    if a.tension is not None:
        cmd += ["--tension", repr(a.tension)]
    if a.max_inc is not None:
        cmd += ["--max-inc", repr(a.max_inc)]
    if a.nlgeom is not None:
        cmd += ["--nlgeom", a.nlgeom]
    if a.element == "C3D20":
        deck, summary = quadratic_block(a)
    else:
        p = subprocess.run(cmd, capture_output=True, text=True, check=True)
        deck, summary = p.stdout, p.stderr.strip()
    # the density goes with the elastic constants
    deck = re.sub(r"(\*ELASTIC\n[^\n]*\n)", lambda m: m.group(1) + f"*DENSITY\n{a.rho:.9g}\n", deck,
                  count=1)
    if a.element == "C3D8I":
        deck = deck.replace("*ELEMENT, TYPE=C3D8,", "*ELEMENT, TYPE=C3D8I,")
    deck = deck.replace("*HEADING\n", "*HEADING\nNatural frequencies about a preload: ", 1)
    deck += f"*STEP, PERTURBATION\n*FREQUENCY\n{a.modes}\n*END STEP\n"
    out = sys.stdout if a.output == "-" else open(a.output, "w")
    out.write(deck)
    if out is not sys.stdout:
        out.close()
    # gen_block.py's summary line (equations, elements, gaps) for run_suite.py
    sys.stderr.write(summary + f", modes {a.modes}\n")


if __name__ == "__main__":
    main()
