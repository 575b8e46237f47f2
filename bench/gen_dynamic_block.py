#!/usr/bin/env python3
"""Generate the dynamic benchmark deck: bench/gen_block.py's quarter block of C3D8 on a GAPUNI
foundation (or with a fixed base), given a density and a *DYNAMIC step instead of *STATIC. The
decks run unchanged in gapfem and in CalculiX (ccx): NLGEOM on the step with gaps (ccx needs a
nonlinear step to iterate on GAPUNI; docs/performance.md), *GAP fields 6-7 with --penalty, the
same HHT parameter on both (*DYNAMIC, ALPHA=, DIRECT: fixed increments).

Loading: the top pressure of gen_block.py rises over --rise seconds and then holds (a tabular
*AMPLITUDE from 0, so that both codes start from rest with zero accelerations), and the block
rings on its foundation. With the defaults (E = 2e5, rho = 1, height 1) the first vertical mode of
the block is about a quarter wave on its height, T ~ 4 H / sqrt(E / rho) = 8.9e-3 s; dt = 2.5e-4
s is T / 36, and 200 increments cover 5.6 periods.

Output: *NODE PRINT of the monitored node (the top centre, MON) and of the ground reactions
(TOTALS=YES) after every increment.

Usage: gen_dynamic_block.py --nx 25 --nz 24 --penalty 1e7 --increments 200 -o job.inp
"""
import argparse
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--nx", type=int, default=10)
    ap.add_argument("--nz", type=int, default=10)
    ap.add_argument("--penalty", type=float, default=None, help="GAPUNI penalty (ccx fields 6-7)")
    ap.add_argument("--tension", type=float, default=None,
                    help="ccx field 7: tension of an open penalty gap (ccx default 1e-3)")
    ap.add_argument("--no-gaps", action="store_true", help="fixed base, linear step (no NLGEOM)")
    ap.add_argument("--pressure", type=float, default=10.0)
    ap.add_argument("--E", type=float, default=2.0e5)
    ap.add_argument("--dmax", type=float, default=2.0e-4, help="clearance at the corner")
    ap.add_argument("--rho", type=float, default=1.0)
    ap.add_argument("--dt", type=float, default=2.5e-4)
    ap.add_argument("--increments", type=int, default=200)
    ap.add_argument("--rise", type=float, default=2.0e-3, help="rise time of the pressure")
    ap.add_argument("--alpha", type=float, default=-0.05, help="HHT alpha on both codes")
    ap.add_argument("-o", "--output", default="-")
    a = ap.parse_args()
    cmd = [sys.executable, os.path.join(HERE, "gen_block.py"), "--nx", str(a.nx), "--nz", str(a.nz),
           "--pressure", repr(a.pressure), "--E", repr(a.E), "--dmax", repr(a.dmax)]
    if a.no_gaps:
        cmd.append("--no-gaps")
    if a.penalty is not None:
        cmd += ["--penalty", repr(a.penalty)]
    if a.tension is not None:
        cmd += ["--tension", repr(a.tension)]
    p = subprocess.run(cmd, capture_output=True, text=True, check=True)
    deck = p.stdout
    # the density goes with the elastic constants
    deck = re.sub(r"(\*ELASTIC\n[^\n]*\n)", lambda m: m.group(1) + f"*DENSITY\n{a.rho:.9g}\n", deck, count=1)
    model = deck[:deck.index("*STEP")]
    # the monitored node: the top node on both symmetry planes (the block's centre line)
    top = 1 + (a.nx + 1) * (a.nx + 1) * a.nz
    step = [f"*AMPLITUDE, NAME=RISE\n0., 0., {a.rise:.9g}, 1., 1e6, 1.\n",
            f"*NSET, NSET=MON\n{top}\n",
            f"*STEP{'' if a.no_gaps else ', NLGEOM'}, INC={a.increments + 100}\n",
            f"*DYNAMIC, ALPHA={a.alpha:.9g}, DIRECT\n{a.dt:.9g}, {a.dt * a.increments:.9g}\n",
            f"*DSLOAD, AMPLITUDE=RISE\nSTOP, P, {a.pressure:.9g}\n",
            "*NODE PRINT, NSET=MON\nU\n",
            # every increment: ccx's FREQUENCY is one setting for all the step's *NODE PRINT
            f"*NODE PRINT, NSET={'BASE' if a.no_gaps else 'GROUND'}, TOTALS=YES\nRF\n",
            "*END STEP\n"]
    text = model + "".join(step)
    out = sys.stdout if a.output == "-" else open(a.output, "w")
    out.write(text)
    if out is not sys.stdout:
        out.close()
    # gen_block.py's summary line (equations, elements, gaps) for run_suite.py
    sys.stderr.write(p.stderr.strip() + f", increments {a.increments}\n")


if __name__ == "__main__":
    main()
