# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost: post-processing of coagulationFoam's HDF5 moment samples.

The command lines applications/utilities/coagulationReport/coagulationReport.py and
applications/utilities/coagulationTables/coagulationTables.py are thin layers over it.

Modules (each imports only what it needs; ``analytic`` and ``statistics`` need numpy and
scipy, ``samples`` h5py, ``plots`` matplotlib):

  samples     reading the solver's sample files: processors and restarts merged by cell
              centre and time, realisations of an ensemble, the time window
  statistics  mean, sd, 95 % confidence half-widths; the pooling of groups of samples
              (Chan et al.'s parallel update, written once); Student t; standard errors
  analytic    Patterson & Wagner's duct references: eqs (39)-(45), (47), (50), the moment
              ODEs (38)-(44) and those of the additive kernel, cell averages
  report      per-cell statistics of one case or of pooled realisations against the
              analytic reference, and their CSV, JSON and text table (coagulationReport)
  tables      rows of the paper's Tables 1 and 2 pooled over realisations, their CSV and
              markdown (coagulationTables)
  plots       the PNG figures of both tools (matplotlib, Agg)
  checks      the acceptance checks of both tools

Tests: python3 -m pytest tests/python
"""
