#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationProfiles: moments along an axis and deposition per wall of a coagulationFoam
run on a general mesh (a thin command line over coagulationPost.profiles).

  coagulationProfiles.py --case DIR [--out results] [--axis x] [--bins 50]
                         [--t-relax T] [--no-plots]

Outputs in --out (relative to --case): profiles.csv (slab means of the time-averaged
M0..M3 along the axis), deposition.csv (per patch: outflow or deposited, computational
particles, physical particles, mass), axialMoments.png, deposition.png.

Exit status: 0 success, 2 bad input (no such case, no sample file, no sample at t >= tRelax).
"""
import argparse
import os
import sys

from coagulationPost import profiles
from coagulationPost.samples import InputError


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--case", default=".")
    ap.add_argument("--out", default="results")
    ap.add_argument("--axis", choices=sorted(profiles.AXES), default="x")
    ap.add_argument("--bins", type=int, default=50)
    ap.add_argument("--t-relax", type=float, default=None)
    ap.add_argument("--no-plots", action="store_true")
    a = ap.parse_args()
    out = a.out if os.path.isabs(a.out) else os.path.join(a.case, a.out)
    try:
        profiles.write(a.case, out, a.axis, a.bins, a.t_relax, plots=not a.no_plots)
    except InputError as e:
        print("coagulationProfiles: error: %s" % e, file=sys.stderr)
        return 2
    print("Profiles and deposition in %s" % out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
