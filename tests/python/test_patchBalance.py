# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""patchBalance.py (the case tests' check of the per-patch lines against the totals) on
logs written here: it passes a consistent log and names each kind of inconsistency."""
import importlib.util
import os

# patchBalance.py is the case tests' script beside this file, not a module of the package
_spec = importlib.util.spec_from_file_location(
    "patchBalance", os.path.join(os.path.dirname(os.path.abspath(__file__)), "patchBalance.py"))
patchBalance = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(patchBalance)

BLOCK = """Time = {t}  particles = 10
Coagulation cloud:
    particles in domain        = 10
    physical particles         = 0.8
    coagulation events         = 0 (fictitious 0, 0 per real one)
    particles in/incepted/out  = 0 / {inc} / {out}
    mass initial + inflow + inception - outflow + control = 0 + 0 + 8.8000000000000007 - {mout} + 0
    mass in domain             = 0.8
    mass balance error (rel.)  = 0
    particle balance error     = 0
    particles held at a face   = 0
    outflow outlet: {n1} particles, number {x1}, mass {m1}
    deposited bottom: {n2} particles, number {x2}, mass {m2}

"""

HEAD = "Coagulation cloud coagulationCloud: 0 particles, weight per new particle 0.08, inception rate\n"


def write(tmp_path, blocks, rows=None):
    log = tmp_path / "log"
    log.write_text(HEAD + "".join(BLOCK.format(**b) for b in blocks))
    if rows is None:
        return str(log), None
    csv = tmp_path / "patches.csv"
    csv.write_text("time,patch,kind,particles,number,mass\n" + "".join(r + "\n" for r in rows))
    return str(log), str(csv)


GOOD = dict(t="0.3", inc=110, out=100, mout="8", n1=60, x1=4.8, m1=4.8, n2=40, x2=3.2, m2=3.2)
ROWS = ["0.3,outlet,outflow,60,4.8,4.8", "0.3,bottom,deposited,40,3.2,3.2"]


def test_consistent_log_passes(tmp_path):
    log, csv = write(tmp_path, [GOOD], ROWS)
    assert patchBalance.check(log, csv_path=csv, equal_weights=True) == []


def test_a_patch_mass_counted_twice_is_named(tmp_path):
    log, csv = write(tmp_path, [dict(GOOD, m2=6.4)])
    bad = patchBalance.check(log)
    assert len(bad) == 1 and "mass adds up to" in bad[0]


def test_particles_and_csv_and_weights(tmp_path):
    log, csv = write(tmp_path, [dict(GOOD, n1=61, x1=4.88)], ["0.3,outlet,outflow,61,4.88,4.9",
                                                             "0.3,bottom,deposited,40,3.2,3.2"])
    bad = patchBalance.check(log, csv_path=csv)
    assert any("particles add up to 101" in b for b in bad)
    assert any("patches.csv's row" in b for b in bad)
    log, _ = write(tmp_path, [dict(GOOD, x1=60)])
    bad = patchBalance.check(log, equal_weights=True)
    assert len(bad) == 1 and "is not W = 0.08 times its 60 particles" in bad[0]


def test_restart_subtracts_the_start(tmp_path):
    start = tmp_path / "coagulationPatchBalance"
    start.write_text("outlet\n{\n    particles 20;\n    number 1.6;\n    mass 2;\n}\n"
                     "bottom\n{\n    particles 10;\n    number 0.8;\n    mass 1;\n}\n")
    b = dict(GOOD, out=100, mout="5", n1=80, x1=6.4, m1=5.0, n2=50, x2=4.0, m2=3.0)
    log, _ = write(tmp_path, [b])
    assert patchBalance.check(log, start=str(start)) == []
    # the start's mass read as its number: the sum is off by 0.4
    start.write_text(start.read_text().replace("mass 2;", "mass 1.6;"))
    bad = patchBalance.check(log, start=str(start))
    assert len(bad) == 1 and "mass adds up to" in bad[0]


def test_inflow_against_its_poisson_mean(tmp_path):
    # 0 particles entered in GOOD; a log with 10000 entered, W = 0.08, mass 2 each
    log = tmp_path / "log"
    text = HEAD + BLOCK.format(**GOOD)
    text = text.replace("= 0 / 110 / 100", "= 10000 / 110 / 100").replace(
        "control = 0 + 0 +", "control = 0 + 1600.0000000000002 +")
    log.write_text(text)
    # mean c QT/W = 10000 (z = 0), 10400 (z = -3.9), 10500 (z = -4.9)
    assert patchBalance.check(str(log), inflow=(1e3, 0.8, 2.0)) == []
    assert patchBalance.check(str(log), inflow=(1e3, 0.832, 2.0)) == []
    bad = patchBalance.check(str(log), inflow=(1e3, 0.84, 2.0))
    assert len(bad) == 1 and "z = -4.88" in bad[0]
    bad = patchBalance.check(str(log), inflow=(1e3, 0.8, 3.0))
    assert len(bad) == 1 and "not the count times W m" in bad[0]
