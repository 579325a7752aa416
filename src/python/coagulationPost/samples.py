# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Reading the HDF5 moment samples written by coagulationFoam.

    <case>/postProcessing/coagulationSamples/*.h5   (also in sub-folders)

each holding /cellCentres [nCells][3], /time [nSamples],
/moments [nSamples][nCells][nMoments] (M_{n,k} of Patterson & Wagner eq. 37)
and the root attributes n, V1, K0, inceptionRate, seed, splitDeltaT,
sampleInterval, tRelax, particleWeight, algorithm, kernel, with the case's
'particles' density and massUnit, and the growth totals of GROWTH_TOTALS
(each file's since its run started, 0 without growth).

Files of one run hold disjoint cell sets (processors) and/or different time
ranges (restarts).  Cells are merged by centre; where several files hold the
same cell at the same time, the sample of the file whose first time is latest
wins (a restart overrides what the run it restarted from wrote after the
restart time).

An ensemble (what coagulationEnsemble -out writes) is a folder of realisation_*
runs; realisation_dirs lists them.
"""

import glob
import os
import re
import sys

import numpy as np

SAMPLE_DIR = os.path.join("postProcessing", "coagulationSamples")
DATASETS = ("cellCentres", "time", "moments")
# attributes that must agree between all files that are pooled
MUST_AGREE = ("n", "V1", "K0", "inceptionRate", "algorithm", "kernel")
# what growth added to sum(w m) (negative: took), and the computational particles, their
# number and mass that shrinking removed
GROWTH_TOTALS = ("grownMass", "lostParticles", "lostNumber", "lostMass")


class InputError(Exception):
    """Bad input (missing or inconsistent files, bad options): the command lines
    report it on stderr and exit with status 2."""


def warn(msg):
    """'<program>: warning: msg' on stderr, <program> the running command's name."""
    prog = os.path.splitext(os.path.basename(sys.argv[0] if sys.argv else ""))[0]
    if prog in ("", "-c", "__main__"):
        prog = "coagulationPost"
    print("%s: warning: %s" % (prog, msg), file=sys.stderr)


def attr_value(v):
    """h5py attribute -> python scalar/str."""
    if isinstance(v, bytes):
        return v.decode("utf-8", "replace")
    if isinstance(v, np.ndarray):
        if v.dtype.kind in "SO" or v.dtype.kind == "U":
            v = v.ravel()
            return attr_value(v[0]) if v.size else ""
        if v.size == 1:
            return v.ravel()[0].item()
        return v.tolist()
    if isinstance(v, np.generic):
        return v.item()
    return v


def same(a, b):
    """Attribute equality: numbers to 1e-12 relative, anything else as text."""
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return a == b or abs(a - b) <= 1e-12 * max(abs(a), abs(b))
    return str(a) == str(b)


def largest_totals(attr_sets):
    """Of each of GROWTH_TOTALS, the number of largest magnitude over the attribute sets
    (files, runs), so that growth or shrinking booked in any of them shows."""
    out = {}
    for attrs in attr_sets:
        for key in GROWTH_TOTALS:
            v = attrs.get(key)
            if isinstance(v, (int, float, np.integer, np.floating)) and not (
                    key in out and abs(v) <= abs(out[key])):
                out[key] = float(v)
    return out


def find_sample_files(case):
    if not os.path.isdir(case):
        raise InputError("no such case: %s is not a folder" % case)
    d = os.path.join(case, SAMPLE_DIR)
    files = sorted(set(glob.glob(os.path.join(d, "*.h5"))
                       + glob.glob(os.path.join(d, "**", "*.h5"), recursive=True)))
    if not files:
        why = unloaded_function_object(case)
        raise InputError("no HDF5 sample file found: %s/*.h5 does not exist or is empty%s"
                         % (d, "; " + why if why else ""))
    return files


def unloaded_function_object(case):
    """Why a flow solver ran a case's coagulationCloud function object without particles, or
    None: its system/controlDict names the type but loads no library coagulationModels (in a
    'libs' entry of the function object or of the controlDict), so OpenFOAM only warned
    'Unknown function type coagulationCloud' and ran the flow alone."""
    try:
        text = open(os.path.join(case, "system", "controlDict")).read()
    except OSError:
        return None
    text = re.sub(r"//[^\n]*|/\*.*?\*/", "", text, flags=re.S)
    if not re.search(r"\btype\s+coagulationCloud\s*;", text):
        return None
    if any("coagulationModels" in libs
           for libs in re.findall(r"\b(?:libs|functionObjectLibs)\s*\(([^)]*)\)", text)):
        return None
    return ("system/controlDict has a coagulationCloud function object but no "
            "'libs (coagulationModels);': OpenFOAM ran the flow without it (its log says "
            "'Unknown function type coagulationCloud'). Add the entry to the function object")


def read_sample_file(path):
    """One sample file: dict path, attrs, centres [nCells][3], times, moments."""
    import h5py
    try:
        f = h5py.File(path, "r")
    except (OSError, IOError) as e:
        raise InputError("cannot open %s as HDF5: %s" % (path, e))
    with f:
        missing = [d for d in DATASETS if d not in f]
        if missing:
            raise InputError("%s lacks dataset%s %s" % (
                path, "s" if len(missing) > 1 else "", ", ".join("/" + m for m in missing)))
        attrs = {k: attr_value(v) for k, v in f.attrs.items()}
        centres = np.asarray(f["cellCentres"][()], dtype=float)
        times = np.asarray(f["time"][()], dtype=float).ravel()
        moments = np.asarray(f["moments"][()], dtype=float)
    if centres.ndim == 1:
        centres = centres.reshape(-1, 1)
    if centres.ndim != 2:
        raise InputError("%s: /cellCentres has shape %s, expected [nCells][3]"
                         % (path, centres.shape))
    if centres.shape[1] < 3:
        centres = np.hstack([centres, np.zeros((centres.shape[0], 3 - centres.shape[1]))])
    nc = centres.shape[0]
    if moments.ndim == 2 and nc == 1:
        moments = moments[:, None, :]
    if moments.ndim != 3 or moments.shape[0] != times.size or moments.shape[1] != nc:
        raise InputError("%s: /moments has shape %s, expected [nSamples=%d][nCells=%d][nMoments]"
                         % (path, moments.shape, times.size, nc))
    return {"path": path, "attrs": attrs, "centres": centres[:, :3], "times": times,
            "moments": moments}


def check_consistent(files, ref_attrs, ref_path):
    for fd in files:
        for key in MUST_AGREE:
            if key in ref_attrs and key in fd["attrs"] and not same(ref_attrs[key], fd["attrs"][key]):
                raise InputError("attribute '%s' differs: %r in %s but %r in %s"
                                 % (key, ref_attrs[key], ref_path, fd["attrs"][key], fd["path"]))


def realisation_dirs(row_dir):
    """The realisation_* runs of an ensemble folder, or the folder itself when it is a run."""
    dirs = sorted(d for d in glob.glob(os.path.join(row_dir, "realisation_*")) if os.path.isdir(d))
    if not dirs and os.path.isdir(os.path.join(row_dir, SAMPLE_DIR)):
        dirs = [row_dir]  # a single run given directly
    if not dirs:
        raise InputError("%s holds no realisation_* folder and no %s" % (row_dir, SAMPLE_DIR))
    return dirs


class CellIndex:
    """Cells identified by their centres rounded to a quantum: the same cell in
    several files (processors, restarts, realisations) gets one id, in order of
    first appearance."""

    def __init__(self, cell_quantum):
        self.cq = cell_quantum
        self.index = {}
        self.centres = []

    def __len__(self):
        return len(self.centres)

    def ids(self, centres):
        q = np.round(centres / self.cq).astype(np.int64)
        ids = np.empty(len(centres), dtype=np.int64)
        for i, k in enumerate(tuple(r) for r in q):
            j = self.index.get(k)
            if j is None:
                j = len(self.centres)
                self.index[k] = j
                self.centres.append(centres[i])
            ids[i] = j
        return ids


class RunReader:
    """Reads runs (case directories) one after another onto one set of cells.

    The first file read fixes the reference attributes (which all later files must
    share, MUST_AGREE), the cell quantum (1e-9 of the first run's extent) and the
    number of moments."""

    def __init__(self):
        self.ref = {}
        self.cells = None
        self.nmom = None

    def read(self, case, t_relax=None, t_end=None):
        """Merge one run's files and keep the samples with t_relax <= t <= t_end.

        t_relax None: the files' tRelax attribute; t_end None: no upper limit.
        Returns (ids, data, info): the run's cell ids (CellIndex), its samples
        data [nTimes][len(ids)][nMoments] with NaN where a cell has no sample at
        a time, and a dict describing the run (files, seeds, window, counts)."""
        paths = find_sample_files(case)
        files = [read_sample_file(p) for p in paths]
        for fd in files:
            if fd["times"].size == 0:
                warn("%s holds no sample; ignored" % fd["path"])
        files = [fd for fd in files if fd["times"].size > 0]
        if not files:
            raise InputError("no sample in the HDF5 files of %s" % case)
        ref = self.ref
        if not ref:
            ref.update(files[0]["attrs"])
            ref["_path"] = files[0]["path"]
        check_consistent(files, ref, ref["_path"])

        nmom = min(fd["moments"].shape[2] for fd in files)
        if any(fd["moments"].shape[2] != nmom for fd in files):
            warn("files of %s differ in nMoments; using the first %d" % (case, nmom))

        if self.cells is None:
            allc = np.vstack([fd["centres"] for fd in files])
            scale = max(float(np.ptp(allc, axis=0).max()) if allc.size else 0.0,
                        float(np.abs(allc).max()) if allc.size else 0.0, 1e-30)
            self.cells = CellIndex(1e-9 * scale)
            self.nmom = nmom
        if nmom < self.nmom:
            raise InputError("%s has %d moments, earlier runs %d" % (case, nmom, self.nmom))

        # time window
        attrs = files[0]["attrs"]
        if t_relax is None:
            t_relax = float(attrs.get("tRelax", 0.0) or 0.0)
            for fd in files:
                tr = fd["attrs"].get("tRelax")
                if tr is not None and not same(float(tr), t_relax):
                    warn("tRelax differs between files (%g in %s); using %g"
                         % (tr, fd["path"], t_relax))
                    break
        dt_s = float(attrs.get("sampleInterval", 0.0) or 0.0)
        tmax = max(float(np.abs(fd["times"]).max()) for fd in files)
        tq = dt_s * 1e-6 if dt_s > 0 else 1e-12 * max(1.0, tmax)
        eps = 0.5 * tq
        lo = t_relax - eps
        hi = (t_end + eps) if t_end is not None else np.inf

        # union of cells and of in-window times of this run
        ids_per_file = [self.cells.ids(fd["centres"]) for fd in files]
        run_cells = np.unique(np.concatenate(ids_per_file))
        col_of = {int(c): i for i, c in enumerate(run_cells)}
        tkeys_per_file, inwin_per_file = [], []
        for fd in files:
            w = (fd["times"] >= lo) & (fd["times"] <= hi)
            inwin_per_file.append(w)
            tkeys_per_file.append(np.round(fd["times"][w] / tq).astype(np.int64))
        all_keys = np.unique(np.concatenate(tkeys_per_file))
        if all_keys.size == 0:
            t_all = np.concatenate([fd["times"] for fd in files])
            raise InputError(
                "no sample of %s lies in the averaging window: the samples run from t = %g to "
                "%g, the window starts at tRelax = %g%s. The run ended before tRelax: run it "
                "longer, or set an earlier start (--t-relax)"
                % (case, t_all.min(), t_all.max(), t_relax,
                   "" if t_end is None else " and ends at %g" % t_end))
        data = np.full((all_keys.size, run_cells.size, self.nmom), np.nan)
        # restarts: files with a later first time overwrite earlier ones
        order = sorted(range(len(files)), key=lambda i: (float(files[i]["times"][0]), files[i]["path"]))
        for i in order:
            fd = files[i]
            if tkeys_per_file[i].size == 0:
                continue
            rows = np.searchsorted(all_keys, tkeys_per_file[i])
            cols = np.array([col_of[int(c)] for c in ids_per_file[i]], dtype=np.int64)
            data[np.ix_(rows, cols)] = fd["moments"][inwin_per_file[i]][:, :, :self.nmom]

        nvalid = (~np.isnan(data[:, :, 0])).sum(axis=0) if data.size else np.zeros(0)
        seeds = sorted({fd["attrs"].get("seed") for fd in files if fd["attrs"].get("seed") is not None},
                       key=str)
        t_all = np.concatenate([fd["times"] for fd in files])
        # the growth totals of the files, each processor's and run start's own
        growth = largest_totals(fd["attrs"] for fd in files)
        info = {
            "case": case,
            "files": [fd["path"] for fd in files],
            "seeds": seeds,
            "tRelax": t_relax,
            "tEnd": t_end,
            "timeRange": [float(t_all.min()), float(t_all.max())],
            "nCells": int(run_cells.size),
            "samplesPerCell": [int(nvalid.min()) if nvalid.size else 0,
                               int(nvalid.max()) if nvalid.size else 0],
            "growthTotals": growth,
        }
        return run_cells, data, info
