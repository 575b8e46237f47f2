#!/usr/bin/env python3
"""Writes shrink_fit.inp: a steel ring (bore 20 mm, outer radius 40 mm) shrunk onto a solid steel
shaft (radius 20 mm) with a radial interference of 20 micron, axisymmetric CAX4 slice 2 mm high in
plane strain. GAPUNI elements join each shaft surface node to the ring bore node at the same place
(closure direction -r: the ring moving inwards closes the gap), d = -0.02 mm.
Step 1 removes the interference gradually with *CONTACT INTERFERENCE, SHRINK (the solver starts
from the overlapping geometry and lets the parts push each other apart); step 2 spins nothing and
just pulls the ring axially — here only a check that the fit holds (frictionless: it slides)."""
N_SHAFT, N_RING = 20, 20
A, B, H, DELTA = 20.0, 40.0, 2.0, 0.02
out = ["*HEADING", "Shrink fit of a ring on a shaft (CAX4, GAPUNI, *CONTACT INTERFERENCE SHRINK)",
       "*NODE, NSET=ALL"]
def sid(i, top): return 1 + i + (100 if top else 0)
def rid(i, top): return 1001 + i + (100 if top else 0)
for i in range(N_SHAFT + 1):
    for t in (0, 1):
        out.append(f"{sid(i, t)}, {A * i / N_SHAFT:.9g}, {H * t:.9g}")
for i in range(N_RING + 1):
    for t in (0, 1):
        out.append(f"{rid(i, t)}, {A + (B - A) * i / N_RING:.9g}, {H * t:.9g}")
out.append("*ELEMENT, TYPE=CAX4, ELSET=SHAFT")
for i in range(N_SHAFT):
    out.append(f"{1 + i}, {sid(i, 0)}, {sid(i + 1, 0)}, {sid(i + 1, 1)}, {sid(i, 1)}")
out.append("*ELEMENT, TYPE=CAX4, ELSET=RING")
for i in range(N_RING):
    out.append(f"{1001 + i}, {rid(i, 0)}, {rid(i + 1, 0)}, {rid(i + 1, 1)}, {rid(i, 1)}")
out += ["*MATERIAL, NAME=STEEL", "*ELASTIC", "2.1E5, 0.3",
        "*SOLID SECTION, ELSET=SHAFT, MATERIAL=STEEL", "*SOLID SECTION, ELSET=RING, MATERIAL=STEEL",
        "*ELEMENT, TYPE=GAPUNI, ELSET=FIT",
        f"5001, {rid(0, 0)}, {sid(N_SHAFT, 0)}", f"5002, {rid(0, 1)}, {sid(N_SHAFT, 1)}",
        "*GAP, ELSET=FIT", f"{-DELTA}, -1., 0., 0., 1.",
        f"*NSET, NSET=AXIS\n{sid(0, 0)}, {sid(0, 1)}",
        "*BOUNDARY", "ALL, 2, 2", "AXIS, 1, 1",
        "*STEP, NAME=SHRINK", "*STATIC", "0.25, 1.",
        "*CONTACT INTERFERENCE, TYPE=ELEMENT, SHRINK", "FIT",
        "*EL PRINT, ELSET=FIT", "S, E", "*EL PRINT, ELSET=RING, POSITION=CENTROIDAL", "S",
        "*NODE PRINT, NSET=ALL, FREQUENCY=4", "U", "*END STEP"]
open("shrink_fit.inp", "w").write("\n".join(out) + "\n")
