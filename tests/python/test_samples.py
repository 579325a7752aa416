# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.samples on synthetic HDF5 files in the solver's layout: processors
(disjoint cells, unsorted, one in a sub-folder), a restart overlapping in time whose
samples must win, the time window, realisations, and the bad-input errors."""

import os

import h5py
import numpy as np
import pytest

from coagulationPost import report, samples

X = np.array([0.5, 1.5, 2.5, 3.5])          # cell centres (x); y = z = 0.25
ATTRS = dict(n=256, V1=1e-3, K0=1e-5, inceptionRate=3e8, seed=7, splitDeltaT=1e-2,
             sampleInterval=0.1, tRelax=0.3, algorithm=np.bytes_(b"SWA"), kernel="constant")


def value(cells, times, nmom=4):
    """The true sample of cell c at time t, moment k: 100 (c + 1) + 10 t + k."""
    c = np.asarray(cells)[None, :, None]
    t = np.asarray(times)[:, None, None]
    return 100.0 * (c + 1) + 10.0 * t + np.arange(nmom)[None, None, :]


def write(path, cells, times, moments=None, nudge=0.0, **attrs):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    cells = np.asarray(cells)
    centres = np.stack([X[cells] * (1 + nudge), np.full(len(cells), 0.25), np.full(len(cells), 0.25)], 1)
    with h5py.File(path, "w") as f:
        f["cellCentres"] = centres
        f["time"] = np.asarray(times, float)
        f["moments"] = value(cells, times) if moments is None else moments
        for k, v in {**ATTRS, **attrs}.items():
            f.attrs[k] = v


def sample_dir(case):
    return os.path.join(str(case), samples.SAMPLE_DIR)


@pytest.fixture
def split_case(tmp_path):
    """proc0: cells 2, 0 at t = 0..1 (wrong from t = 0.6 on); processor1/proc1.h5:
    cells 1, 3 at t = 0..1; a_restart.h5: cells 0, 2 (reversed, centres off by 1e-15
    relative) at t = 0.6..1.5 from another rounding of the times."""
    d = sample_dir(tmp_path)
    t = np.arange(11) * 0.1
    bad = value([2, 0], t)
    bad[t >= 0.6 - 1e-9] = -999.0
    write(os.path.join(d, "proc0.h5"), [2, 0], t, moments=bad)
    write(os.path.join(d, "processor1", "proc1.h5"), [1, 3], t)
    tr = np.linspace(0.6, 1.5, 10)
    write(os.path.join(d, "a_restart.h5"), [0, 2], tr, nudge=1e-15)
    return str(tmp_path)


def merged(case, **kw):
    reader = samples.RunReader()
    ids, data, info = reader.read(case, **kw)
    order = np.argsort(np.array(reader.cells.centres)[ids, 0])
    return reader, data[:, order, :], info


def test_processors_and_restart_merged(split_case):
    reader, data, info = merged(split_case)
    assert len(reader.cells) == 4
    t = np.round(np.arange(3, 16) * 0.1, 10)                  # tRelax = 0.3 .. 1.5
    assert data.shape == (13, 4, 4)
    want = value([0, 1, 2, 3], t)
    want[np.ix_(t > 1.0 + 1e-9, [1, 3])] = np.nan
    np.testing.assert_allclose(data, want, rtol=1e-14)        # no -999: the restart won
    assert info["samplesPerCell"] == [8, 13]
    assert info["timeRange"] == [0.0, pytest.approx(1.5)]
    assert info["seeds"] == [7] and len(info["files"]) == 3
    assert reader.ref["algorithm"] == "SWA"                    # bytes attribute decoded


def test_time_window(split_case):
    _, data, info = merged(split_case, t_relax=0.95, t_end=1.2)
    assert data.shape[0] == 3                                  # 1.0, 1.1, 1.2
    assert info["tRelax"] == 0.95 and info["samplesPerCell"] == [1, 3]


def test_realisations_pooled(split_case, tmp_path, capsys):
    """A second realisation (one file, all cells, the same seed) pooled by report.compute:
    cells matched across realisations, counts added, the shared seed warned about."""
    other = tmp_path / "other"
    t = np.arange(11) * 0.1
    write(os.path.join(sample_dir(other), "s.h5"), [3, 1, 0, 2], t)
    res = report.compute([split_case, str(other)], analytic_kind="none")
    np.testing.assert_allclose(res["x"], X, rtol=1e-14)
    np.testing.assert_array_equal(res["count"][:, 0], [13 + 8, 8 + 8, 13 + 8, 8 + 8])
    allc0 = np.concatenate([value([0], np.arange(3, 16) * 0.1), value([0], np.arange(3, 11) * 0.1)])
    assert res["mean"][0, 2] == pytest.approx(allc0[:, 0, 2].mean(), rel=1e-13)
    assert res["sd"][0, 2] == pytest.approx(allc0[:, 0, 2].std(ddof=1), rel=1e-12)
    assert "seed 7 appears in both" in capsys.readouterr().err


def test_fewer_moments_in_a_later_realisation(split_case, tmp_path):
    other = tmp_path / "other"
    t = np.arange(11) * 0.1
    write(os.path.join(sample_dir(other), "s.h5"), [0], t, moments=value([0], t)[:, :, :2])
    reader = samples.RunReader()
    reader.read(split_case)
    with pytest.raises(samples.InputError, match="has 2 moments, earlier runs 4"):
        reader.read(str(other))


def test_bad_input(tmp_path, capsys):
    with pytest.raises(samples.InputError, match="no HDF5 sample file found"):
        samples.RunReader().read(str(tmp_path))
    d = sample_dir(tmp_path)
    t = np.arange(5) * 0.1
    write(os.path.join(d, "a.h5"), [0, 1], t)
    write(os.path.join(d, "b.h5"), [2, 3], t, n=512)
    with pytest.raises(samples.InputError, match="attribute 'n' differs"):
        samples.RunReader().read(str(tmp_path))
    write(os.path.join(d, "b.h5"), [2, 3], t, moments=np.zeros((5, 3, 4)))
    with pytest.raises(samples.InputError, match="/moments has shape"):
        samples.RunReader().read(str(tmp_path))
    with h5py.File(os.path.join(d, "b.h5"), "w") as f:
        f["time"] = t
    with pytest.raises(samples.InputError, match="lacks datasets /cellCentres, /moments"):
        samples.RunReader().read(str(tmp_path))
    write(os.path.join(d, "b.h5"), [2, 3], np.zeros(0), moments=np.zeros((0, 2, 4)))
    _, data, _ = samples.RunReader().read(str(tmp_path))
    assert data.shape[1] == 2
    assert "holds no sample; ignored" in capsys.readouterr().err


def test_realisation_dirs(tmp_path):
    for k in (10, 2, 0):
        os.makedirs(tmp_path / ("realisation_%d" % k))
    (tmp_path / "realisation_x.txt").write_text("not a folder")
    assert [os.path.basename(d) for d in samples.realisation_dirs(str(tmp_path))] == \
        ["realisation_0", "realisation_10", "realisation_2"]
    run = tmp_path / "run"
    os.makedirs(sample_dir(run))
    assert samples.realisation_dirs(str(run)) == [str(run)]
    with pytest.raises(samples.InputError, match="holds no realisation_"):
        samples.realisation_dirs(str(tmp_path / "realisation_0"))


def test_attr_value():
    assert samples.attr_value(b"SWA") == "SWA"
    assert samples.attr_value(np.array([b"DSA1"])) == "DSA1"
    assert samples.attr_value(np.array([3.5])) == 3.5
    assert samples.attr_value(np.array([1, 2])) == [1, 2]
    assert samples.attr_value(np.int64(4)) == 4 and isinstance(samples.attr_value(np.int64(4)), int)
    assert samples.same(1.0, 1.0 + 1e-14) and not samples.same(1.0, 1.0 + 1e-9)
    assert samples.same("SWA", "SWA") and not samples.same("SWA", "DSA1")


def test_cell_order_ignores_round_off_of_the_centres():
    # one column of a 2-D mesh at x = 0.335, its centres' x off by round-off as a decomposed
    # mesh's are: the rows sort by y, as the serial mesh's do (a serial and a
    # decomposed run of the sheared box had 20 rows in a different order)
    centres = [(0.335 + 2e-16, 0.095, 0.005), (0.335, 0.005, 0.005),
               (0.335 - 2e-16, 0.05, 0.005), (0.325, 0.095, 0.005), (0.345, 0.005, 0.005)]
    assert list(report.cell_order(centres)) == [3, 1, 2, 0, 4]
    # distinct x still sort first, and one cell or identical centres do not fail
    assert list(report.cell_order([(0.2, 0, 0), (0.1, 1, 0)])) == [1, 0]
    assert list(report.cell_order([(1.0, 2.0, 3.0)])) == [0]
    assert list(report.cell_order([(1.0, 2.0, 3.0)] * 2)) == [0, 1]


def test_function_object_without_its_library(tmp_path):
    """A flow solver whose controlDict names the coagulationCloud type but loads no
    coagulationModels ran without particles: the missing samples say why."""
    os.makedirs(os.path.join(tmp_path, "system"))
    control = os.path.join(tmp_path, "system", "controlDict")
    fo = "functions\n{\n    particles\n    {\n        type coagulationCloud;%s\n    }\n}\n"
    open(control, "w").write(fo % "  // libs (coagulationModels);")
    with pytest.raises(samples.InputError, match="no 'libs .coagulationModels.;'"):
        samples.RunReader().read(str(tmp_path))
    for libs in ("\n        libs (coagulationModels);", "\n        libs (\"libcoagulationModels.so\");"):
        open(control, "w").write(fo % libs)
        with pytest.raises(samples.InputError) as e:
            samples.RunReader().read(str(tmp_path))
        assert "libs" not in str(e.value)
    # the library loaded for the whole case
    open(control, "w").write("libs (coagulationModels);\n" + fo % "")
    with pytest.raises(samples.InputError) as e:
        samples.RunReader().read(str(tmp_path))
    assert "libs" not in str(e.value)
