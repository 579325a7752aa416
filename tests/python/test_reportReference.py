# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationReport.py's analytic reference and exact size distribution on synthetic sample
files in the solver's layout.

--analytic auto compares with Patterson & Wagner's duct only where the samples describe that
case: a constant or additive kernel, inception, masses in units of the incepted particle's
(not in kg), no growth or loss. Elsewhere the report has no reference and says why in one
line; --analytic KIND still forces one. The size distribution of log bins in kg (no integer
size in any bin) is plotted without an exact curve."""
import importlib.util
import json
import os

import h5py
import numpy as np
import pytest

from coagulationPost import analytic, psd

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "applications", "utilities",
                      "coagulationReport", "coagulationReport.py")

I, K0, NC, DX, DT = 3e8, 1e-5, 25, 4e-3, 5e-3
# the attributes the solver's momentSampler writes for the paper's constant-kernel duct
PAPER = dict(n=256, V1=1.25e-8, K0=K0, inceptionRate=I, seed=3, splitDeltaT=1e-4,
             sampleInterval=DT, tRelax=0.4, particleWeight=1.0, algorithm="SWA",
             kernel="constant", coagulations=1e6, fictitious=2e5, grownMass=0.0,
             lostParticles=0.0, lostNumber=0.0, lostMass=0.0)


def _cli():
    spec = importlib.util.spec_from_file_location("coagulationReportCli", SCRIPT)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _samples(case, mass=1.0, **attrs):
    """The duct's exact cell averages with 1 % noise, each particle's mass `mass` times the
    paper's (M_k scaled by mass^k): postProcessing/coagulationSamples/samples_0.h5 with the
    paper's attributes, changed by attrs (None: left out)."""
    lo = np.arange(NC) * DX
    avg = analytic.cell_average("constantDuct", lo, lo + DX, I, K0)
    avg *= (mass ** np.arange(4))[:, None]
    t = np.arange(201) * DT
    rng = np.random.default_rng(11)
    d = os.path.join(case, "postProcessing", "coagulationSamples")
    os.makedirs(d)
    with h5py.File(os.path.join(d, "samples_0.h5"), "w") as f:
        f["cellCentres"] = np.stack([lo + DX / 2, np.full(NC, 2e-3), np.full(NC, 2e-3)], 1)
        f["time"] = t
        f["moments"] = avg.T[None] * (1 + 0.01 * rng.standard_normal((len(t), NC, 4)))
        for k, v in {**PAPER, **attrs}.items():
            if v is not None:
                f.attrs[k] = v
    return case


def _psd(case, edges, bin_type, density=0.0, mass_unit=1.0):
    """A sizeDistribution file (postProcessing/psd/0) of two probes with these bins, their
    numbers noisy about 1e10, and the attributes the solver writes (density 0: no 'particles')."""
    B = len(edges) - 1
    N = 200
    rng = np.random.default_rng(5)
    data = np.full((N, 2, B + 2 + len(psd.DERIVED)), np.nan)
    data[:, :, :B] = 1e10 * (1 + 0.1 * rng.standard_normal((N, 2, B)))
    data[:, :, B:B + 2] = 0.0
    data[:, :, B + 2] = data[:, :, :B].sum(axis=2)
    d = os.path.join(case, "postProcessing", "psd", "0")
    os.makedirs(d)
    with h5py.File(os.path.join(d, "sizeDistribution.h5"), "w") as h:
        h["time"] = 0.4 + DT * np.arange(N)
        h["cellCentres"] = np.array([[0.042, 2e-3, 2e-3], [0.094, 2e-3, 2e-3]])
        h["moments"] = data
        h.attrs["columns"] = " ".join(["n%d" % i for i in range(B)] + ["underflow", "overflow"]
                                      + list(psd.DERIVED))
        h.attrs["binEdges"] = " ".join("%.17g" % e for e in edges)
        h.attrs["binType"] = bin_type
        h.attrs["regions"] = "probe0 probe1"
        h.attrs["regionVolumes"] = "6.4e-08 6.4e-08"
        for k, v in dict(timeStart=0.4, correlationTime=0.0, sampleInterval=DT, density=density,
                         massUnit=mass_unit, K0=K0, inceptionRate=I, kernel="constant").items():
            h.attrs[k] = v
    return case


def _report(case, *options):
    """Runs the report on case into case/results; (exit status, summary or None)."""
    rc = _cli().main(["--case", case, "--out", "results"] + list(options))
    path = os.path.join(case, "results", "summary.json")
    return rc, (json.load(open(path)) if os.path.exists(path) else None)


@pytest.mark.parametrize("attrs", [
    {},
    # the paper's duct with the particles' material for the diameters: masses still in
    # units of the incepted particle (1e-24 kg)
    dict(density=1000.0, massUnit=1e-24),
    # samples of an older solver: no growth totals
    dict(grownMass=None, lostParticles=None, lostNumber=None, lostMass=None),
])
def test_the_papers_duct_keeps_its_reference(tmp_path, capsys, attrs):
    rc, s = _report(_samples(str(tmp_path), **attrs), "--no-plots", "--check",
                    "--check-skip-cells", "3")
    out = capsys.readouterr().out
    assert rc == 0 and s["analytic"] == "constantDuct"
    assert "no analytic reference" not in out and "check passed" in out


@pytest.mark.parametrize("mass, attrs, why", [
    # a duct whose masses are in kg: a 1e-21 kg monomer, the particles' massUnit 1 kg
    (1e-21, dict(density=1800.0, massUnit=1.0), "the particles' masses are in kg"),
    # the same without the material: the particles are lighter than one mass unit
    (1e-21, {}, "the particles are lighter than"),
    (1.0, dict(grownMass=2.5e3), "the case has growth"),
    (1.0, dict(grownMass=-1.0, lostParticles=7.0, lostNumber=70.0, lostMass=1.0),
     "the case has growth"),
    (1.0, dict(lostNumber=70.0), "the case loses particles"),
    (1.0, dict(inceptionRate=0.0), "the case has no inception"),
    (1.0, dict(inceptionRate=None), "the samples lack the attribute 'inceptionRate'"),
    (1.0, dict(K0=-1.0), "the kernel's K0 is -1"),
    (1.0, dict(kernel="Brownian"), "the kernel is 'Brownian'"),
])
def test_other_cases_have_no_reference_and_say_why(tmp_path, capsys, mass, attrs, why):
    rc, s = _report(_samples(str(tmp_path), mass, **attrs), "--no-plots")
    out = capsys.readouterr().out
    assert rc == 0 and s["analytic"] is None
    said = [l for l in out.splitlines() if l.startswith("no analytic reference")]
    assert len(said) == 1 and said[0].startswith("no analytic reference: " + why), said
    assert "%" not in "".join(out.splitlines()[4:])          # no relative error in the table
    # a --check has nothing to compare with: bad input, and the reason given
    rc, _ = _report(str(tmp_path), "--no-plots", "--check")
    assert rc == 2 and why in capsys.readouterr().err


def test_growth_in_a_later_file_counts(tmp_path, capsys):
    """Growth booked in the restart's file (the first file's totals are zero)."""
    case = _samples(str(tmp_path))
    d = os.path.join(case, "postProcessing", "coagulationSamples")
    with h5py.File(os.path.join(d, "samples_0.h5"), "r") as f:
        t, m, c = f["time"][:], f["moments"][:], f["cellCentres"][:]
        attrs = dict(f.attrs)
    with h5py.File(os.path.join(d, "samples_0.8.h5"), "w") as f:
        f["time"], f["moments"], f["cellCentres"] = t[160:], m[160:], c
        for k, v in {**attrs, "grownMass": 10.0}.items():
            f.attrs[k] = v
    rc, s = _report(case, "--no-plots")
    assert rc == 0 and s["analytic"] is None
    assert "the case has growth" in capsys.readouterr().out


def test_an_explicit_reference_is_still_drawn(tmp_path, capsys):
    case = _samples(str(tmp_path), grownMass=2.5e3)
    rc, s = _report(case, "--no-plots", "--analytic", "constant")
    cap = capsys.readouterr()
    assert rc == 0 and s["analytic"] == "constantDuct"
    assert "the case has growth" in cap.err                   # a warning, not a refusal


def test_psd_of_log_bins_in_kg_is_plotted_without_an_exact_curve(tmp_path, capsys):
    case = _samples(str(tmp_path), 1e-21, density=1800.0, massUnit=1.0)
    _psd(case, np.geomspace(1e-22, 1e-18, 21), "log", density=1800.0, mass_unit=1.0)
    p = psd.read(case, "psd")
    assert psd.exact(p) is None                   # no integer size k = 1, 2, ... in any bin
    for option in ([], ["--analytic", "none"]):
        rc, _ = _report(case, "--psd", *option)
        assert rc == 0
        for f in ("sizeDistribution.png", "sizeDistributionDiameter.png"):
            assert os.path.getsize(os.path.join(case, "results", "psd", f)) > 1000
        rows = np.genfromtxt(os.path.join(case, "results", "sizeDistribution_psd.csv"),
                             delimiter=",", names=True, dtype=None, encoding=None)
        assert np.all(np.isnan(rows["exact"])) and np.all(rows["mean"][rows["column"] == "n0"] > 0)
        d = np.genfromtxt(os.path.join(case, "results", "psd", "sizeDistributionDiameter.csv"),
                          delimiter=",", names=True, dtype=None, encoding=None)
        # 1e-22..1e-18 kg at 1800 kg/m3: spheres of 4.7 to 102 nm
        assert np.all((d["d_nm"] > 4.7) & (d["d_nm"] < 102)) and np.all(np.isnan(d["exact"]))
    # a check of the bins against the exact distribution: bad input, no traceback
    rc, _ = _report(case, "--psd", "--no-plots", "--check-psd-bins", "1:5")
    assert rc == 2 and "no exact distribution" in capsys.readouterr().err


def test_psd_exact_of_log_bins(tmp_path):
    """Log bins in mass units hold the sums of n_k over their integer sizes; bins that hold
    no integer size (1.1 to 1.9) have no exact distribution."""
    _psd(str(tmp_path / "a"), np.geomspace(0.5, 64, 8), "log")
    p = psd.read(str(tmp_path / "a"), "psd")
    ex = psd.exact(p)
    n = analytic.duct_sizes("constant", p["centres"][:, 0], p["centres"][:, 0], 64, I, K0)
    e = p["edges"]
    k = np.arange(1, 65)
    for b in range(7):
        assert np.allclose(ex[:, b], n[:, (k >= e[b]) & (k < e[b + 1])].sum(axis=1), rtol=1e-9)
    _psd(str(tmp_path / "b"), np.geomspace(1.1, 1.9, 5), "log")
    assert psd.exact(psd.read(str(tmp_path / "b"), "psd")) is None


def test_psd_of_the_papers_duct_keeps_its_exact_curve(tmp_path, capsys):
    case = _samples(str(tmp_path), density=1000.0, massUnit=1e-24)
    _psd(case, np.arange(11) + 0.5, "integer", density=1000.0, mass_unit=1e-24)
    rc, _ = _report(case, "--psd", "--no-plots")
    assert rc == 0 and "no exact" not in capsys.readouterr().out
    rows = np.genfromtxt(os.path.join(case, "results", "sizeDistribution_psd.csv"),
                         delimiter=",", names=True, dtype=None, encoding=None)
    bins = np.char.startswith(rows["column"].astype(str), "n")
    assert np.all(rows["exact"][bins] > 0)
    # in kg (massUnit 1) the case is not the paper's: no exact curve, and why
    case = _samples(str(tmp_path / "kg"), density=1000.0, massUnit=1.0)
    _psd(case, np.arange(11) + 0.5, "integer", density=1000.0, mass_unit=1.0)
    rc, _ = _report(case, "--psd", "--no-plots")
    assert rc == 0 and "PSD psd: no exact distribution: the particles' masses are in kg" \
        in capsys.readouterr().out
