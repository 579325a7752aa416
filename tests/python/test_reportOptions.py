# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationReport.py's options for the pictures: --slice and --line, their forms and
their refusals (exit 2 with a message)."""
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
