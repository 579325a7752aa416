# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""No development-history notes in the documentation and the sources.

What the code does belongs in its comments and the README; which issue asked for it, or in
which numbered work session it was written, belongs in the git history. This test greps
README.md, CHANGELOG.md, doc/*.md, every source file under src/, applications/, etc/ and
tests/ (C, H, cpp, hpp, c, h, py, sh, txt, the Allrun-type scripts and other scripts without an
extension that start with #!; the planted-bug campaigns' record in tests/regression/plantedBugs
and this file excepted) and every file of the tutorials (scripts and OpenFOAM dictionaries)
for

  - "issue N", "issue #N", "issues N" (any case);
  - "session" used as a numbered work period: "ninth session", "3rd session", "session 3",
    "session #3";

and fails listing every file:line that has one.

Run: /usr/bin/python3 -m pytest -q tests/python/test_noIssueNumbers.py (CTest: python_unit)
"""
import os
import re

import pytest

ROOT = os.path.realpath(os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", ".."))
SOURCE_DIRS = ("src", "applications", "etc", "tests", "tutorials")
SOURCE_EXTENSIONS = (".C", ".H", ".c", ".h", ".cpp", ".hpp", ".py", ".sh", ".txt")
SKIP_DIRS = {"__pycache__", ".git", "build", "lnInclude", "Make", "plantedBugs", "platforms"}
SKIP_FILES = {"tests/python/test_noIssueNumbers.py"}
TOP_FILES = ("README.md", "CHANGELOG.md", "Allrun", "Alltest", "Allwmake", "Allwclean",
             "CMakeLists.txt")
SOURCE_PREFIXES = tuple(d + "/" for d in SOURCE_DIRS)

ORDINALS = ("first|second|third|fourth|fifth|sixth|seventh|eighth|ninth|tenth|eleventh|twelfth|"
            "thirteenth|fourteenth|fifteenth|sixteenth|seventeenth|eighteenth|nineteenth|"
            "twentieth|twenty-\\w+|thirtieth|\\d+(?:st|nd|rd|th)")
# Between two words: blanks, or at most one line break followed by a comment's leader
# (// # *), so that a note wrapped in a comment ("issue 19, fifth\n    //  session") is found
SEP = r"(?:[ \t]+(?:\n[ \t]*(?:(?:/{2,}|#+|\*+)[ \t]*)?)?|\n[ \t]*(?:(?:/{2,}|#+|\*+)[ \t]*)?)"
PATTERNS = [
    re.compile(r"\bissues?(?:" + SEP + r"|-)?(?:#[ \t]*)?\d+", re.I),
    re.compile(r"\b(?:" + ORDINALS + r")" + SEP + r"sessions?\b", re.I),
    re.compile(r"\bsessions?(?:" + SEP + r")?(?:#[ \t]*)?\d+", re.I),
]


def is_script(path):
    """A file without an extension that starts with #! (Allrun, coagulationEnsemble, ...)."""
    name = os.path.basename(path)
    if "." in name:
        return False
    try:
        with open(path, "rb") as f:
            return f.read(2) == b"#!"
    except OSError:
        return False


def checked_files(root=ROOT):
    """The top-level documents and scripts, doc/*.md and the files of SOURCE_DIRS (relative
    paths)."""
    files = [n for n in TOP_FILES if os.path.isfile(os.path.join(root, n))]
    doc = os.path.join(root, "doc")
    if os.path.isdir(doc):
        files += ["doc/" + n for n in sorted(os.listdir(doc)) if n.endswith(".md")]
    for d in SOURCE_DIRS:
        for dirpath, dirnames, names in os.walk(os.path.join(root, d)):
            dirnames[:] = sorted(n for n in dirnames if n not in SKIP_DIRS)
            for name in sorted(names):
                full = os.path.join(dirpath, name)
                rel = os.path.relpath(full, root).replace(os.sep, "/")
                if rel in SKIP_FILES:
                    continue
                if (name.endswith(SOURCE_EXTENSIONS) or name.startswith("All") or is_script(full)
                        or (d == "tutorials" and not name.endswith((".png", ".h5", ".gz")))):
                    files.append(rel)
    return files


def history_notes(text):
    """[(offset, note)] of the development-history notes in a text."""
    return sorted((m.start(), m.group(0)) for p in PATTERNS for m in p.finditer(text))


def hits(files, root=ROOT):
    """['file:line: text'] of every line where a history note starts."""
    out = []
    for rel in files:
        with open(os.path.join(root, rel), encoding="utf-8", errors="replace") as f:
            text = f.read()
        lines = text.split("\n")
        seen = set()
        for offset, _ in history_notes(text):
            n = text.count("\n", 0, offset)
            if n not in seen:
                seen.add(n)
                out.append("%s:%d: %s" % (rel, n + 1, lines[n].strip()))
    return out


@pytest.mark.parametrize("text, found", [
    ("(issue 19: on the additive duct", True),
    ("see Issue #7 for the report", True),
    ("## Kolmogorov pseudo-turbulence (issues 17", True),
    ("Issue 19, fifth session: on the additive duct", True),
    ("measured in the ninth session", True),
    ("the 3rd session's runs", True),
    ("session 3 measured it", True),
    ("the solver has no issue with empty patches", False),
    ("an MPI session of its own", False),
    ("this sessions' code", False),
    ("Sessions end when the machine is given back", False),
    ("on the issue-19 machine", True),
    ("Mersenne twister per cell (issue19)", True),
    ("(coag::CostFit). Issue 19, fifth\n    session: on the additive duct", True),
    ("//  with xoshiro256++ (the third\n        //  session) the box's cell step", True),
    ("# measured in the\n# session 4 runs", True),
    ("the end of a session): finished realisations", False),
    ("a new session\n\n3. the next step", False),
    ("the prefetches cost issue slots", False),
])
def test_pattern(text, found):
    """The patterns catch the notes and leave ordinary words alone."""
    assert bool(history_notes(text)) == found


def test_files_found():
    files = checked_files()
    assert "README.md" in files
    assert any(f.startswith("src/") and f.endswith(".H") for f in files)
    assert any(f.startswith("applications/") and f.endswith(".py") for f in files)
    assert len(files) > 50, "too few files found: %d" % len(files)


def test_no_history_notes_in_sources():
    """src/, applications/, etc/, tests/ and tutorials/."""
    found = hits([f for f in checked_files() if f.startswith(SOURCE_PREFIXES)])
    assert not found, "%d development-history notes (issue or session numbers):\n" % len(found) \
        + "\n".join(found)


def test_no_history_notes_in_documentation():
    """README.md, CHANGELOG.md, the top-level scripts and doc/*.md."""
    found = hits([f for f in checked_files() if not f.startswith(SOURCE_PREFIXES)])
    assert not found, "%d development-history notes (issue or session numbers):\n" % len(found) \
        + "\n".join(found)
