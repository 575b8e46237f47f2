#!/usr/bin/env python3
"""Writes the decks of examples/05_seismic_pipe (units N, m, s; see README.md):

- seismic_pipe.inp: an L-shaped 4-inch steel pipe run (114.3 x 6.02 mm, PIPE31 every 0.5 m, a
  long-radius elbow of four chords) anchored at both ends, on rests (GAPUNI closing downwards,
  zero clearance, PTFE slide plates, mu = 0.1) and guides (GAPCYL about the pipe axis, 1 mm
  radial clearance, mu = 0.3). Step 1 gravity (static); step 2 the three-component accelerogram of
  accelerogram_{x,y,z}.txt as base motion (*BOUNDARY, TYPE=ACCELERATION) of every ground node and
  the anchors, *DYNAMIC with the default application (MODERATE DISSIPATION: the model has gaps).
- accelerogram_{x,y,z}.txt: the accelerogram, *AMPLITUDE DEFINITION=EQUALLY SPACED data (m/s^2,
  every 0.01 s): a sum of sines with fixed phases (seeded) under a smooth-step envelope,
  baseline-corrected so that the ground ends at rest.
- rigid_shake.inp: the same pipe on steel rests (mu = 0.3), all supports closed and sticking, the ground accelerated in x
  by a smooth step to a0 = 0.1 g and held: the reactions sum to m a0 once the transient is gone.
- sliding_threshold.inp: a 50 kg mass (MASS element) on one rest with mu = 0.3, the ground's x
  acceleration ramped (smooth step) from 0 to 0.6 g over 2 s: slip starts at |a_g| = mu g.
- lift_off.inp: the same mass, the ground's z acceleration ramped from 0 to -1.5 g: the rest
  force is m (g + a_z) and reaches zero (lift-off) at a_z = -g.
"""

import math
import random

G = 9.81
OD, T_WALL = 0.1143, 0.00602
RO = OD / 2
R_BEND = 0.1524          # long-radius elbow, 1.5 D of a 4-inch pipe
L1, L2 = 8.0, 6.0        # the corner of the L at (L1, 0), the second anchor at (L1, L2)
DX = 0.5
MU = 0.3          # the blocks' rests
MU_REST = 0.1     # the pipe's rests: PTFE slide plates
MU_STEEL = 0.3    # its guides, and the rests of rigid_shake.inp (steel on steel)
GUIDE_GAP = 0.001  # the guides' radial clearance
DT_ACC, T_ACC = 0.01, 4.0  # the accelerogram's spacing and length
PGA = (0.5 * G, 0.4 * G, 0.3 * G)  # peak ground accelerations x, y, z


def pipe_geometry():
    """Nodes (label, x, y) and elements (label, a, b) of the L."""
    nodes = []

    def add(x, y):
        nodes.append((len(nodes) + 1, x, y))
        return len(nodes)

    x_start = L1 - R_BEND
    line = [add(i * DX, 0.0) for i in range(int(x_start // DX) + 1)]
    line.append(add(x_start, 0.0))
    for k in range(1, 5):
        a = math.pi / 2 * k / 4
        line.append(add(x_start + R_BEND * math.sin(a), R_BEND * (1 - math.cos(a))))
    y = DX
    while y <= L2 + 1e-12:
        line.append(add(L1, y))
        y += DX
    elems = [(k + 1, a, b) for k, (a, b) in enumerate(zip(line, line[1:]))]
    return nodes, elems, line


def node_at(nodes, x, y):
    return min(nodes, key=lambda n: (n[1] - x) ** 2 + (n[2] - y) ** 2)[0]


def steel(alpha_r, beta_r):
    return ["*MATERIAL, NAME=STEEL", "*ELASTIC", "2.0E11, 0.3", "*DENSITY", "7850.",
            "*DAMPING, ALPHA=%.6g, BETA=%.6g" % (alpha_r, beta_r),
            "*BEAM SECTION, ELSET=LINE, MATERIAL=STEEL, SECTION=PIPE", f"{RO}, {T_WALL}",
            "0., 0., -1."]


def rayleigh(zeta, f1, f2):
    """ALPHA, BETA giving the damping ratio zeta at f1 and f2 (Hz)."""
    w1, w2 = 2 * math.pi * f1, 2 * math.pi * f2
    return 2 * zeta * w1 * w2 / (w1 + w2), 2 * zeta / (w1 + w2)


def accelerogram(seed=46):
    """Three components (lists of samples every DT_ACC over [0, T_ACC])."""
    rng = random.Random(seed)
    n = int(round(T_ACC / DT_ACC)) + 1
    t = [i * DT_ACC for i in range(n)]

    def smooth(x):  # 0 -> 1 with zero slope and curvature at both ends
        x = min(max(x, 0.0), 1.0)
        return x ** 3 * (10 - 15 * x + 6 * x * x)

    env = [smooth(s / 0.5) * (1 - smooth((s - 2.5) / 1.2)) for s in t]
    comps = []
    for pga in PGA:
        waves = [(f, rng.uniform(0.5, 1.0), rng.uniform(0, 2 * math.pi))
                 for f in (1.3, 2.1, 3.4, 5.2, 7.9, 11.5)]
        a = [e * sum(amp * math.sin(2 * math.pi * f * s + ph) for f, amp, ph in waves)
             for s, e in zip(t, env)]
        # baseline: remove the envelope-shaped part that leaves a final velocity (trapezoidal
        # integral of the samples, which is the exact integral of the piecewise-linear curve)
        trap = lambda v: DT_ACC * (sum(v) - 0.5 * (v[0] + v[-1]))
        c = trap(a) / trap(env)
        a = [x - c * e for x, e in zip(a, env)]
        peak = max(abs(x) for x in a)
        comps.append([pga * x / peak for x in a])
    return comps


def write_accelerograms():
    for name, comp in zip("xyz", accelerogram()):
        lines = []
        for i in range(0, len(comp), 8):
            lines.append(", ".join("%.6f" % v for v in comp[i:i + 8]))
        open(f"accelerogram_{name}.txt", "w").write("\n".join(lines) + "\n")


def pipe_model(heading, anchored=True, mu_rest=MU_REST):
    """Model data of the L on its supports; returns (lines, monitor nodes, support labels)."""
    nodes, elems, line = pipe_geometry()
    rests = [node_at(nodes, x, y) for x, y in ((2.0, 0), (4.0, 0), (6.0, 0), (L1, 1.5),
                                               (L1, 3.0), (L1, 4.5))]
    guides = [node_at(nodes, 3.0, 0), node_at(nodes, 5.0, 0), node_at(nodes, L1, 2.5)]
    out = ["*HEADING", heading, "*NODE, NSET=PIPE"]
    out += [f"{k}, {x:.12g}, {y:.12g}, 0." for k, x, y in nodes]
    out.append("*NODE, NSET=GROUND")
    ground = []
    for i, n in enumerate(rests + guides):
        _, x, y = nodes[n - 1]
        out.append(f"{101 + i}, {x:.12g}, {y:.12g}, 0.")
        ground.append(101 + i)
    if anchored:
        out += ["*NSET, NSET=ANCHORS", f"{line[0]}, {line[-1]}", "*NSET, NSET=BASE",
                "GROUND, ANCHORS"]
    else:
        out += ["*NSET, NSET=BASE", "GROUND"]
    out.append("*ELEMENT, TYPE=PIPE31, ELSET=LINE")
    out += [f"{k}, {a}, {b}" for k, a, b in elems]
    out += steel(0.0, 2 * 0.03 / (2 * math.pi * 10.0))
    out.append("*ELEMENT, TYPE=GAPUNI, ELSET=RESTS")
    out += [f"{201 + i}, {n}, {ground[i]}" for i, n in enumerate(rests)]
    out += ["*GAP, ELSET=RESTS", "0., 0., 0., -1., 0.01", "*FRICTION", f"{mu_rest}"]
    out.append("*ELEMENT, TYPE=GAPCYL, ELSET=GUIDES_X")
    out += [f"{301 + i}, {n}, {ground[len(rests) + i]}" for i, n in enumerate(guides[:2])]
    out += ["*GAP, ELSET=GUIDES_X", f"{GUIDE_GAP}, 1., 0., 0., 0.01", "*FRICTION",
            f"{MU_STEEL}"]
    out += ["*ELEMENT, TYPE=GAPCYL, ELSET=GUIDES_Y", f"{301 + len(guides) - 1}, {guides[2]}, {ground[-1]}",
            "*GAP, ELSET=GUIDES_Y", f"{GUIDE_GAP}, 0., 1., 0., 0.01", "*FRICTION", f"{MU_STEEL}",
            "*ELSET, ELSET=GUIDES", "GUIDES_X, GUIDES_Y",
            "*ELSET, ELSET=SUPPORTS", "RESTS, GUIDES"]
    monitor = [node_at(nodes, 5.0, 0), line[len(line) // 2], node_at(nodes, L1, 3.5)]
    out += ["*NSET, NSET=MONITOR", ", ".join(str(n) for n in monitor),
            "*NSET, NSET=ELBOW_MID", str(monitor[1]),
            "*ELSET, ELSET=CHARTED_RESTS", "204",
            "*BOUNDARY", "BASE, 1, 3"]
    if anchored:
        out.append("ANCHORS, 4, 6")
    return out


def gravity_step():
    return ["*STEP, NAME=WEIGHT", "*STATIC", "*DLOAD", "LINE, GRAV, 9.81, 0., 0., -1.",
            "*NODE PRINT, NSET=BASE, TOTALS=YES", "RF", "*EL PRINT, ELSET=SUPPORTS", "S, E",
            "*END STEP"]


def seismic_pipe():
    out = pipe_model("L-shaped 4-inch pipe run on rests and guides under a three-component "
                     "accelerogram")
    for c in "XYZ":
        out += [f"*AMPLITUDE, NAME=A{c}, DEFINITION=EQUALLY SPACED, FIXED INTERVAL={DT_ACC}, "
                f"INPUT=accelerogram_{c.lower()}.txt"]
    out += gravity_step()
    out += ["*STEP, NAME=EARTHQUAKE, INC=10000", "*DYNAMIC, DIRECT", f"0.0025, {T_ACC + 1.0}",
            "*BOUNDARY, TYPE=ACCELERATION, AMPLITUDE=AX", "BASE, 1, 1, 1.",
            "*BOUNDARY, TYPE=ACCELERATION, AMPLITUDE=AY", "BASE, 2, 2, 1.",
            "*BOUNDARY, TYPE=ACCELERATION, AMPLITUDE=AZ", "BASE, 3, 3, 1.",
            "*OUTPUT, HISTORY, FREQUENCY=4", "*NODE OUTPUT, NSET=ELBOW_MID", "U",
            "*ELEMENT OUTPUT, ELSET=CHARTED_RESTS", "S",
            "*ELEMENT OUTPUT, ELSET=GUIDES", "S",
            "*ENERGY OUTPUT",
            "*NODE PRINT, NSET=BASE, TOTALS=YES, FREQUENCY=400", "RF",
            "*EL PRINT, ELSET=SUPPORTS, FREQUENCY=400", "S, E",
            "*END STEP"]
    open("seismic_pipe.inp", "w").write("\n".join(out) + "\n")


def rigid_shake():
    out = pipe_model("The seismic pipe without its anchors shaken rigidly: a smooth step of 0.1 g in x, "
                     "held", anchored=False, mu_rest=MU_STEEL)
    out += ["*AMPLITUDE, NAME=STEP01G, DEFINITION=SMOOTH STEP", "0., 0., 1., 0.981"]
    out += gravity_step()
    out += ["*STEP, NAME=SHAKE, INC=10000", "*DYNAMIC, DIRECT", "0.01, 2.5",
            "*BOUNDARY, TYPE=ACCELERATION, AMPLITUDE=STEP01G", "BASE, 1, 1, 1.",
            "*BOUNDARY, TYPE=ACCELERATION", "BASE, 2, 3, 0.",
            "*NODE PRINT, NSET=BASE, TOTALS=YES, FREQUENCY=50", "RF",
            "*EL PRINT, ELSET=SUPPORTS, FREQUENCY=50", "S, E", "*END STEP"]
    open("rigid_shake.inp", "w").write("\n".join(out) + "\n")


def block(heading, amplitude, dof, value):
    out = ["*HEADING", heading, "*NODE", "1, 0., 0., 0.", "2, 0., 0., 0.",
           "*NSET, NSET=GROUND", "2",
           "*ELEMENT, TYPE=MASS, ELSET=BLOCK", "1, 1", "*MASS, ELSET=BLOCK", "50.",
           "*ELEMENT, TYPE=GAPUNI, ELSET=REST", "11, 1, 2",
           "*GAP, ELSET=REST", "0., 0., 0., -1., 0.01", "*FRICTION", f"{MU}",
           "*AMPLITUDE, NAME=RAMP, DEFINITION=SMOOTH STEP", amplitude,
           "*BOUNDARY", "GROUND, 1, 3",
           "*STEP, NAME=WEIGHT", "*STATIC", "*DLOAD", "BLOCK, GRAV, 9.81, 0., 0., -1.",
           "*EL PRINT, ELSET=REST", "S, E", "*END STEP",
           "*STEP, NAME=RAMP, INC=10000", "*DYNAMIC, DIRECT", "0.005, 2.5",
           "*BOUNDARY, TYPE=ACCELERATION, AMPLITUDE=RAMP", f"GROUND, {dof}, {dof}, {value}",
           "*BOUNDARY, TYPE=ACCELERATION"]
    out += [f"GROUND, {d}, {d}, 0." for d in (1, 2, 3) if d != dof]
    out += ["*OUTPUT, HISTORY", "*NODE OUTPUT, NSET=GROUND", "A", "*ELEMENT OUTPUT, ELSET=REST",
            "S, E", "*ENERGY OUTPUT", "*EL PRINT, ELSET=REST, FREQUENCY=50", "S, E", "*END STEP"]
    return out


def sliding_threshold():
    out = block("A 50 kg block on a rest (mu = 0.3), the ground accelerated in x from 0 to 0.6 g",
                "0., 0., 2., 1.", 1, 0.6 * G)
    open("sliding_threshold.inp", "w").write("\n".join(out) + "\n")


def lift_off():
    out = block("A 50 kg block on a rest, the ground accelerated down from 0 to 1.5 g",
                "0., 0., 2., 1.", 3, -1.5 * G)
    open("lift_off.inp", "w").write("\n".join(out) + "\n")


if __name__ == "__main__":
    write_accelerograms()
    seismic_pipe()
    rigid_shake()
    sliding_threshold()
    lift_off()
