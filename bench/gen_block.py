#!/usr/bin/env python3
"""Generate a block of C3D8 elements, either fixed at its base (linear static benchmark) or resting
on a foundation of GAPUNI elements to fixed ground nodes (gap benchmark). The decks run unchanged in
gapfem and in CalculiX (ccx): NLGEOM on the step, *GAP fields 6-7 when --penalty is given, one
elset per clearance value.

Quarter model of a square block (side 2*L, height H) under a uniform pressure p on its top face:
symmetry planes x=0 (XSYMM) and y=0 (YSYMM). Foundation: every bottom node has a GAPUNI to its own
ground node 1 unit below, closure direction (0,0,-1); the clearance grows with the distance r from
the centre, d = d_max * (r / R)^2 quantised to --levels values, so the centre starts closed and a
central patch closes under load (like a slightly convex base on a rigid floor).

Equations: 3 * (nx+1)*(ny+1)*(nz+1) minus the symmetry constraints.
"""
import argparse
import math
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--nx", type=int, default=10, help="elements along x and y (quarter model)")
    ap.add_argument("--nz", type=int, default=10, help="elements through the height")
    ap.add_argument("--length", type=float, default=1.0, help="half side L of the block")
    ap.add_argument("--height", type=float, default=1.0)
    ap.add_argument("--E", type=float, default=2.0e5)
    ap.add_argument("--nu", type=float, default=0.3)
    ap.add_argument("--pressure", type=float, default=10.0)
    ap.add_argument("--dmax", type=float, default=2.0e-4, help="clearance at the corner")
    ap.add_argument("--levels", type=int, default=20, help="distinct clearance values")
    ap.add_argument("--penalty", type=float, default=None,
                    help="GAPUNI penalty stiffness (CalculiX fields 6-7); omit for exact contact")
    ap.add_argument("--tension", type=float, default=None,
                    help="CalculiX field 7: tension carried by an open penalty gap (ccx default 1e-3)")
    ap.add_argument("--friction", type=float, default=None,
                    help="Coulomb friction coefficient on the gaps (*FRICTION after each *GAP; gapfem only)")
    ap.add_argument("--shear", type=float, default=None,
                    help="lateral traction along x on the top face (nodal loads) in a second step "
                         "that releases the x=0 face, so friction alone holds the block laterally")
    ap.add_argument("--no-gaps", action="store_true", help="fixed base instead of gaps (linear static)")
    ap.add_argument("--nlgeom", choices=["yes", "no"], default=None,
                    help="NLGEOM on the step (default: yes with gaps, no without)")
    ap.add_argument("--inc", type=float, default=0.1, help="initial increment (fraction of step)")
    ap.add_argument("--max-inc", type=float, default=None,
                    help="maximum increment (fraction of step); 0.1 makes at least 10 increments")
    ap.add_argument("--print-gaps", action="store_true", help="*EL PRINT of the gap elements")
    ap.add_argument("-o", "--output", default="-")
    a = ap.parse_args()
    nx, ny, nz = a.nx, a.nx, a.nz
    nlgeom = (a.nlgeom or ("no" if a.no_gaps else "yes")) == "yes"
    out = sys.stdout if a.output == "-" else open(a.output, "w")
    w = out.write

    def nid(i, j, k):
        return 1 + i + (nx + 1) * (j + (ny + 1) * k)

    # *STATIC: initial increment, period[, minimum, maximum]
    static_line = f"{a.inc:.6g}, 1." + (f", , {a.max_inc:.6g}" if a.max_inc else "")
    n_block = (nx + 1) * (ny + 1) * (nz + 1)
    w("*HEADING\n")
    w(f"Quarter block {nx}x{ny}x{nz} C3D8 {'fixed base' if a.no_gaps else 'on a GAPUNI foundation'}\n")
    w("*NODE, NSET=NALL\n")
    for k in range(nz + 1):
        z = a.height * k / nz
        for j in range(ny + 1):
            y = a.length * j / ny
            for i in range(nx + 1):
                x = a.length * i / nx
                w(f"{nid(i, j, k)}, {x:.9g}, {y:.9g}, {z:.9g}\n")
    if not a.no_gaps:
        w("*NODE, NSET=GROUND\n")
        for j in range(ny + 1):
            for i in range(nx + 1):
                w(f"{n_block + nid(i, j, 0)}, {a.length * i / nx:.9g}, {a.length * j / ny:.9g}, -1.\n")
    w("*ELEMENT, TYPE=C3D8, ELSET=BLOCK\n")
    e = 0
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                e += 1
                n = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                     nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)]
                w(f"{e}, " + ", ".join(map(str, n)) + "\n")
    n_solid = e
    top_first = n_solid - nx * ny + 1
    w(f"*ELSET, ELSET=TOP, GENERATE\n{top_first}, {n_solid}, 1\n")
    w("*SURFACE, NAME=STOP, TYPE=ELEMENT\nTOP, S2\n")
    w("*MATERIAL, NAME=STEEL\n*ELASTIC\n" f"{a.E:.9g}, {a.nu:.9g}\n")
    w("*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL\n")
    w("*NSET, NSET=XSYM\n")
    members = [nid(0, j, k) for k in range(nz + 1) for j in range(ny + 1)]
    for s in range(0, len(members), 16):
        w(", ".join(map(str, members[s:s + 16])) + "\n")
    w("*NSET, NSET=YSYM\n")
    members = [nid(i, 0, k) for k in range(nz + 1) for i in range(nx + 1)]
    for s in range(0, len(members), 16):
        w(", ".join(map(str, members[s:s + 16])) + "\n")
    w("*NSET, NSET=BASE\n")
    members = [nid(i, j, 0) for j in range(ny + 1) for i in range(nx + 1)]
    for s in range(0, len(members), 16):
        w(", ".join(map(str, members[s:s + 16])) + "\n")
    if not a.no_gaps:
        # with --shear the base is graded from (L/2, 0) and flat (d = 0) within 0.3 L of it, so that
        # a patch of gaps is closed from the start and holds the block against tilting
        cx, flat = (0.5, 0.3) if a.shear is not None else (0.0, 0.0)
        radius = a.length * math.hypot(max(cx, 1.0 - cx), 1.0)
        levels = {}
        for j in range(ny + 1):
            for i in range(nx + 1):
                r = a.length * math.hypot(i / nx - cx, j / ny)
                rr = max(0.0, (r - flat * a.length) / (radius - flat * a.length))
                level = min(a.levels - 1, int(round((a.levels - 1) * rr ** 2)))
                levels.setdefault(level, []).append(nid(i, j, 0))
        ge = n_solid
        for level in sorted(levels):
            w(f"*ELEMENT, TYPE=GAPUNI, ELSET=G{level}\n")
            for n in levels[level]:
                ge += 1
                w(f"{ge}, {n}, {n_block + n}\n")
        w(f"*ELSET, ELSET=GAPS, GENERATE\n{n_solid + 1}, {ge}, 1\n")
        for level in sorted(levels):
            d = a.dmax * level / (a.levels - 1)
            line = f"{d:.9g}, 0., 0., -1."
            if a.penalty is not None:
                line += f", , {a.penalty:.9g}"
                if a.tension is not None:
                    line += f", {a.tension:.9g}"
            w(f"*GAP, ELSET=G{level}\n{line}\n")
            if a.friction is not None:
                w(f"*FRICTION\n{a.friction:.9g}\n")
    w("*BOUNDARY\nXSYM, 1, 1\nYSYM, 2, 2\n")
    if a.no_gaps:
        w("BASE, 3, 3\n")
    else:
        w("GROUND, 1, 3\n")
    w(f"*STEP{', NLGEOM' if nlgeom else ''}, INC=1000\n*STATIC\n{static_line}\n")
    w(f"*DSLOAD\nSTOP, P, {a.pressure:.9g}\n")
    if a.shear is not None:
        # step 2: the x = 0 face is released (its reaction ramps off) and a lateral traction is
        # added; friction at the closed gaps, loaded by step 1, now holds the block
        w("*NODE PRINT, NSET=GROUND, TOTALS=YES\nRF\n*END STEP\n")
        w(f"*STEP{', NLGEOM' if nlgeom else ''}, INC=1000\n*STATIC\n{static_line}\n")
        w("*BOUNDARY, OP=NEW\nYSYM, 2, 2\nGROUND, 1, 3\n")
        w("*CLOAD\n")
        hx, hy = a.length / nx, a.length / ny
        for j in range(ny + 1):
            for i in range(nx + 1):
                wt = (0.5 if i in (0, nx) else 1.0) * (0.5 if j in (0, ny) else 1.0)
                w(f"{nid(i, j, nz)}, 1, {a.shear * hx * hy * wt:.9g}\n")
    w("*NODE PRINT, NSET=GROUND, TOTALS=YES\nRF\n" if not a.no_gaps else "*NODE PRINT, NSET=BASE, TOTALS=YES\nRF\n")
    if a.print_gaps and not a.no_gaps:
        w("*EL PRINT, ELSET=GAPS\nS\nE\n")
    w("*END STEP\n")
    if out is not sys.stdout:
        out.close()
    eqs = 3 * n_block - (nz + 1) * (ny + 1) - (nz + 1) * (nx + 1) \
        - (0 if not a.no_gaps else (nx + 1) * (ny + 1))
    print(f"equations {eqs}, C3D8 {n_solid}, gaps {0 if a.no_gaps else (nx + 1) * (ny + 1)}", file=sys.stderr)


if __name__ == "__main__":
    main()
