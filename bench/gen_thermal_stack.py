#!/usr/bin/env python3
"""Generate a thermal stack: --layers square plates stacked in z, separated by thin gaps, heated on
top and held at a fixed temperature at the bottom. Steady-state heat transfer with DGAP elements
(default), or coupled temperature-displacement with GAPUNIT elements (--coupled). Units: m, W, K,
N, Pa.

Quarter model of square plates (side 2*--side, thickness --thickness), symmetry planes x = 0 and
y = 0 (insulated in heat transfer; XSYM/YSYM displacement conditions with --coupled). Each plate
has nx * nx * nz elements (DC3D8, or C3D8T with --coupled); plates alternate between two materials:
  STEEL      conductivity 50 W/(m K)
  STAINLESS  conductivity 16 W/(m K); with --nonlinear 15 at 20 degC rising to 25 at 520 degC
             (temperature-dependent: Newton iterations, and an unsymmetric tangent, so gapfem
             factorises with UMFPACK instead of CHOLMOD)
(--coupled adds E = 2e11 / 1.95e11, nu = 0.3, expansion 1.2e-5 / 1.7e-5, ZERO = 20).

Interfaces: plate k's top face and plate k+1's bottom face are separate nodes at the same
coordinates. Every top-face node of plate k is joined to the coincident bottom-face node of plate
k+1 by a gap element (node 1 lower, node 2 upper) with the node's tributary area (dx^2 inside,
half on an edge, a quarter at a corner) on the *GAP line. The clearance is graded across the
interface, d = --dmax * level / (--levels - 1) with level = round((levels - 1) * s), s = r^2 on even
interfaces and 1 - r^2 on odd ones (r = distance from the plate centre at the origin / the corner
distance): the contact resistance is lowest at the middle on even interfaces and at the far corner
(x = y = side) on odd ones, so the heat meanders.
One elset per (clearance level, area class), each with its own *GAP line and
  *GAP CONDUCTANCE (clearance): k = 1e4 W/(m^2 K) at h = 0, 2e3 at 1e-4, 1e3 at 2e-4, zero beyond.
  DGAP: h = d is constant and any direction is ignored, so the data line is "d, , , , A".
  GAPUNIT (--coupled): closure direction (0, 0, 1) (h = d + u2z - u1z: the upper plate moving
  down closes it), and *GAP CONDUCTANCE, PRESSURE as well: k = 1e4 at p = 0, 3e4 at 1e6 Pa,
  6e4 at 1e7 Pa (the pressure table applies while closed, the clearance table while open).

Loads: bottom face of plate 0 at --t-bottom (*BOUNDARY, DOF 11; in --coupled also u3 = 0); the
top face of the top plate gets a surface flux --flux (*DFLUX, S2) or, with --film H, a film
condition (h = H, sink --sink). --coupled: a pressure --pressure on the top face (*DSLOAD) presses
the stack together; the gaps in the middle of even interfaces and at the far corner of odd ones
start closed (d = 0), so every plate is held in z from the first iteration; XSYM/YSYM on every plate
hold it in x and y. Pressure and heat ramp together in one step: an isothermal preload step
(pressure, no flux) does not converge in gapfem, whose heat-flux criterion then has a zero scale.

Equations: heat transfer 1 per node: layers * (nx+1)^2 * (nz+1) - (nx+1)^2 (bottom face held).
--coupled: 4 per node minus the bottom face (T and u3) and the symmetry planes of every plate.
--nx 60 --nz 4 --layers 10 gives 182,329 heat-transfer equations (--nz 3: 145,119).
"""
import argparse
import math
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--nx", type=int, default=12, help="elements along x and y per plate (quarter model)")
    ap.add_argument("--nz", type=int, default=2, help="elements through each plate")
    ap.add_argument("--layers", type=int, default=4, help="plates in the stack")
    ap.add_argument("--side", type=float, default=0.1, help="half side of the plates (m)")
    ap.add_argument("--thickness", type=float, default=0.01, help="plate thickness (m)")
    ap.add_argument("--dmax", type=float, default=1.0e-4, help="largest gap clearance (m)")
    ap.add_argument("--levels", type=int, default=6, help="distinct clearance values")
    ap.add_argument("--flux", type=float, default=5.0e4, help="heat flux into the top face (W/m^2)")
    ap.add_argument("--film", type=float, default=None,
                    help="film coefficient on the top face (W/(m^2 K)) instead of --flux")
    ap.add_argument("--sink", type=float, default=400.0, help="sink temperature of --film (degC)")
    ap.add_argument("--t-bottom", type=float, default=20.0, help="bottom face temperature (degC)")
    ap.add_argument("--nonlinear", action="store_true",
                    help="temperature-dependent conductivity of the STAINLESS plates")
    ap.add_argument("--coupled", action="store_true",
                    help="coupled temperature-displacement with C3D8T and GAPUNIT (default: DC3D8, DGAP)")
    ap.add_argument("--pressure", type=float, default=1.0e6, help="--coupled: pressure on the top face (Pa)")
    ap.add_argument("--inc", type=float, default=0.25, help="--coupled: initial increment (fraction)")
    ap.add_argument("--print-gaps", action="store_true", help="*EL PRINT of the gap elements")
    ap.add_argument("-o", "--output", default="-")
    a = ap.parse_args()
    if a.nx < 1 or a.nz < 1 or a.layers < 2 or a.levels < 1:
        ap.error("need --nx, --nz, --levels >= 1 and --layers >= 2")
    nx, nz, nl = a.nx, a.nz, a.layers
    n1 = nx + 1
    per_layer = n1 * n1 * (nz + 1)
    dx = a.side / nx
    out = sys.stdout if a.output == "-" else open(a.output, "w")
    w = out.write

    def nid(layer, i, j, k):
        return 1 + i + n1 * (j + n1 * (k + (nz + 1) * layer))

    def wlist(members):
        for s in range(0, len(members), 16):
            w(", ".join(map(str, members[s:s + 16])) + "\n")

    solid = "C3D8T" if a.coupled else "DC3D8"
    gap_type = "GAPUNIT" if a.coupled else "DGAP"
    w("*HEADING\n")
    w(f"Thermal stack: {nl} plates of {nx}x{nx}x{nz} {solid} (quarter model) joined by {gap_type} gaps\n")
    w("*NODE, NSET=NALL\n")
    for layer in range(nl):
        for k in range(nz + 1):
            z = a.thickness * (layer + k / nz)
            for j in range(n1):
                for i in range(n1):
                    w(f"{nid(layer, i, j, k)}, {dx * i:.9g}, {dx * j:.9g}, {z:.9g}\n")
    e = 0
    for layer in range(nl):
        w(f"*ELEMENT, TYPE={solid}, ELSET=PLATE{layer}\n")
        for k in range(nz):
            for j in range(nx):
                for i in range(nx):
                    e += 1
                    n = [nid(layer, i, j, k), nid(layer, i + 1, j, k), nid(layer, i + 1, j + 1, k),
                         nid(layer, i, j + 1, k), nid(layer, i, j, k + 1), nid(layer, i + 1, j, k + 1),
                         nid(layer, i + 1, j + 1, k + 1), nid(layer, i, j + 1, k + 1)]
                    w(f"{e}, " + ", ".join(map(str, n)) + "\n")
    n_solid = e
    top_first = n_solid - nx * nx + 1
    w(f"*ELSET, ELSET=TOPEL, GENERATE\n{top_first}, {n_solid}, 1\n")
    w("*SURFACE, NAME=STOP, TYPE=ELEMENT\nTOPEL, S2\n")
    # materials
    w("*MATERIAL, NAME=STEEL\n*CONDUCTIVITY\n50.\n")
    if a.coupled:
        w("*ELASTIC\n2.0E11, 0.3\n*EXPANSION, ZERO=20.\n1.2E-5\n")
    w("*MATERIAL, NAME=STAINLESS\n*CONDUCTIVITY\n" + ("15., 20.\n25., 520.\n" if a.nonlinear else "16.\n"))
    if a.coupled:
        w("*ELASTIC\n1.95E11, 0.3\n*EXPANSION, ZERO=20.\n1.7E-5\n")
    for layer in range(nl):
        w(f"*SOLID SECTION, ELSET=PLATE{layer}, MATERIAL={'STEEL' if layer % 2 == 0 else 'STAINLESS'}\n")
    # gaps: one elset per (level, area class)
    sets = {}
    rmax = math.hypot(1.0, 1.0)
    for m in range(nl - 1):
        for j in range(n1):
            for i in range(n1):
                r2 = (math.hypot(i / nx, j / nx) / rmax) ** 2
                s = r2 if m % 2 == 0 else 1.0 - r2
                level = int(round((a.levels - 1) * s)) if a.levels > 1 else 0
                cls = (i in (0, nx)) + (j in (0, nx))       # 0 inside, 1 edge, 2 corner
                sets.setdefault((level, cls), []).append((nid(m, i, j, nz), nid(m + 1, i, j, 0)))
    ge = 100000 * ((n_solid + 100000) // 100000)
    first_gap = ge + 1
    for key in sorted(sets):
        w(f"*ELEMENT, TYPE={gap_type}, ELSET=G{key[0]}_{key[1]}\n")
        for lo, hi in sets[key]:
            ge += 1
            w(f"{ge}, {lo}, {hi}\n")
    n_gaps = ge - first_gap + 1
    w(f"*ELSET, ELSET=GAPS, GENERATE\n{first_gap}, {ge}, 1\n")
    for level, cls in sorted(sets):
        d = a.dmax * level / (a.levels - 1) if a.levels > 1 else 0.0
        area = dx * dx / (1, 2, 4)[cls]
        direction = "0., 0., 1." if a.coupled else ", , "
        w(f"*GAP, ELSET=G{level}_{cls}\n{d:.9g}, {direction}, {area:.9g}\n")
        w("*GAP CONDUCTANCE\n1.E4, 0.\n2.E3, 1.E-4\n1.E3, 2.E-4\n")
        if a.coupled:
            w("*GAP CONDUCTANCE, PRESSURE\n1.E4, 0.\n3.E4, 1.E6\n6.E4, 1.E7\n")
    w("*NSET, NSET=BOTTOM\n")
    wlist([nid(0, i, j, 0) for j in range(n1) for i in range(n1)])
    w("*NSET, NSET=AXIS\n")
    wlist([nid(layer, 0, 0, k) for layer in range(nl) for k in range(nz + 1)])
    if a.coupled:
        w("*NSET, NSET=XSYM\n")
        wlist([nid(layer, 0, j, k) for layer in range(nl) for k in range(nz + 1) for j in range(n1)])
        w("*NSET, NSET=YSYM\n")
        wlist([nid(layer, i, 0, k) for layer in range(nl) for k in range(nz + 1) for i in range(n1)])
    w(f"*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, {a.t_bottom:.9g}\n")
    if a.coupled:
        w("*BOUNDARY\nXSYM, 1, 1\nYSYM, 2, 2\nBOTTOM, 3, 3\n")
        w(f"*STEP, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n{a.inc:.6g}, 1.\n")
    else:
        w("*STEP, INC=100\n*HEAT TRANSFER, STEADY STATE\n1., 1.\n")
    w(f"*BOUNDARY\nBOTTOM, 11, 11, {a.t_bottom:.9g}\n")
    if a.film is not None:
        w(f"*FILM\nTOPEL, F2, {a.sink:.9g}, {a.film:.9g}\n")
    else:
        w(f"*DFLUX\nTOPEL, S2, {a.flux:.9g}\n")
    if a.coupled:
        w(f"*DSLOAD\nSTOP, P, {a.pressure:.9g}\n")
    w("*NODE PRINT, NSET=AXIS\nNT\n")
    w("*NODE PRINT, NSET=BOTTOM, TOTALS=YES, SUMMARY=NO\nRFL\n")
    if a.coupled:
        w("*NODE PRINT, NSET=BOTTOM, TOTALS=YES, SUMMARY=NO\nRF\n")
    if a.print_gaps:
        w("*EL PRINT, ELSET=GAPS\nHFL\n" + ("S, E\n" if a.coupled else ""))
    w("*END STEP\n")
    if out is not sys.stdout:
        out.close()
    n_nodes = nl * per_layer
    if a.coupled:
        sym = nl * (nz + 1) * n1
        eqs = 4 * n_nodes - 2 * n1 * n1 - 2 * sym
    else:
        eqs = n_nodes - n1 * n1
    print(f"equations {eqs}, {solid} {n_solid}, gaps {n_gaps} ({gap_type})", file=sys.stderr)


if __name__ == "__main__":
    main()
