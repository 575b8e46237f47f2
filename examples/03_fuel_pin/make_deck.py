#!/usr/bin/env python3
"""Writes fuel_pin.inp: an axisymmetric slice (1 mm high, plane strain) of a UO2 pellet and its
Zircaloy clad, coupled temperature-displacement (CAX4T), with GAPUNIT elements across the
pellet/clad gap. Units: mm, N, s, K, tonne (stress MPa, energy mJ, power mW: conductivity mW/(mm K) =
W/(m K), heat generation mW/mm^3, film mW/(mm^2 K)).

The pellet generates 450 mW/mm^3 (about 24 kW/m of rod), ramped up over 10 s; the clad is cooled
by water at 580 K (film 30 mW/(mm^2 K) = 30 kW/(m^2 K)). The 10 micron helium gap conducts with a clearance-
dependent conductance k = k_He / (h + 0.01 mm) while open and with a contact conductance growing
with the contact pressure once the pellet's thermal expansion has closed it."""
import math

R_PELLET, GAP, T_CLAD = 4.10, 0.010, 0.63
N_PELLET, N_CLAD, H = 16, 4, 1.0
r_nodes = [R_PELLET * i / N_PELLET for i in range(N_PELLET + 1)]
c_nodes = [R_PELLET + GAP + T_CLAD * i / N_CLAD for i in range(N_CLAD + 1)]

out = ["*HEADING", "Fuel pin slice: UO2 pellet, helium gap (GAPUNIT), Zircaloy clad; heat-up to gap closure",
       "*NODE, NSET=ALL"]
def nid(part, i, top):  # part 0 pellet, 1 clad
    return (1 if part == 0 else 101) + i + (50 if top else 0)
for part, rs in ((0, r_nodes), (1, c_nodes)):
    for i, r in enumerate(rs):
        for top in (0, 1):
            out.append(f"{nid(part, i, top)}, {r:.9g}, {H * top:.9g}")
for part, name, n in ((0, "PELLET", N_PELLET), (1, "CLAD", N_CLAD)):
    out.append(f"*ELEMENT, TYPE=CAX4T, ELSET={name}")
    for i in range(n):
        e = (1 if part == 0 else 101) + i
        out.append(f"{e}, {nid(part, i, 0)}, {nid(part, i + 1, 0)}, {nid(part, i + 1, 1)}, {nid(part, i, 1)}")
out += [f"*ELSET, ELSET=CLAD_OUT\n{100 + N_CLAD}",
        "*NSET, NSET=AXIS", f"{nid(0, 0, 0)}, {nid(0, 0, 1)}",
        "*MATERIAL, NAME=UO2", "*ELASTIC", "2.0E5, 0.3", "*EXPANSION, ZERO=580.", "1.0E-5",
        "*CONDUCTIVITY", "4.5, 580.", "2.8, 1300.", "*DENSITY", "1.096E-8", "*SPECIFIC HEAT", "3.0E8",
        "*MATERIAL, NAME=ZIRC", "*ELASTIC", "9.9E4, 0.37", "*EXPANSION, ZERO=580.", "6.0E-6",
        "*CONDUCTIVITY", "16.", "*DENSITY", "6.5E-9", "*SPECIFIC HEAT", "3.3E8",
        "*SOLID SECTION, ELSET=PELLET, MATERIAL=UO2", "*SOLID SECTION, ELSET=CLAD, MATERIAL=ZIRC"]
# GAPUNIT: pellet surface node (node 1) to clad bore node (node 2); closure along +r; area = ring
# area of half the slice height (forces and heat flows of axisymmetric models are totals).
area = 2 * math.pi * R_PELLET * H / 2
out.append("*ELEMENT, TYPE=GAPUNIT, ELSET=GAP")
out.append(f"1001, {nid(0, N_PELLET, 0)}, {nid(1, 0, 0)}")
out.append(f"1002, {nid(0, N_PELLET, 1)}, {nid(1, 0, 1)}")
out += ["*GAP, ELSET=GAP", f"{GAP}, 1., 0., 0., {area:.9g}", "*GAP CONDUCTANCE"]
k_he = 0.25  # helium, mW/(mm K)
for h in (0.0, 0.005, 0.01, 0.02, 0.04, 0.08, 0.2):
    out.append(f"{k_he / (h + 0.01):.6g}, {h}")
out += ["*GAP CONDUCTANCE, PRESSURE", f"{k_he / 0.01:.6g}, 0.", f"{k_he / 0.01 + 100.:.6g}, 100.",
        "*AMPLITUDE, NAME=POWER", "0., 0., 10., 1., 1000., 1.",
        "*INITIAL CONDITIONS, TYPE=TEMPERATURE", "ALL, 580.",
        "*BOUNDARY", "ALL, 2, 2", "AXIS, 1, 1",
        "*STEP, INC=500", "*COUPLED TEMPERATURE-DISPLACEMENT, DELTMX=40.", "0.5, 60., 1.E-4, 5.",
        "*DFLUX, AMPLITUDE=POWER", "PELLET, BF, 450.",
        "*FILM", "CLAD_OUT, F2, 580., 30.",
        # ParaView frames every second increment: the .pvd animates the gap closing
        "*OUTPUT, FIELD, FREQUENCY=2", "*NODE OUTPUT", "U, NT", "*ELEMENT OUTPUT", "S, E, HFL",
        "*EL PRINT, ELSET=GAP", "S, E, HFL",
        "*NODE PRINT, NSET=AXIS, FREQUENCY=5", "NT",
        "*END STEP"]
open("fuel_pin.inp", "w").write("\n".join(out) + "\n")
