#!/usr/bin/env python3
"""Generate a pipe rack: parallel straight steel pipe lines of B31 beams on GAPUNI rest supports
and GAPCYL guides, loaded by self weight and then by thermal expansion and a lateral (wind) load.
Units: N, m, degC.

Lines: --lines parallel lines along x, 0.6 m apart in y (line j at y = 0.6 j), each --spans spans
of --span m with --elems B31 elements per span. The line sizes cycle through four standard pipes
(OD x wall: 114.3 x 6.02, 168.3 x 7.11, 219.1 x 8.18, 273.1 x 9.27 mm; *BEAM SECTION,
SECTION=PIPE), steel E = 2e11, nu = 0.3, density 7850, expansion 1.2e-5 (ZERO = 20).
x = 0 is an anchor (ENCASTRE); the other end is free.

Supports at x = k * span, k = 1 .. spans. Each support has a fixed ground node at the pipe node's
position and
  * a GAPUNI rest support (pipe node first, ground node second, closure direction (0, 0, -1):
    the pipe rests on the support and may lift off). Supports with even k hold a guide and have
    d = 0; at odd k the support is lowered by a graded clearance d = --clearance * level / (--levels
    - 1), level = (j + k // 2) % --levels, so low supports under the stiffer lines stay open (lift
    off) while the lighter lines sag onto them;
  * at even k a GAPCYL guide (axis x, d = --guide-gap > 0: the pipe node moves inside a ring of
    that radial clearance around the ground node); axial motion is free.
Without --friction the supports are frictionless (*FRICTION after each rest *GAP otherwise).

Step 1 (WEIGHT): gravity (*DLOAD GRAV 9.81 in -z on all pipe elements).
Step 2 (HOT): the pipes heat from 20 degC by --dT (*INITIAL CONDITIONS / *TEMPERATURE on the pipe
nodes), so they grow along x (alpha * dT * spans * span at the free end), and a lateral load of
--lateral N/m in +y (nodal *CLOAD) pushes them into the guides, where they close and the lines bow
sideways between the guides.

With --frequency N a third step follows: `*STEP, PERTURBATION` / `*FREQUENCY` / N, the natural
frequencies about the hot state (docs/theory/frequency.md: closed hard gaps hold as constraint rows,
open ones are free). CalculiX cannot run these decks (no GAPCYL, no ENCASTRE, SECTION=PIPE only on
B32R), so they are gapfem's.

Every pipe node is held by the beam itself back to the anchor, so the model has no rigid-body
mode whatever the gap status (the ground nodes are fixed in 1-3). NLGEOM with B31 is an input
error in gapfem, hence --nlgeom defaults to no (yes writes NLGEOM on the steps, to test that error).

Equations: 6 * lines * (spans * elems + 1) minus the 6 anchor DOFs per line (gapfem may add one
multiplier per closed gap on top). --lines 40 --spans 20 --elems 10 gives 48,000 equations,
--lines 200 --spans 20 --elems 10 gives 240,000.
"""
import argparse
import sys

# outer radius, wall thickness (m)
PIPES = [(0.05715, 0.00602), (0.08415, 0.00711), (0.10955, 0.00818), (0.13655, 0.00927)]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--lines", type=int, default=4, help="parallel pipe lines")
    ap.add_argument("--spans", type=int, default=5, help="spans per line")
    ap.add_argument("--elems", type=int, default=10, help="B31 elements per span")
    ap.add_argument("--span", type=float, default=6.0, help="span length (m)")
    ap.add_argument("--pitch", type=float, default=0.6, help="distance between lines (m)")
    ap.add_argument("--clearance", type=float, default=0.01,
                    help="largest rest-support clearance d (m) at the odd supports")
    ap.add_argument("--levels", type=int, default=5, help="distinct rest clearances (0 .. --clearance)")
    ap.add_argument("--guide-gap", type=float, default=0.002, help="GAPCYL radial clearance (m)")
    ap.add_argument("--dT", type=float, default=180.0, help="temperature rise in step 2 (K)")
    ap.add_argument("--lateral", type=float, default=100.0, help="lateral load in +y in step 2 (N/m)")
    ap.add_argument("--friction", type=float, default=None, help="Coulomb coefficient at the rest supports")
    ap.add_argument("--nlgeom", choices=["yes", "no"], default="no",
                    help="NLGEOM on the steps (B31 with NLGEOM is an input error in gapfem)")
    ap.add_argument("--inc", type=float, default=0.25, help="initial increment of step 2 (fraction)")
    ap.add_argument("--print-gaps", action="store_true", help="*EL PRINT of the gap elements")
    ap.add_argument("--frequency", type=int, default=None,
                    help="a third step: this many natural frequencies about the hot state")
    ap.add_argument("-o", "--output", default="-")
    a = ap.parse_args()
    if a.lines < 1 or a.spans < 1 or a.elems < 1 or a.levels < 1:
        ap.error("--lines, --spans, --elems and --levels must be >= 1")
    if a.guide_gap <= 0:
        ap.error("--guide-gap must be > 0 (GAPCYL with d = 0 is an input error)")
    out = sys.stdout if a.output == "-" else open(a.output, "w")
    w = out.write
    nl = a.spans * a.elems + 1          # nodes per line
    ne = a.spans * a.elems              # elements per line
    dx = a.span / a.elems
    n_pipe = a.lines * nl
    nlg = ", NLGEOM" if a.nlgeom == "yes" else ""

    def nid(j, i):                       # line j, node i along the line
        return 1 + j * nl + i

    def gid(j, k):                       # ground node of line j, support k (1 .. spans)
        return n_pipe + 1 + j * a.spans + (k - 1)

    def nset(name, members):
        w(f"*NSET, NSET={name}\n")
        for s in range(0, len(members), 16):
            w(", ".join(map(str, members[s:s + 16])) + "\n")

    w("*HEADING\n")
    w(f"Pipe rack: {a.lines} lines x {a.spans} spans of {a.span:g} m, B31 on GAPUNI rests and GAPCYL guides\n")
    w("*NODE, NSET=PIPE\n")
    for j in range(a.lines):
        y = a.pitch * j
        for i in range(nl):
            w(f"{nid(j, i)}, {dx * i:.9g}, {y:.9g}, 0.\n")
    w("*NODE, NSET=GROUND\n")
    for j in range(a.lines):
        for k in range(1, a.spans + 1):
            w(f"{gid(j, k)}, {a.span * k:.9g}, {a.pitch * j:.9g}, 0.\n")
    e = 0
    for s in range(len(PIPES)):
        lines = [j for j in range(s, a.lines, len(PIPES))]
        if not lines:
            continue
        w(f"*ELEMENT, TYPE=B31, ELSET=SIZE{s}\n")
        for j in lines:
            for i in range(ne):
                w(f"{1 + j * ne + i}, {nid(j, i)}, {nid(j, i + 1)}\n")
                e += 1
    n_beam = e
    w(f"*ELSET, ELSET=PIPES, GENERATE\n1, {n_beam}, 1\n")
    w("*MATERIAL, NAME=STEEL\n*ELASTIC\n2.0E11, 0.3\n*DENSITY\n7850.\n*EXPANSION, ZERO=20.\n1.2E-5\n")
    for s, (r, t) in enumerate(PIPES):
        if s < a.lines:
            w(f"*BEAM SECTION, ELSET=SIZE{s}, MATERIAL=STEEL, SECTION=PIPE\n{r:.9g}, {t:.9g}\n0., 0., -1.\n")
    # rest supports: one elset per clearance level
    levels = {}
    guides = []
    for j in range(a.lines):
        for k in range(1, a.spans + 1):
            if k % 2 == 0:
                levels.setdefault(0, []).append((j, k))
                guides.append((j, k))
            else:
                lv = (j + k // 2) % a.levels if a.levels > 1 else 0
                levels.setdefault(lv, []).append((j, k))
    ge = 100000 * ((n_beam + 100000) // 100000)   # gap labels start at the next multiple of 1e5
    first_gap = ge + 1
    for lv in sorted(levels):
        w(f"*ELEMENT, TYPE=GAPUNI, ELSET=REST{lv}\n")
        for j, k in levels[lv]:
            ge += 1
            w(f"{ge}, {nid(j, k * a.elems)}, {gid(j, k)}\n")
    n_rest = ge - first_gap + 1
    w(f"*ELSET, ELSET=RESTS, GENERATE\n{first_gap}, {ge}, 1\n")
    if guides:
        w("*ELEMENT, TYPE=GAPCYL, ELSET=GUIDES\n")
        for j, k in guides:
            ge += 1
            w(f"{ge}, {nid(j, k * a.elems)}, {gid(j, k)}\n")
    for lv in sorted(levels):
        d = a.clearance * lv / (a.levels - 1) if a.levels > 1 else 0.0
        w(f"*GAP, ELSET=REST{lv}\n{d:.9g}, 0., 0., -1., 0.01\n")
        if a.friction is not None:
            w(f"*FRICTION\n{a.friction:.9g}\n")
    if guides:
        w(f"*GAP, ELSET=GUIDES\n{a.guide_gap:.9g}, 1., 0., 0., 0.01\n")
    nset("ANCHOR", [nid(j, 0) for j in range(a.lines)])
    nset("FREE", [nid(j, nl - 1) for j in range(a.lines)])
    w("*BOUNDARY\nANCHOR, ENCASTRE\nGROUND, 1, 3\n")
    w("*INITIAL CONDITIONS, TYPE=TEMPERATURE\nPIPE, 20.\n")
    w(f"*STEP, NAME=WEIGHT{nlg}, INC=100\n*STATIC\n")
    w("*DLOAD\nPIPES, GRAV, 9.81, 0., 0., -1.\n")
    w("*NODE PRINT, NSET=ANCHOR, TOTALS=YES\nRF\n")
    w("*NODE PRINT, NSET=GROUND, TOTALS=YES, SUMMARY=NO\nRF\n")
    if a.print_gaps:
        w("*EL PRINT, ELSET=RESTS\nS, E\n")
    w("*END STEP\n")
    w(f"*STEP, NAME=HOT{nlg}, INC=1000\n*STATIC\n{a.inc:.6g}, 1.\n")
    w(f"*TEMPERATURE\nPIPE, {20.0 + a.dT:.9g}\n")
    if a.lateral:
        w("*CLOAD\n")
        for j in range(a.lines):
            for i in range(1, nl):
                f = a.lateral * dx * (0.5 if i == nl - 1 else 1.0)
                w(f"{nid(j, i)}, 2, {f:.9g}\n")
    w("*NODE PRINT, NSET=FREE\nU\n")
    w("*NODE PRINT, NSET=ANCHOR, TOTALS=YES\nRF\n")
    w("*NODE PRINT, NSET=GROUND, TOTALS=YES, SUMMARY=NO\nRF\n")
    if a.print_gaps:
        w("*EL PRINT, ELSET=RESTS\nS, E\n")
        if guides:
            w("*EL PRINT, ELSET=GUIDES\nS, E\n")
    w("*END STEP\n")
    if a.frequency is not None:
        w(f"*STEP, NAME=MODES, PERTURBATION\n*FREQUENCY\n{a.frequency}\n*END STEP\n")
    if out is not sys.stdout:
        out.close()
    eqs = 6 * n_pipe - 6 * a.lines
    print(f"equations {eqs}, B31 {n_beam}, gaps {n_rest + len(guides)} "
          f"(GAPUNI {n_rest}, GAPCYL {len(guides)})", file=sys.stderr)


if __name__ == "__main__":
    main()
