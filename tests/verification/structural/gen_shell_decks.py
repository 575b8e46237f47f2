#!/usr/bin/env python3
"""Writes the shell verification decks of this directory (our own meshes; run from here).

shell_strip_moment.inp  cantilever strips of S4R, S4, S3, S8R under an end moment (exact)
shell_plate_ss.inp      quarter of a simply supported square plate under pressure, S4R 8x8
shell_scordelis_lo.inp  Scordelis-Lo roof, quarter, S8R 8x8 (and S4R 16x16 in the _s4r deck)
shell_strip_offset.inp  strips with OFFSET=SPOS (S8R: *NODAL THICKNESS) under a tip axial force
shell_rollup_*.inp      NLGEOM roll-up of a strip into a circle (S4R 32, S8R 16 elements)
shell_hemisphere.inp    pinched hemisphere, quarter, S4R 8x8
shell_macneal_harder_straight.inp  MacNeal-Harder straight cantilever, S4R 6 x 1, four loads
shell_twisted_beam.inp  MacNeal-Harder twisted beam t = 0.32, S4R and S8R 12 x 2, two tip loads each
shell_twisted_beam_thin.inp  the same with t = 0.0032 and tip loads 1e-6
shell_plate_thick_*.inp  quarter of a hard simply supported square plate, a/h = 10 and 5, S4R 8 x 8
                        and S8R 8 x 8 (Mindlin closed form: see thick_plate)
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


def edge_weights(n_nodes, quad8):
    """Consistent nodal forces of a unit uniform line load along an edge of n_nodes nodes (equally
    spaced elements, linear or quadratic)."""
    ne = (n_nodes - 1) // (2 if quad8 else 1)
    w = [0.0] * n_nodes
    for e in range(ne):
        if quad8:
            for k, f in enumerate((1 / 6, 2 / 3, 1 / 6)):
                w[2 * e + k] += f / ne
        else:
            w[e] += 0.5 / ne
            w[e + 1] += 0.5 / ne
    return w


# MacNeal & Harder (1985) twisted beam: L = 12, width 1.1, twist 90 degrees from root to tip,
# E = 29.0e6, nu = 0.22, root clamped. Published tip displacements along the load: t = 0.32, P = 1:
# 5.424e-3 for the load in the plane of the tip (along the tip's width, i.e. along the root's
# normal) and 1.754e-3 for the load normal to the tip (along the root's width); t = 0.0032,
# P = 1e-6: 5.256e-3 and 1.294e-3. The root lies in the x-y plane (width along y, normal +z); the
# section at x is turned by theta = (pi/2) x / L about x, so the tip's width runs along z and its
# normal along -y: the in-plane load is along z (DOF 3), the out-of-plane one along y (DOF 2).
TWIST_CASES = [("S4R", 12, 2, 3), ("S4R", 12, 2, 2), ("S8R", 12, 2, 3), ("S8R", 12, 2, 2)]


def twisted_beam(t, P, name, cases=TWIST_CASES):
    """One twisted beam per case (element, n along, n across, load DOF), copy c shifted 3c in y,
    labels from 1000c; the tip load P is split over the tip nodes as a uniform line load."""
    L, W = 12.0, 1.1
    out = ["*HEADING", f"MacNeal-Harder twisted beam, t = {t:g}, tip load {P:g}: "
           + "; ".join(f"{et} {nx} x {ny} load {d}" for et, nx, ny, d in cases)]
    loads, outs = [], []
    for c, (et, nx, ny, dof) in enumerate(cases):
        def X(u, v, c=c):
            th = 0.5 * math.pi * u
            s = W * (v - 0.5)
            return (L * u, 3.0 * c + s * math.cos(th), s * math.sin(th))

        q8 = et == "S8R"
        nodes, elems, nid, mx, my = grid(nx, ny, q8, et == "S3", X, base=1000 * c,
                                         ebase=1000 * c)
        assert len(cases) == 1 or len(nodes) < 1000, "labels of the copies would overlap"
        have = {k for k, _ in nodes}
        root = [nid(0, j) for j in range(my + 1) if nid(0, j) in have]
        tip = [nid(mx, j) for j in range(my + 1) if nid(mx, j) in have]
        out += ["*NODE"] + node_lines(nodes)
        out += [f"*ELEMENT, TYPE={et}, ELSET=B{c}"] + [f"{k}, " + ", ".join(map(str, e))
                                                        for k, e in elems]
        out += [f"*NSET, NSET=ROOT{c}", ", ".join(map(str, root)),
                f"*NSET, NSET=TIP{c}", ", ".join(map(str, tip)),
                f"*SHELL SECTION, ELSET=B{c}, MATERIAL=M", f"{t:g}"]
        loads += [f"{k}, {dof}, {P * w:.15g}" for k, w in zip(tip, edge_weights(len(tip), q8))]
        outs.append(f"TIP{c}")
    out += ["*MATERIAL, NAME=M", "*ELASTIC", "29.0e6, 0.22", "*BOUNDARY"]
    out += [f"ROOT{c}, 1, 6" for c in range(len(cases))]
    out += ["*STEP", "*STATIC", "*CLOAD"] + loads
    for s in outs:
        out += [f"*NODE PRINT, NSET={s}", "U"]
    out += ["*END STEP"]
    write(name, out)


def marcus_and_kirchhoff_centre():
    """Centre values of the simply supported square plate (a = q = D = 1) under uniform load:
    the Marcus moment M (laplacian M = -q, M = 0 on the edges) and the Kirchhoff deflection w_K
    (laplacian w = -M / D), by the single (Levy) series, checked against the Navier double
    series."""
    M = 1 / 8 - sum((-1) ** ((m - 1) // 2) * 4 / (m * math.pi) ** 3 / math.cosh(m * math.pi / 2)
                    for m in range(1, 60, 2))
    w = 0.0
    for m in range(1, 60, 2):
        am = m * math.pi / 2
        w += (-1) ** ((m - 1) // 2) / m ** 5 * (1 - (am * math.tanh(am) + 2) / (2 * math.cosh(am)))
    w *= 4 / math.pi ** 5
    Mn = wn = 0.0
    for m in range(1, 400, 2):
        for n in range(1, 400, 2):
            s = (-1) ** ((m + n - 2) // 2) / (m * n)
            Mn += s / (m * m + n * n)
            wn += s / (m * m + n * n) ** 2
    Mn *= 16 / math.pi ** 4
    wn *= 16 / math.pi ** 6
    assert abs(Mn - M) < 1e-6 * M and abs(wn - w) < 1e-7 * w, (M, Mn, w, wn)
    return M, w


def thick_plate(et, n, ratios, name):
    """Quarter of a hard simply supported square plate a = 1 under q = 1 (E = 1e7, nu = 0.3), one
    copy per a/h (copy c shifted 2c in x, labels from 1000c); edges x = 0 and y = 0 hold w and the
    rotation along the edge (UR1 on x = 0, UR2 on y = 0), x = y = a/2 are symmetry planes.

    Mindlin plate with hard supports (Wang & Alwis 1995; Wang, Reddy & Lee, "Shear Deformable
    Beams and Plates", 2000): with the rotations psi, M = (Mx + My) / (1 + nu) = D div psi and
    Q = kappa G h (grad w + psi), equilibrium div Q = -q and Q = div(moments) give
    laplacian M = -q. On a straight hard-supported edge psi_s = 0 along it (so d psi_s / ds = 0)
    and M_n = D (d psi_n / dn + nu d psi_s / ds) = 0, so d psi_n / dn = 0 and M = D div psi = 0:
    the same problem as the Kirchhoff plate's Marcus moment, so M_Mindlin = M_Kirchhoff. Then
    laplacian w = -q / (kappa G h) - M / D = laplacian (M / (kappa G h)) + laplacian w_K with
    w = M = w_K = 0 on the edges, so w_M = w_K + M / (kappa G h), kappa = 5/6. At the centre
    (a = q = 1) M = 0.0736714 and w_K = 0.00406235 / D (marcus_and_kirchhoff_centre); with
    D / (G h) = h^2 / (6 (1 - nu)), w_M / w_K = 1 + 18.1352 (h/a)^2 / (6 kappa (1 - nu)) = 1.051815
    at a/h = 10 and 1.20726 at a/h = 5."""
    E, nu = 1e7, 0.3
    Mc, wc = marcus_and_kirchhoff_centre()
    out = ["*HEADING", f"Thick hard simply supported square plate, quarter, {et} {n} x {n}, a/h = "
           + ", ".join(f"{r:g}" for r in ratios)]
    bcs = []
    for c, r in enumerate(ratios):
        h = 1.0 / r
        D, G = E * h ** 3 / (12 * (1 - nu * nu)), E / (2 * (1 + nu))
        wk, ws = wc / D, Mc / (5 / 6 * G * h)
        nodes, elems, nid, m, _ = grid(n, n, et == "S8R", et == "S3",
                                       lambda u, v, c=c: (2.0 * c + 0.5 * u, 0.5 * v, 0.0),
                                       base=1000 * c, ebase=1000 * c)
        assert len(ratios) == 1 or (m + 1) ** 2 < 1000, "labels of the copies would overlap"
        have = {k for k, _ in nodes}
        side = lambda f: ", ".join(str(f(k)) for k in range(m + 1) if f(k) in have)
        out += [f"** a/h = {r:g}: w_K = {wk:.10g}, w_shear = {ws:.10g}, Mindlin w = {wk + ws:.10g}"
                f" at node {nid(m, m)}"]
        out += ["*NODE"] + node_lines(nodes)
        out += [f"*ELEMENT, TYPE={et}, ELSET=P{c}"] + [f"{k}, " + ", ".join(map(str, e))
                                                        for k, e in elems]
        out += [f"*NSET, NSET=X0_{c}", side(lambda j: nid(0, j)),
                f"*NSET, NSET=Y0_{c}", side(lambda i: nid(i, 0)),
                f"*NSET, NSET=XS_{c}", side(lambda j: nid(m, j)),
                f"*NSET, NSET=YS_{c}", side(lambda i: nid(i, m)),
                f"*NSET, NSET=C{c}", str(nid(m, m)),
                f"*SHELL SECTION, ELSET=P{c}, MATERIAL=M", f"{h:.15g}, 5"]
        bcs += [f"X0_{c}, 3", f"X0_{c}, 4", f"Y0_{c}, 3", f"Y0_{c}, 5", f"XS_{c}, XSYMM",
                f"YS_{c}, YSYMM"]
    out += ["*MATERIAL, NAME=M", "*ELASTIC", "1e7, 0.3", "*BOUNDARY"] + bcs
    out += ["*STEP", "*STATIC", "*DLOAD"] + [f"P{c}, P, 1.0" for c in range(len(ratios))]
    for c in range(len(ratios)):
        out += [f"*NODE PRINT, NSET=C{c}", "U"]
    out += ["*END STEP"]
    write(name, out)


if __name__ == "__main__":
    twisted_beam(0.32, 1.0, "shell_twisted_beam.inp")
    twisted_beam(0.0032, 1e-6, "shell_twisted_beam_thin.inp")
    thick_plate("S4R", 8, [10, 5], "shell_plate_thick_s4r.inp")
    thick_plate("S8R", 8, [10, 5], "shell_plate_thick_s8r.inp")
    macneal_harder_straight()
    strip_offset()
    rollup("S4R", 32, "shell_rollup_s4r.inp")
    rollup("S8R", 16, "shell_rollup_s8r.inp")
    hemisphere("S4R", 8, "shell_hemisphere.inp")
    strip()
    plate()
    scordelis("S8R", 8, "shell_scordelis_lo.inp")
    scordelis("S4R", 16, "shell_scordelis_lo_s4r.inp")
