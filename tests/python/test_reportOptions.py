# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationReport.py's options: --slice and --line, their forms and their refusals, and the
refusal of numbers that make no sense (a density, a mass unit or a speed that is not positive
and finite, a tolerance below zero, NaN anywhere): exit 2 with argparse's one-line message
naming the option, the value and what is expected."""
import importlib.util
import os

import pytest

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "applications", "utilities",
                      "coagulationReport", "coagulationReport.py")


def _cli():
    spec = importlib.util.spec_from_file_location("coagulationReportCli", SCRIPT)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_slices_and_lines_in_every_form():
    cli = _cli()
    a = cli.parse_args(["--slice", "z=0.025", "--slice", "x=-1e-3",
                        "--line", "(0 0.1 -2)", "(1 0.1 -2)",
                        "--line", "-0.1,0,0", "-0.2,1e-3,-3",
                        "--lin", "-1,0,0", "1,0,0"])
    assert a.slices == [(2, 0.025), (0, -1e-3)]
    assert a.lines == [([0, 0.1, -2], [1, 0.1, -2]), ([-0.1, 0, 0], [-0.2, 1e-3, -3]),
                       ([-1, 0, 0], [1, 0, 0])]


@pytest.mark.parametrize("argv, message", [
    (["--slice", "w=1"], "AXIS=VALUE"),
    (["--slice", "z=abc"], "not a number"),
    (["--slice", "z=0.5", "--slice", "z=5e-1"], "a plane given twice"),
    (["--line", "(0 0)", "(1 0 0)"], "three numbers"),
    (["--line", "0,0,0", "0,0,0"], "the two points are the same"),
    (["--no-plots", "--slice", "z=0"], "not with --no-plots"),
])
def test_refused(argv, message, capsys):
    with pytest.raises(SystemExit) as e:
        _cli().parse_args(argv)
    assert e.value.code == 2
    assert message in capsys.readouterr().err


@pytest.mark.parametrize("argv, message", [
    (["--density", "-5"], "argument --density: -5 is not a positive finite density in kg/m3"),
    (["--density", "nan"], "argument --density: nan is not a positive finite density in kg/m3"),
    (["--density", "0"], "argument --density: 0 is not a positive finite density in kg/m3"),
    (["--density", "inf"], "argument --density: inf is not a positive finite density"),
    (["--density", "abc"], "argument --density: abc is not a positive finite density"),
    (["--mass-unit", "-1"], "argument --mass-unit: -1 is not a positive finite mass unit in kg"),
    (["--mass-unit", "0"], "argument --mass-unit: 0 is not a positive finite mass unit in kg"),
    (["--u", "-1"], "argument --u: -1 is not a positive finite speed"),
    (["--u", "0"], "argument --u: 0 is not a positive finite speed"),
    (["--t-relax", "nan"], "argument --t-relax: nan is not a finite time"),
    (["--t-end", "inf"], "argument --t-end: inf is not a finite time"),
    (["--x-inlet", "nan"], "argument --x-inlet: nan is not a finite position"),
    (["--correlation-time", "-1"], "argument --correlation-time: -1 is not a finite time >= 0"),
    (["--check-rel-tol", "nan"], "argument --check-rel-tol: nan is not a positive finite"),
    (["--check-rel-tol", "0"], "argument --check-rel-tol: 0 is not a positive finite"),
    (["--check-sigma", "-2"], "argument --check-sigma: -2 is not a positive finite"),
    (["--check-skip-cells", "-1"], "argument --check-skip-cells: -1 is not a whole number >= 0"),
    (["--check-moments", "0,x"], "argument --check-moments: 0,x is not a comma-separated list"),
    (["--check-moments", "1,-1"], "argument --check-moments: 1,-1 is not a comma-separated list"),
    (["--check-moment", "-1"], "argument --check-moment: -1 is not a whole number >= 0"),
    (["--check-value", "nan"], "argument --check-value: nan is not a finite number"),
    (["--check-value-rel-tol", "-0.1"], "argument --check-value-rel-tol: -0.1 is not a positive"),
    (["--check-psd-bins", "3"], "argument --check-psd-bins: 3 is not A:B"),
    (["--check-psd-bins", "0:5"], "argument --check-psd-bins: 0:5 is not A:B"),
    (["--check-psd-bins", "5:3"], "argument --check-psd-bins: 5:3 is not A:B"),
    (["--slice", "z=nan"], "not a finite number"),
    (["--line", "(0 nan 0)", "(1 0 0)"], "each finite"),
])
def test_numbers_that_make_no_sense_are_refused(argv, message, capsys):
    with pytest.raises(SystemExit) as e:
        _cli().parse_args(argv)
    assert e.value.code == 2
    err = capsys.readouterr().err
    assert message in err
    # argparse's usage and then its one line: "coagulationReport.py: error: ..."
    assert err.strip().splitlines()[-1].startswith("coagulationReport.py: error: ")


def test_sensible_numbers_are_taken_as_given():
    a = _cli().parse_args(["--density", "1800", "--mass-unit", "9.42e-22", "--u", "0.5",
                           "--t-relax", "-1", "--correlation-time", "0", "--check-sigma", "4",
                           "--check-psd-bins", "2:30", "--check-moments", "0,3"])
    assert (a.density, a.mass_unit, a.u, a.t_relax) == (1800.0, 9.42e-22, 0.5, -1.0)
    assert a.correlation_time == 0.0 and a.check_sigma == 4.0
    assert a.check_psd_bins == (2, 30) and a.check_moments == [0, 3]


def test_the_options_material_wins_over_the_cases():
    cli = _cli()
    res = {"meta": {"density": 1000.0, "massUnit": 1e-24}}
    assert cli.material(cli.parse_args(["--density", "1800"]), res) == (1800.0, 1e-24)
    assert cli.material(cli.parse_args(["--mass-unit", "2e-24"]), res) == (1000.0, 2e-24)
    assert cli.material(cli.parse_args([]), {"meta": {"density": None, "massUnit": None}}) is None


@pytest.mark.parametrize("given, kind", [("constant", "constantDuct"),
                                         ("additiveDuct", "additiveDuct"), ("none", "none")])
def test_analytic_takes_the_kernels_name(given, kind):
    assert _cli().parse_args(["--analytic", given]).analytic == kind
