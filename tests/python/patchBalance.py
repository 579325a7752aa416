#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""The per-patch balance of a coagulationFoam log against its totals, at every write.

At each write the solver logs the run's totals ("particles in/incepted/out = a / b / c",
"mass initial + inflow + inception - outflow + control = ...") and, per patch, what left
through it since the case's first start ("outflow outlet: N particles, number X, mass Y",
"deposited bottom: ..."); postProcessing/coagulationBalance/patches.csv repeats those
lines. This checks, at every write of the log:

  - the patch lines add up to the totals: particles exactly, mass to round-off (the
    sums are the same terms added in another order). After a restart the totals count
    from the run's start and the patch lines from the first start: the patch totals the
    run started from (--start, the start time's uniform/coagulationPatchBalance) are
    subtracted first;
  - with --csv, patches.csv's rows at that time are the log's lines;
  - with --equal-weights, every leaving particle had the weight W of the log's "weight per
    new particle" (runs without number control in which nothing coagulates under SWA):
    each patch's number is W times its particles;
  - with --inflow C QT M (inflow of density C and particle mass M, QT the inlet's volume
    flux times the time since the start): at the last write the particles booked as entering
    are Poisson with mean C QT/W (a sum over faces and steps of Poisson counts), within 4
    standard deviations, and their mass is the count times W M to round-off.

    patchBalance.py LOG [--start FILE] [--csv FILE] [--equal-weights] [--inflow C QT M]

Prints one line per write and exits 1 on the first violation (the message says which).
"""
import argparse
import csv
import re
import sys

REL = 1e-12     # round-off of a sum of up to ~1e5 terms printed with 17 digits


def parse_log(path):
    """[(time, totals, patches)] per "Coagulation cloud:" block of the log, totals a dict
    (inParticles, incepted, outParticles, inMass, outMass), patches {name: (kind,
    particles, number, mass)}; the weight per new particle (None if not logged)."""
    writes, time, weight = [], None, None
    lines = open(path).read().splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        m = re.match(r"^Time = (\S+)", line)
        if m:
            time = m.group(1)
        m = re.search(r"weight per new particle (\S+?),", line)
        if m and weight is None:
            weight = float(m.group(1))
        if line.startswith("Coagulation cloud:"):
            totals, patches = {}, {}
            i += 1
            while i < len(lines) and lines[i].strip():
                s = lines[i]
                m = re.search(r"particles in/incepted/out\s*=\s*(\d+) / (\d+) / (\d+)", s)
                if m:
                    totals["inParticles"], totals["incepted"], totals["outParticles"] = \
                        (int(g) for g in m.groups())
                m = re.search(r"control = (\S+) \+ (\S+) \+ (\S+) - (\S+) \+ (\S+)$", s)
                if m:
                    totals["inMass"] = float(m.group(2))
                    totals["outMass"] = float(m.group(4))
                m = re.match(r"^\s+(outflow|deposited) (\S+): (\d+) particles, number (\S+), mass (\S+)$", s)
                if m:
                    patches[m.group(2)] = (m.group(1), int(m.group(3)), float(m.group(4)),
                                           float(m.group(5)))
                i += 1
            if "outParticles" not in totals or "outMass" not in totals:
                raise SystemExit("%s: a 'Coagulation cloud:' block without its totals" % path)
            writes.append((time, totals, patches))
        i += 1
    return writes, weight


def parse_start(path):
    """{patch: (particles, number, mass)} of a uniform/coagulationPatchBalance file."""
    text = open(path).read()
    out = {}
    for name, body in re.findall(r"(\w+)\s*\{([^}]*)\}", text):
        get = lambda key: re.search(r"\b%s\s+(\S+);" % key, body).group(1)
        out[name] = (int(get("particles")), float(get("number")), float(get("mass")))
    return out


def close(a, b, scale):
    return abs(a - b) <= REL * max(abs(scale), 1e-300)


def check_inflow(totals, weight, c, qt, m, out=sys.stdout):
    """The booked inflow (the totals of the last write) against c QT/W particles of mass m."""
    import math
    n, mass = totals["inParticles"], totals["inMass"]
    mu = c * qt / weight
    z = (n - mu) / math.sqrt(mu)
    print("inflow: %d particles, Poisson mean c_in Q t/W = %.1f (z = %.2f); mass %.10g"
          % (n, mu, z, mass), file=out)
    bad = []
    if not abs(z) <= 4:
        bad.append("%d particles entered, expected %.1f: z = %.2f" % (n, mu, z))
    if not close(mass, n * weight * m, mass):
        bad.append("inflow mass %.17g is not the count times W m = %.17g" % (mass, n * weight * m))
    return bad


def check(log, start=None, csv_path=None, equal_weights=False, inflow=None, out=sys.stdout):
    """Returns a list of violations (empty: the balance holds at every write)."""
    writes, weight = parse_log(log)
    bad = []
    if not writes:
        return ["%s: no 'Coagulation cloud:' block" % log]
    if inflow is not None:
        if weight is None:
            bad.append("%s: no 'weight per new particle' line" % log)
        else:
            bad += check_inflow(writes[-1][1], weight, *inflow, out=out)
    before = parse_start(start) if start else {}
    rows = {}
    if csv_path:
        for r in csv.DictReader(open(csv_path)):
            rows.setdefault(r["time"], {})[r["patch"]] = r
    if equal_weights and weight is None:
        bad.append("%s: no 'weight per new particle' line" % log)
    for time, totals, patches in writes:
        n = sum(p[1] - before.get(name, (0, 0, 0))[0] for name, p in patches.items())
        mass = sum(p[3] - before.get(name, (0, 0, 0))[2] for name, p in patches.items())
        lost = [name for name in before if name not in patches]
        if lost:
            bad.append("t = %s: patches %s of the start missing" % (time, lost))
        if n != totals["outParticles"]:
            bad.append("t = %s: the patches' particles add up to %d, the total out is %d"
                       % (time, n, totals["outParticles"]))
        if not close(mass, totals["outMass"], totals["outMass"] + totals["inMass"]):
            bad.append("t = %s: the patches' mass adds up to %.17g, the total outflow is %.17g"
                       " (relative %.3g)" % (time, mass, totals["outMass"],
                                             (mass - totals["outMass"]) / max(totals["outMass"], 1e-300)))
        if equal_weights and weight is not None:
            for name, (kind, p, number, m) in patches.items():
                if not close(number, weight * p, number):
                    bad.append("t = %s: %s %s: number %.17g is not W = %g times its %d particles"
                               % (time, kind, name, number, weight, p))
        if csv_path:
            at = rows.get(time, {})
            if sorted(at) != sorted(patches):
                bad.append("t = %s: patches.csv has %s, the log %s" % (time, sorted(at), sorted(patches)))
            for name, (kind, p, number, m) in patches.items():
                r = at.get(name)
                if r and (r["kind"] != kind or int(r["particles"]) != p
                          or not close(float(r["number"]), number, number)
                          or not close(float(r["mass"]), m, m)):
                    bad.append("t = %s: patches.csv's row %s differs from the log's line %s"
                               % (time, dict(r), (kind, p, number, m)))
        print("t = %s: %d patch line(s) add up to %d particles out, mass %.10g (total %.10g)"
              % (time, len(patches), n, mass, totals["outMass"]), file=out)
    return bad


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("log")
    ap.add_argument("--start", help="the start time's uniform/coagulationPatchBalance (a restart)")
    ap.add_argument("--csv", help="postProcessing/coagulationBalance/patches.csv")
    ap.add_argument("--equal-weights", action="store_true")
    ap.add_argument("--inflow", nargs=3, type=float, metavar=("C", "QT", "M"))
    a = ap.parse_args(argv)
    bad = check(a.log, a.start, a.csv, a.equal_weights, a.inflow)
    for b in bad:
        print("FAIL %s: %s" % (a.log, b))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
