#!/usr/bin/env python3
"""Writes pipe_on_supports.inp: a 12 m steel pipe (114.3 x 6 mm, B31 beams every 0.5 m) anchored
at x = 0, resting on four sliding rest supports (GAPUNI, closure downwards, friction mu = 0.3;
the one at x = 6 m has 2 mm of clearance) and passing through two guides (GAPCYL about the pipe
axis, 3 mm radial clearance, at x = 3 m and 9 m). Units: N, m, s, degC.

Step 1: self weight. Step 2: the pipe heats from 20 to 170 degC (thermal growth 21.6 mm at the
free end, resisted by friction at the rests) while a lateral load of 2 kN at x = 7.5 m pushes it
into the guides."""

L, DX = 12.0, 0.5
n = int(L / DX) + 1
out = ["*HEADING", "Pipe on sliding rest supports and guides: weight, then thermal growth and a lateral load",
       "*NODE, NSET=PIPE"]
for i in range(n):
    out.append(f"{i + 1}, {i * DX:.6g}, 0., 0.")
rests = {3.0: 0.0, 6.0: 0.002, 9.0: 0.0, 12.0: 0.0}
guides = [3.0, 9.0]
out.append("*NODE, NSET=GROUND")
ground = {}
for k, x in enumerate(sorted(set(rests) | set(guides))):
    ground[x] = 101 + k
    out.append(f"{101 + k}, {x:.6g}, 0., 0.")
out.append("*ELEMENT, TYPE=B31, ELSET=LINE")
for i in range(n - 1):
    out.append(f"{i + 1}, {i + 1}, {i + 2}")
out += ["*MATERIAL, NAME=STEEL", "*ELASTIC", "2.0E11, 0.3", "*DENSITY", "7850.",
        "*EXPANSION, ZERO=20.", "1.2E-5",
        "*BEAM SECTION, ELSET=LINE, MATERIAL=STEEL, SECTION=PIPE", "0.05715, 0.006", "0., 0., -1."]
node_at = lambda x: int(round(x / DX)) + 1
for k, (x, d) in enumerate(sorted(rests.items())):
    out += [f"*ELEMENT, TYPE=GAPUNI, ELSET=REST{k + 1}", f"{201 + k}, {node_at(x)}, {ground[x]}",
            f"*GAP, ELSET=REST{k + 1}", f"{d}, 0., 0., -1., 0.03", "*FRICTION", "0.3"]
out.append("*ELSET, ELSET=RESTS")
out.append(", ".join(str(201 + k) for k in range(len(rests))))
out.append("*ELEMENT, TYPE=GAPCYL, ELSET=GUIDES")
for k, x in enumerate(guides):
    out.append(f"{301 + k}, {node_at(x)}, {ground[x]}")
out += ["*GAP, ELSET=GUIDES", "0.003, 1., 0., 0., 0.02",  # guide shoes of 0.02 m^2: S11 is the pressure
        "*BOUNDARY", "1, ENCASTRE", "GROUND, 1, 3",
        "*INITIAL CONDITIONS, TYPE=TEMPERATURE", "PIPE, 20.",
        "*STEP, NAME=WEIGHT", "*STATIC", "*DLOAD", "LINE, GRAV, 9.81, 0., 0., -1.",
        "*EL PRINT, ELSET=RESTS", "S, E", "*NODE PRINT, NSET=GROUND, TOTALS=YES", "RF", "*END STEP",
        "*STEP, NAME=HOT, INC=200", "*STATIC", "0.1, 1.",
        "*TEMPERATURE", "PIPE, 170.", "*CLOAD", f"{node_at(7.5)}, 2, 2000.",
        "*EL PRINT, ELSET=RESTS", "S, E", "*EL PRINT, ELSET=GUIDES", "S, E",
        "*NODE PRINT, NSET=GROUND, TOTALS=YES", "RF", "*NODE PRINT, NSET=PIPE", "U",
        "*END STEP"]
open("pipe_on_supports.inp", "w").write("\n".join(out) + "\n")
