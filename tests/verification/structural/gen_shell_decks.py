#!/usr/bin/env python3
"""Writes the shell verification decks of this directory (our own meshes; run from here).

shell_strip_moment.inp  cantilever strips of S4R, S4, S3, S8R under an end moment (exact)
shell_plate_ss.inp      quarter of a simply supported square plate under pressure, S4R 8x8
shell_scordelis_lo.inp  Scordelis-Lo roof, quarter, S8R 8x8 (and S4R 16x16 in the _s4r deck)
shell_strip_offset.inp  strips with OFFSET=SPOS (S8R: *NODAL THICKNESS) under a tip axial force
shell_rollup_*.inp      NLGEOM roll-up of a strip into a circle (S4R 32, S8R 16 elements)
shell_hemisphere.inp    pinched hemisphere, quarter, S4R 8x8
shell_macneal_harder_straight.inp  MacNeal-Harder straight cantilever, S4R 6 x 1, four loads
"""
import math


def write(name, lines):
    with open(name, "w") as f:
        f.write("\n".join(lines) + "\n")


def grid(nx, ny, quad8, tri, X, base=0, ebase=0):
    """Nodes X(i, j) of a structured grid and its elements (Abaqus numbering)."""
    mx, my = (2 * nx, 2 * ny) if quad8 else (nx, ny)
    nid = lambda i, j: base + i * (my + 1) + j + 1
    els = []
    for i in range(nx):
        for j in range(ny):
            if quad8:
                I, J = 2 * i, 2 * j
                els.append([nid(I, J), nid(I + 2, J), nid(I + 2, J + 2), nid(I, J + 2),
                            nid(I + 1, J), nid(I + 2, J + 1), nid(I + 1, J + 2), nid(I, J + 1)])
            elif tri:
                els.append([nid(i, j), nid(i + 1, j), nid(i + 1, j + 1)])
                els.append([nid(i, j), nid(i + 1, j + 1), nid(i, j + 1)])
            else:
                els.append([nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1)])
    used = sorted(set(n for e in els for n in e))
    nodes = []
    for i in range(mx + 1):
        for j in range(my + 1):
            if nid(i, j) in used:
                nodes.append((nid(i, j), X(i / mx, j / my)))
    elems = [(ebase + k + 1, e) for k, e in enumerate(els)]
    return nodes, elems, nid, mx, my


def node_lines(nodes):
    return [f"{k}, {x:.15g}, {y:.15g}, {z:.15g}" for k, (x, y, z) in nodes]


def strip():
    out = ["*HEADING", "Cantilever strips 10 x 1 x 0.1 under an end moment 1 (E = 1e6, nu = 0)"]
    for s, et in enumerate(["S4R", "S4", "S3", "S8R"]):
        q8, tri = et == "S8R", et == "S3"
        nodes, elems, nid, mx, my = grid(4, 1, q8, tri, lambda u, v: (10 * u, v + 2 * s, 0.0),
                                         base=100 * s, ebase=100 * s)
        out += ["*NODE"] + node_lines(nodes)
        out += [f"*ELEMENT, TYPE={et}, ELSET=S{s}"] + [f"{k}, " + ", ".join(map(str, e))
                                                        for k, e in elems]
        out += [f"*NSET, NSET=ROOT{s}", ", ".join(str(nid(0, j)) for j in range(my + 1)
                                                 if any(n == nid(0, j) for n, _ in nodes))]
        out += [f"*NSET, NSET=TIP{s}", ", ".join(str(nid(mx, j)) for j in range(my + 1)
                                                if any(n == nid(mx, j) for n, _ in nodes))]
        out += [f"*SHELL SECTION, ELSET=S{s}, MATERIAL=M", "0.1, 5"]
    out += ["*MATERIAL, NAME=M", "*ELASTIC", "1e6, 0", "*BOUNDARY"]
    out += [f"ROOT{s}, 1, 6" for s in range(4)]
    out += ["*STEP", "*STATIC", "*CLOAD"]
    for s in range(3):  # two tip nodes each, consistent end moment -1 about y
        out += [f"{100 * s + 9}, 5, -0.5", f"{100 * s + 10}, 5, -0.5"]
    out += ["325, 5, -0.16666666666666667", "326, 5, -0.66666666666666667",
            "327, 5, -0.16666666666666667"]
    out += ["*NODE PRINT", "U", "*EL PRINT, ELSET=S0", "SF", "*END STEP"]
    write("shell_strip_moment.inp", out)


def plate():
    nodes, elems, nid, m, _ = grid(8, 8, False, False, lambda u, v: (0.5 * u, 0.5 * v, 0.0))
    out = ["*HEADING", "Quarter of a simply supported (hard) square plate a = 1, t = 0.01, q = 1",
           "*NODE"] + node_lines(nodes)
    out += ["*ELEMENT, TYPE=S4R, ELSET=PLATE"] + [f"{k}, " + ", ".join(map(str, e)) for k, e in elems]
    side = lambda f: ", ".join(str(f(k)) for k in range(m + 1))
    out += ["*NSET, NSET=X0", side(lambda j: nid(0, j)), "*NSET, NSET=Y0", side(lambda i: nid(i, 0)),
            "*NSET, NSET=XS", side(lambda j: nid(m, j)), "*NSET, NSET=YS", side(lambda i: nid(i, m))]
    out += ["*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL", "0.01, 5",
            "*MATERIAL, NAME=STEEL", "*ELASTIC", "1e7, 0.3",
            "*BOUNDARY", "X0, 3", "X0, 4", "Y0, 3", "Y0, 5", "XS, XSYMM", "YS, YSYMM",
            "*STEP", "*STATIC", "*DLOAD", "PLATE, P, 1.0", "*NODE PRINT", "U",
            "*EL PRINT, ELSET=PLATE", "S", "SF", "*END STEP"]
    write("shell_plate_ss.inp", out)


def scordelis(et, n, name):
    R, L = 25.0, 50.0
    X = lambda u, v: (L / 2 * u, R * math.sin(math.radians(40) * v), R * math.cos(math.radians(40) * v))
    nodes, elems, nid, m, _ = grid(n, n, et == "S8R", False, X)
    used = {k for k, _ in nodes}
    sel = lambda lst: ", ".join(str(k) for k in lst if k in used)
    out = ["*HEADING", f"Scordelis-Lo roof, quarter, {et} {n} x {n}", "*NODE"] + node_lines(nodes)
    out += [f"*ELEMENT, TYPE={et}, ELSET=ROOF"] + [f"{k}, " + ", ".join(map(str, e)) for k, e in elems]
    out += ["*NSET, NSET=DIAPH", sel(nid(0, j) for j in range(m + 1)),
            "*NSET, NSET=MID", sel(nid(m, j) for j in range(m + 1)),
            "*NSET, NSET=CROWN", sel(nid(i, 0) for i in range(m + 1)),
            "*NSET, NSET=A", str(nid(m, m))]
    out += ["*SHELL SECTION, ELSET=ROOF, MATERIAL=M", "0.25", "*MATERIAL, NAME=M", "*ELASTIC",
            "4.32e8, 0.0", "*DENSITY", "360.0", "*BOUNDARY", "DIAPH, 2", "DIAPH, 3", "DIAPH, 4",
            "MID, XSYMM", "CROWN, YSYMM", "*STEP", "*STATIC", "*DLOAD", "ROOF, GRAV, 1.0, 0, 0, -1",
            "*NODE PRINT, NSET=A", "U", "*END STEP"]
    write(name, out)


def strip_offset():
    """S4R and S8R strips with OFFSET=SPOS under a tip axial force on the reference surface; the
    S8R strip takes its thickness from *NODAL THICKNESS."""
    out = ["*HEADING", "Strips 10 x 1 x 0.1 with the reference surface on top (OFFSET=SPOS), tip force 1"]
    for s, et in enumerate(["S4R", "S8R"]):
        nodes, elems, nid, mx, my = grid(4, 1, et == "S8R", False,
                                         lambda u, v: (10 * u, v + 2 * s, 0.0), base=100 * s,
                                         ebase=100 * s)
        have = {n for n, _ in nodes}
        out += ["*NODE, NSET=N%d" % s] + node_lines(nodes)
        out += [f"*ELEMENT, TYPE={et}, ELSET=S{s}"] + [f"{k}, " + ", ".join(map(str, e))
                                                        for k, e in elems]
        out += [f"*NSET, NSET=ROOT{s}", ", ".join(str(nid(0, j)) for j in range(my + 1)
                                                 if nid(0, j) in have)]
        if et == "S8R":
            out += [f"*SHELL SECTION, ELSET=S{s}, MATERIAL=M, OFFSET=SPOS, NODAL THICKNESS", ", 5",
                    "*NODAL THICKNESS", "N1, 0.1"]
        else:
            out += [f"*SHELL SECTION, ELSET=S{s}, MATERIAL=M, OFFSET=SPOS", "0.1, 5"]
    out += ["*MATERIAL, NAME=M", "*ELASTIC", "1e6, 0", "*BOUNDARY", "ROOT0, 1, 6", "ROOT1, 1, 6",
            "*STEP", "*STATIC", "*CLOAD", "9, 1, 0.5", "10, 1, 0.5",
            "125, 1, 0.16666666666666667", "126, 1, 0.66666666666666667",
            "127, 1, 0.16666666666666667", "*NODE PRINT", "U", "*EL PRINT, ELSET=S0", "SF",
            "*END STEP"]
    write("shell_strip_offset.inp", out)


def rollup(et, n, name):
    """Cantilever strip 10 x 1 x 0.1 (E = 1e6, nu = 0) under the end moment 2 pi E I / L that
    rolls it into a full circle, NLGEOM."""
    q8 = et == "S8R"
    nodes, elems, nid, mx, my = grid(n, 1, q8, False, lambda u, v: (10 * u, v, 0.0))
    have = {k for k, _ in nodes}
    M = 2 * math.pi * 1e6 * 0.1 ** 3 / 12 / 10
    tip = [nid(mx, j) for j in range(my + 1) if nid(mx, j) in have]
    weights = [1 / 6, 2 / 3, 1 / 6] if q8 else [0.5, 0.5]
    out = ["*HEADING", f"Roll-up of a cantilever strip into a circle, {n} {et}", "*NODE"]
    out += node_lines(nodes)
    out += [f"*ELEMENT, TYPE={et}, ELSET=S"] + [f"{k}, " + ", ".join(map(str, e)) for k, e in elems]
    out += ["*NSET, NSET=ROOT", ", ".join(str(nid(0, j)) for j in range(my + 1) if nid(0, j) in have),
            "*NSET, NSET=TIP", ", ".join(map(str, tip)),
            "*SHELL SECTION, ELSET=S, MATERIAL=M", "0.1, 5", "*MATERIAL, NAME=M", "*ELASTIC",
            "1e6, 0", "*BOUNDARY", "ROOT, 1, 6", "*STEP, NLGEOM, INC=200", "*STATIC",
            "0.05, 1.0, 1e-5, 0.05", "*CLOAD"]
    out += [f"{k}, 5, {-M * w:.15g}" for k, w in zip(tip, weights)]
    out += ["*NODE PRINT, NSET=TIP", "U, UR", "*END STEP"]
    write(name, out)


def hemisphere(et, n, name):
    """Pinched hemisphere with an 18-degree hole (MacNeal-Harder), quarter model."""
    R = 10.0

    def X(u, v):
        ph, la = math.radians(90 * u), math.radians(72 * v)
        return (R * math.cos(la) * math.cos(ph), R * math.cos(la) * math.sin(ph), R * math.sin(la))

    nodes, elems, nid, m, _ = grid(n, n, et == "S8R", False, X)
    have = {k for k, _ in nodes}
    sel = lambda lst: ", ".join(str(k) for k in lst if k in have)
    out = ["*HEADING", f"Pinched hemisphere, quarter, {et} {n} x {n}", "*NODE"] + node_lines(nodes)
    out += [f"*ELEMENT, TYPE={et}, ELSET=H"] + [f"{k}, " + ", ".join(map(str, e)) for k, e in elems]
    out += ["*NSET, NSET=PHI0", sel(nid(0, j) for j in range(m + 1)),
            "*NSET, NSET=PHI90", sel(nid(m, j) for j in range(m + 1)),
            "*NSET, NSET=LOADS", f"{nid(0, 0)}, {nid(m, 0)}",
            "*SHELL SECTION, ELSET=H, MATERIAL=M", "0.04", "*MATERIAL, NAME=M", "*ELASTIC",
            "6.825e7, 0.3", "*BOUNDARY", "PHI0, YSYMM", "PHI90, XSYMM", f"{nid(0, 0)}, 3",
            "*STEP", "*STATIC", "*CLOAD", f"{nid(0, 0)}, 1, 1.0", f"{nid(m, 0)}, 2, -1.0",
            "*NODE PRINT, NSET=LOADS", "U", "*END STEP"]
    write(name, out)


def macneal_harder_straight():
    """MacNeal-Harder straight cantilever (L = 6, width 0.2, t = 0.1, E = 1e7, nu = 0.3), 6 x 1
    rectangular S4R, four copies (1 apart in z) with unit tip loads: extension, in-plane shear,
    out-of-plane shear, twist."""
    out = ["*HEADING", "MacNeal-Harder straight cantilever, 6 x 1 S4R, four load cases"]
    loads = []
    for c in range(4):
        base = 100 * c
        out.append("*NODE")
        out += [f"{base + 2 * i + j + 1}, {i:.15g}, {0.2 * j:.15g}, {float(c):.15g}"
                for i in range(7) for j in range(2)]
        out.append(f"*ELEMENT, TYPE=S4R, ELSET=C{c}")
        out += [f"{base + i + 1}, {base + 2 * i + 1}, {base + 2 * i + 3}, {base + 2 * i + 4}, "
                f"{base + 2 * i + 2}" for i in range(6)]
        out += [f"*SHELL SECTION, ELSET=C{c}, MATERIAL=M", "0.1"]
        a, b = base + 13, base + 14
        loads += {0: [f"{a}, 1, 0.5", f"{b}, 1, 0.5"], 1: [f"{a}, 2, 0.5", f"{b}, 2, 0.5"],
                  2: [f"{a}, 3, 0.5", f"{b}, 3, 0.5"], 3: [f"{a}, 3, -5.", f"{b}, 3, 5."]}[c]
    out += ["*MATERIAL, NAME=M", "*ELASTIC", "1e7, 0.3", "*BOUNDARY"]
    out += [f"{100 * c + k}, 1, 6" for c in range(4) for k in (1, 2)]
    out += ["*STEP", "*STATIC", "*CLOAD"] + loads + ["*NODE PRINT", "U", "*END STEP"]
    write("shell_macneal_harder_straight.inp", out)


if __name__ == "__main__":
    macneal_harder_straight()
    strip_offset()
    rollup("S4R", 32, "shell_rollup_s4r.inp")
    rollup("S8R", 16, "shell_rollup_s8r.inp")
    hemisphere("S4R", 8, "shell_hemisphere.inp")
    strip()
    plate()
    scordelis("S8R", 8, "shell_scordelis_lo.inp")
    scordelis("S4R", 16, "shell_scordelis_lo_s4r.inp")
