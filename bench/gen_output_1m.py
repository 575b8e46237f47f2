#!/usr/bin/env python3
"""Generate a deck whose solve is trivial but whose result frame is large: an n x n grid of free
nodes, each held by three SPRING1 (k = 1, one per DOF, so the stiffness matrix is diagonal), pushed
down by a unit CLOAD, and a GAPUNI (clearance 0.5, closure direction (0, 0, -1)) from each node of
the central --gaps-side x --gaps-side patch to its own fixed ground node. The gaps close (u = 0.5,
gap force 0.5). With the default n = 578: 334,084 nodes, 1,002,252 equations, 40,000 gaps.

Used to time the output of a 1M-equation frame (job.dat with *NODE PRINT of every node,
job.results.json and the ParaView frame), which the solve does not hide:
    bench/gen_output_1m.py -o out1m.inp && build/release/gapfem out1m.inp
(the timing line "output" of the terminal summary). With --increments n the step has n fixed
increments, each a frame of every node in job.results.json: summary.publication_seconds of that
file is the cost of keeping it a complete document after every increment (docs/results.md).
"""
import argparse


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", type=int, default=578, help="nodes per side of the grid")
    ap.add_argument("--gaps-side", type=int, default=200, help="side of the patch with gaps")
    ap.add_argument("--increments", type=int, default=1,
                    help="fixed increments of the step (*STATIC, DIRECT): each one is a frame "
                         "with the *NODE PRINT of every node, published to job.results.json")
    ap.add_argument("-o", "--output", default="out1m.inp")
    a = ap.parse_args()
    n, g = a.n, a.gaps_side
    start = (n - g) // 2
    ground0 = n * n + 1
    with open(a.output, "w") as f:
        f.write("*HEADING\nspring field with gaps: output timing deck\n*NODE, NSET=FREE\n")
        for j in range(n):
            for i in range(n):
                f.write(f"{j * n + i + 1}, {i}., {j}., 0.\n")
        f.write("*NODE, NSET=GROUND\n")
        patch = []
        for j in range(start, start + g):
            for i in range(start, start + g):
                patch.append(j * n + i + 1)
        for k, node in enumerate(patch):
            i, j = (node - 1) % n, (node - 1) // n
            f.write(f"{ground0 + k}, {i}., {j}., -1.\n")
        for dof in (1, 2, 3):
            f.write(f"*ELEMENT, TYPE=SPRING1, ELSET=S{dof}\n")
            base = dof * 10_000_000
            for node in range(1, n * n + 1):
                f.write(f"{base + node}, {node}\n")
            f.write(f"*SPRING, ELSET=S{dof}\n{dof}\n1.\n")
        f.write("*ELEMENT, TYPE=GAPUNI, ELSET=GAPS\n")
        for k, node in enumerate(patch):
            f.write(f"{40_000_000 + k + 1}, {node}, {ground0 + k}\n")
        f.write("*GAP, ELSET=GAPS\n0.5, 0., 0., -1., 1.\n")
        f.write("*BOUNDARY\nGROUND, 1, 3\n")
        inc = 1.0 / a.increments
        static = f"*STATIC, DIRECT\n{inc!r}, 1.\n" if a.increments > 1 else "*STATIC\n"
        f.write(f"*STEP, INC={a.increments + 10}\n{static}*CLOAD\nFREE, 3, -1.\n"
                "*NODE PRINT, NSET=FREE\nU, RF\n"
                "*EL PRINT, ELSET=GAPS\nS, E\n*END STEP\n")
    print(f"nodes {n * n + len(patch)}, equations {3 * n * n}, gaps {len(patch)}")


if __name__ == "__main__":
    main()
