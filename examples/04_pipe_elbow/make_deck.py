#!/usr/bin/env python3
"""Writes pipe_elbow.inp: an L-shaped steel pipe run (6-inch, 168.3 x 7.11 mm, PIPE31 every
0.5 m) anchored at A = (0, 0, 0), along x to a long-radius 90-degree elbow (R = 0.2286 m, six
PIPE31 chords), then along y to a free end at y = 4 m. It rests on frictionless rest supports
(GAPUNI, closure downwards) at x = 3 and 5 m and y = 1.5, 3 and 4 m, and passes a lateral guide at
y = 2.5 m (two GAPUNI, 15 mm clearance each side in x). Units: N, m, s, degC.

Step 1 (WEIGHT): self weight. Step 2 (PRESSURE): + 5 MPa internal pressure (PI, closed-end
condition). Step 3 (HOT): + heating from 20 to 170 degC."""

import math

D, T_WALL = 0.1683, 0.00711
RO = D / 2
R_BEND = 0.2286
L1, L2 = 6.0, 4.0  # corner of the L at (L1, 0); the free end at (L1, L2)
DX = 0.5

nodes, elems = [], []


def add_node(x, y):
    nodes.append((len(nodes) + 1, x, y))
    return len(nodes)


# leg 1 along x up to the elbow start, the elbow (6 chords), leg 2 along y to the free end
x_start = L1 - R_BEND
n1 = [add_node(i * DX, 0.0) for i in range(int(x_start // DX) + 1)]
if abs(nodes[-1][1] - x_start) > 1e-12:
    n1.append(add_node(x_start, 0.0))
arc = []
for k in range(1, 7):
    a = math.pi / 2 * k / 6
    arc.append(add_node(x_start + R_BEND * math.sin(a), R_BEND * (1 - math.cos(a))))
y0 = R_BEND
n2 = []
y = math.ceil(y0 / DX) * DX
while y <= L2 + 1e-12:
    if y - y0 > 1e-9:
        n2.append(add_node(L1, y))
    y += DX
line = n1 + arc + n2
for a, b in zip(line, line[1:]):
    elems.append((len(elems) + 1, a, b))


def node_at(x, y):
    return min(nodes, key=lambda n: (n[1] - x) ** 2 + (n[2] - y) ** 2)[0]


rests = [node_at(3.0, 0.0), node_at(5.0, 0.0), node_at(L1, 1.5), node_at(L1, 3.0), node_at(L1, L2)]
guide = node_at(L1, 2.5)
out = ["*HEADING",
       "L-shaped pipe run with an elbow on rest supports and a guide: weight, pressure, heat",
       "*NODE, NSET=PIPE"]
out += [f"{k}, {x:.12g}, {y:.12g}, 0." for k, x, y in nodes]
out.append("*NODE, NSET=GROUND")
ground = {}
for i, n in enumerate(rests + [guide]):
    ground[n] = 101 + i
    _, x, y = nodes[n - 1]
    out.append(f"{101 + i}, {x:.12g}, {y:.12g}, 0.")
out.append("*ELEMENT, TYPE=PIPE31, ELSET=LINE")
out += [f"{k}, {a}, {b}" for k, a, b in elems]
out += [f"*NSET, NSET=FREE_END", str(line[-1]), "*NSET, NSET=ELBOW",
        ", ".join(str(n) for n in arc), "*ELSET, ELSET=ELBOW_ELEMS",
        ", ".join(str(k) for k, a, b in elems if b in arc)]
out += ["*MATERIAL, NAME=STEEL", "*ELASTIC", "2.0E11, 0.3", "*DENSITY", "7850.",
        "*EXPANSION, ZERO=20.", "1.2E-5",
        "*BEAM SECTION, ELSET=LINE, MATERIAL=STEEL, SECTION=PIPE", f"{RO}, {T_WALL}", "0., 0., -1."]
out.append("*ELEMENT, TYPE=GAPUNI, ELSET=RESTS")
out += [f"{201 + i}, {n}, {ground[n]}" for i, n in enumerate(rests)]
out += ["*GAP, ELSET=RESTS", "0., 0., 0., -1., 0.03"]
out += ["*ELEMENT, TYPE=GAPUNI, ELSET=GUIDE_PX", f"301, {guide}, {ground[guide]}",
        "*GAP, ELSET=GUIDE_PX", "0.015, 1., 0., 0., 0.01",
        "*ELEMENT, TYPE=GAPUNI, ELSET=GUIDE_MX", f"302, {guide}, {ground[guide]}",
        "*GAP, ELSET=GUIDE_MX", "0.015, -1., 0., 0., 0.01",
        "*ELSET, ELSET=GUIDES", "GUIDE_PX, GUIDE_MX",
        "*BOUNDARY", "1, ENCASTRE", "GROUND, 1, 3",
        "*INITIAL CONDITIONS, TYPE=TEMPERATURE", "PIPE, 20."]
prints = ["*NODE PRINT, NSET=FREE_END", "U", "*NODE PRINT, NSET=GROUND, TOTALS=YES", "RF",
          "*EL PRINT, ELSET=RESTS", "S, E", "*EL PRINT, ELSET=GUIDES", "S, E"]
out += ["*STEP, NAME=WEIGHT", "*STATIC", "*DLOAD", "LINE, GRAV, 9.81, 0., 0., -1."] + prints + [
    "*END STEP"]
out += ["*STEP, NAME=PRESSURE", "*STATIC", "*DLOAD", "LINE, PI, 5.0E6",
        "*EL PRINT, ELSET=ELBOW_ELEMS", "S, SF"] + prints + ["*END STEP"]
out += ["*STEP, NAME=HOT", "*STATIC", "*TEMPERATURE", "PIPE, 170."] + prints + ["*END STEP"]
open("pipe_elbow.inp", "w").write("\n".join(out) + "\n")
