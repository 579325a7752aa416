# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""The package as a whole: every module exported and documented, imported on first use,
runnable with python3 -m where it has a main, the console scripts of pyproject.toml, and no
sys.path edits left in the project (the package comes from PYTHONPATH or pip install)."""

import glob
import importlib
import os
import subprocess
import sys

import pytest

import coagulationPost

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PKG = os.path.dirname(os.path.abspath(coagulationPost.__file__))
MAINS = {"lagrangianStudy": 1, "coagulationDiffusionFigures": 2, "coagulationDiffusionColumn": 2,
         "pseudoTurbulencePuff": 2, "splittingStudy": 2, "hotReactor": 2,
         "squareCylinder": 2}   # their usage exit status


def modules():
    return sorted(os.path.basename(p)[:-3] for p in glob.glob(os.path.join(PKG, "*.py"))
                  if not p.endswith("__init__.py"))


def test_every_module_is_exported_and_listed():
    assert sorted(coagulationPost.__all__) == modules()
    listed = [l.split()[0] for l in coagulationPost.__doc__.splitlines()
              if l.startswith("  ") and not l.startswith("   ")]
    assert sorted(listed) == modules()


@pytest.mark.parametrize("name", modules())
def test_submodule_is_an_attribute(name):
    assert getattr(coagulationPost, name) is importlib.import_module("coagulationPost." + name)


def test_unknown_attribute():
    with pytest.raises(AttributeError):
        coagulationPost.nonexistent


def run(*args):
    return subprocess.run([sys.executable, *args], capture_output=True, text=True, cwd="/",
                          env=dict(os.environ, PYTHONPATH=os.path.dirname(PKG)))


def test_the_package_import_is_light():
    r = run("-c", "import sys, coagulationPost; "
                  "print(sorted(m for m in sys.modules if m.startswith('coagulationPost.')))")
    assert r.returncode == 0 and r.stdout.strip() == "[]"


@pytest.mark.parametrize("name", sorted(MAINS))
def test_runs_as_a_module(name):
    r = run("-m", "coagulationPost." + name)
    assert r.returncode == MAINS[name]
    assert "python3 -m coagulationPost." + name in r.stdout + r.stderr


def test_console_scripts_name_the_mains():
    tomllib = pytest.importorskip("tomllib")
    with open(os.path.join(os.path.dirname(PKG), "pyproject.toml"), "rb") as f:
        project = tomllib.load(f)["project"]
    assert project["name"] == "coagulationPost"
    assert sorted(project["dependencies"]) == ["h5py", "matplotlib", "numpy", "scipy"]
    targets = sorted(project["scripts"].values())
    assert targets == sorted("coagulationPost.%s:main" % m for m in MAINS)
    for t in targets:
        module, func = t.split(":")
        assert callable(getattr(importlib.import_module(module), func))


def test_no_sys_path_edits_in_the_project():
    files = [p for pat in ("applications/utilities/*/*.py", "src/python/**/*.py", "tests/**/*.py",
                           "tests/**/*.sh", "tutorials/*/Allrun")
             for p in glob.glob(os.path.join(ROOT, pat), recursive=True)]
    assert files
    bad = [os.path.relpath(p, ROOT) for p in files
           if p != os.path.abspath(__file__) and "sys.path.insert" in open(p, errors="replace").read()]
    assert bad == []
