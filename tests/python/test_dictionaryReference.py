# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""doc/dictionaryReference.md against the C++ sources: the reference cannot drift from the code.

The sources declare what a dictionary accepts in one way: a keyword check, a function that
refuses every entry of a dictionary whose keyword is not in a list (found here as any function
whose body tests `<list>.found(<entry>.keyword())`: caseChecks::keywords and workDecomposition's
checkKeywords). Every call of a checker is a *site*; its list is read from the call:

    caseChecks::keywords(dict, {"type", "K0"});                  a braced list
    checkKeywords(coeffs, wordList({"n", "field"}));              a wordList of one
    wordList valid{"T", "mu"}; valid.append(otherKeys);           a list built in the function,
    if (rateEntry) valid.append("rate"); ...keywords(dict, valid)   from its parameters

A list built from the function's parameters (inceptionModel's constructor, readBrownianGas) makes
that function a template: each call of it elsewhere (a derived constructor's initialiser, a
model's member initialiser) is a site, its list the template's with the call's arguments (and
the declaration's defaults) put in.

Dictionaries that nothing checks but a utility reads (system/pseudoTurbulenceDict, the entries of
decomposeParDict that workDecomposition reads, constant/transportProperties' nu) are read sites:
every key of `<var>.get/getOrDefault/lookup/lookupOrDefault/found/subDict/isDict("key")`. The
optimisation, debug and info switches registered by name (`debug::optimisationSwitch("name",
...)`) are a site of their own.

The reference (doc/dictionaryReference.md) gives each dictionary a section: a heading whose
first code span is the dictionary's path and, for a dictionary whose 'type' selects a model,
a code span `type <model>` (or `type <a> | <b>` for models that take the same entries), e.g.

    ### `kernel`: `type localSaffmanTurner`
    ### `cloudFunctions/<name>/bins`: `type integer`

followed by a table whose header starts with `Property` and whose first column holds each entry
as `` `keyword` `` (`` `<...>` `` for a name the user chooses). SECTIONS below says which site
fills which section. The tests:

  - every site is mapped to sections, every mapping is found in the sources (the map is
    current), and the parser found keywords at all (it cannot pass vacuously);
  - every keyword a site accepts is in its sections' tables (the reference is complete);
  - every keyword a section documents is accepted by a site of that section, and every section
    with a table is one the sources know (the reference invents nothing);
  - every run-time selectable model type a user can name has a section;
  - the Usage tables of the model headers list exactly the keywords of their sections.

Run: /usr/bin/python3 -m pytest -q tests/python/test_dictionaryReference.py (CTest: python_unit)
"""
import os
import re
from collections import defaultdict

import pytest

ROOT = os.path.realpath(os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", ".."))
REFERENCE = os.path.join(ROOT, "doc", "dictionaryReference.md")
SOURCE_DIRS = ("src/coagulationModels", "applications")
SOURCE_EXTENSIONS = (".C", ".H")

MODELS = "src/coagulationModels/"

# (file, the site's enclosing function, its ordinal among that function's sites) -> sections
# A section is (path, model): path the dictionary's place in its file, model the value of its
# 'type' entry where that selects the model (None otherwise). CORE_KERNELS stands for the
# kernels registered by makeCoreCoagulationKernel (coreKernels.C), read from the sources.
CORE_KERNELS = "CORE_KERNELS"
SECTIONS = {
    (MODELS + "clouds/coagulationCloud/coagulationCloud.C", "coagulationCloud", 0):
        [("coagulationProperties", None)],
    (MODELS + "clouds/coagulationCloud/coagulationCloud.C", "readNumberControl", 0):
        [("numberControl", None)],
    (MODELS + "clouds/statisticalScaling/statisticalScaling.C", "statisticalScaling", 0):
        [("statisticalWeight", None)],
    (MODELS + "clouds/statisticalScaling/statisticalScaling.C", "statisticalScaling", 1):
        [("statisticalWeight/V1", None)],
    (MODELS + "submodels/injectionModels/initialPopulation/initialPopulation.C", "initialPopulation", 0):
        [("initialPopulation", None)],
    (MODELS + "submodels/coagulationKernels/coagulationKernel/coagulationKernel.C",
     "coagulationKernel", 0):
        CORE_KERNELS,
    (MODELS + "submodels/coagulationKernels/localSaffmanTurner/localSaffmanTurner.C",
     "readCoefficient", 0):
        [("kernel", "localSaffmanTurner")],
    (MODELS + "submodels/coagulationKernels/noCoagulation/noCoagulation.C", "noCoagulation", 0):
        [("kernel", "none")],
    (MODELS + "submodels/coagulationKernels/Brownian/Brownian.C", "readRegime", 0):
        [("kernel", "Brownian")],
    (MODELS + "submodels/coagulationKernels/gravitationalSettling/gravitationalSettling.C",
     "readLayout", 0):
        [("kernel", "gravitationalSettling")],
    (MODELS + "submodels/coagulationKernels/sum/sum.C", "readParts", 0):
        [("kernel", "sum")],
    (MODELS + "clouds/particleMaterial/particleMaterial.C", "readParticleMaterial", 0):
        [("particles", None)],
    (MODELS + "submodels/inceptionModels/uniformInception/uniformInception.C", "uniform", 0):
        [("inception", "uniform")],
    (MODELS + "submodels/inceptionModels/cellZoneInception/cellZoneInception.C", "cellZone", 0):
        [("inception", "cellZone")],
    (MODELS + "submodels/inceptionModels/fieldInception/fieldInception.C", "field", 0):
        [("inception", "field")],
    (MODELS + "submodels/injectionModels/patchInflow/patchInflow.C", "patchInflow", 0):
        [("inflow", "patchInflow")],
    (MODELS + "submodels/transportModels/frozenFlow/frozenFlow.C", "frozenFlow", 0):
        [("transport", "frozenFlow")],
    (MODELS + "submodels/transportModels/frozenFlow/frozenFlow.C", "frozenFlow", 1):
        [("transport/interpolationSchemes", None)],
    (MODELS + "submodels/dispersionModels/noDispersion/noDispersion.C", "noDispersion", 0):
        [("dispersion", "none")],
    (MODELS + "submodels/dispersionModels/constantDispersion/constantDispersion.C",
     "constantDispersion", 0):
        [("dispersion", "constant")],
    (MODELS + "submodels/dispersionModels/brownianDispersion/brownianDispersion.C",
     "brownianDispersion", 0):
        [("dispersion", "Brownian")],
    (MODELS + "submodels/dispersionModels/turbulentDispersion/turbulentDispersion.C",
     "turbulentDispersion", 0):
        [("dispersion", "turbulent")],
    (MODELS + "submodels/dispersionModels/turbulentDispersion/turbulentDispersion.C",
     "turbulentDispersion", 1):
        [("dispersion/Brownian", None)],
    (MODELS + "submodels/patchInteractionModels/localInteraction/localInteraction.C",
     "localInteraction", 0):
        [("patchInteraction", "localInteraction")],
    (MODELS + "cloudFunctions/momentSampler/momentSampler.C", "momentSampler", 0):
        [("sampling", None)],
    (MODELS + "cloudFunctions/sizeDistribution/sizeDistribution.C", "sizeDistribution", 0):
        [("cloudFunctions/<name>", "sizeDistribution")],
    (MODELS + "cloudFunctions/sizeDistribution/sizeDistribution.C", "readBins", 0):
        [("cloudFunctions/<name>/bins", "integer")],
    (MODELS + "cloudFunctions/sizeDistribution/sizeDistribution.C", "readBins", 1):
        [("cloudFunctions/<name>/bins", "log")],
    (MODELS + "cloudFunctions/cellWork/cellWork.C", "cellWork", 0):
        [("cloudFunctions/<name>", "cellWork")],
    (MODELS + "submodels/growthModels/growthModelList/growthModelList.C", "growthModelList", 0):
        [("growth", None)],
    (MODELS + "submodels/growthModels/constantGrowth/constantGrowth.C", "constantGrowth", 0):
        [("growth/<name>", "constant"), ("growth/<name>", "linear")],
    (MODELS + "submodels/growthModels/surfaceGrowth/surfaceGrowth.C", "surfaceGrowth", 0):
        [("growth/<name>", "surface")],
    (MODELS + "submodels/growthModels/condensationGrowth/condensationGrowth.C",
     "condensationGrowth", 0):
        [("growth/<name>", "condensation")],
    ("applications/utilities/workDecomposition/workDecomposition.C", "main", 0):
        [("decomposeParDict/workDecompositionCoeffs", None)],
    (MODELS + "functionObjects/coagulationCloudFunctionObject/coagulationCloudFunctionObject.C",
     "read", 0):
        [("controlDict/functions/<name>", "coagulationCloud")],
}

# Read sites, (file, the dictionary's variable) -> section: dictionaries no keyword check covers
READ_SITES = {
    ("applications/utilities/pseudoTurbulenceField/pseudoTurbulenceField.C", "dict"):
        ("pseudoTurbulenceDict", None),
    ("applications/utilities/workDecomposition/workDecomposition.C", "decompDict"):
        ("decomposeParDict", None),
    ("applications/utilities/workDecomposition/workDecomposition.C", "manualCoeffs"):
        ("decomposeParDict/coeffs", None),
    (MODELS + "submodels/coagulationKernels/localSaffmanTurner/localSaffmanTurner.C",
     "transport"):
        ("transportProperties", None),
    (MODELS + "clouds/runProgress/runProgress.C", "controls"):
        ("controlDict", None),
}

# Switches registered by name -> the section of their controlDict sub-dictionary
SWITCH_SECTIONS = {
    "optimisationSwitch": ("controlDict/OptimisationSwitches", None),
    "debugSwitch": ("controlDict/DebugSwitches", None),
    "infoSwitch": ("controlDict/InfoSwitches", None),
}

# Sections whose entries are names the user chooses (`<name>` rows only): nothing to check
FREE_FORM = {("cloudFunctions", None), ("patchInteraction/patches", None)}

# Sections with keywords beside names the user chooses (`<name>` rows): the keywords checked
MIXED = {("growth", None)}

# The run-time selection tables a user names a model of -> the dictionary that names it
SELECTION_TABLES = {
    ("coagulationKernel", "dictionary"): "kernel",
    ("inceptionModel", "dictionary"): "inception",
    ("injectionModel", "dictionary"): "inflow",
    ("transportModel", "dictionary"): "transport",
    ("dispersionModel", "dictionary"): "dispersion",
    ("patchInteractionModel", "dictionary"): "patchInteraction",
    ("cloudFunction", "dictionary"): "cloudFunctions/<name>",
    ("growthModel", "dictionary"): "growth/<name>",
}

# Model headers whose Usage block (\table ... \endtable) lists exactly these sections' entries
HEADER_SECTIONS = {
    MODELS + "functionObjects/coagulationCloudFunctionObject/coagulationCloudFunctionObject.H":
        [("controlDict/functions/<name>", "coagulationCloud")],
    MODELS + "clouds/coagulationCloud/coagulationCloud.H":
        [("coagulationProperties", None), ("numberControl", None)],
    MODELS + "clouds/statisticalScaling/statisticalScaling.H":
        [("statisticalWeight", None), ("statisticalWeight/V1", None)],
    MODELS + "submodels/injectionModels/initialPopulation/initialPopulation.H": [("initialPopulation", None)],
    MODELS + "submodels/coagulationKernels/coagulationKernel/coagulationKernel.H":
        CORE_KERNELS,
    MODELS + "submodels/coagulationKernels/localSaffmanTurner/localSaffmanTurner.H":
        [("kernel", "localSaffmanTurner")],
    MODELS + "submodels/inceptionModels/uniformInception/uniformInception.H":
        [("inception", "uniform")],
    MODELS + "submodels/inceptionModels/cellZoneInception/cellZoneInception.H":
        [("inception", "cellZone")],
    MODELS + "submodels/inceptionModels/fieldInception/fieldInception.H":
        [("inception", "field")],
    MODELS + "submodels/injectionModels/patchInflow/patchInflow.H": [("inflow", "patchInflow")],
    MODELS + "submodels/transportModels/frozenFlow/frozenFlow.H":
        [("transport", "frozenFlow"), ("transport/interpolationSchemes", None)],
    MODELS + "submodels/dispersionModels/noDispersion/noDispersion.H": [("dispersion", "none")],
    MODELS + "submodels/dispersionModels/constantDispersion/constantDispersion.H":
        [("dispersion", "constant")],
    MODELS + "submodels/dispersionModels/brownianDispersion/brownianDispersion.H":
        [("dispersion", "Brownian")],
    MODELS + "submodels/dispersionModels/turbulentDispersion/turbulentDispersion.H":
        [("dispersion", "turbulent"), ("dispersion/Brownian", None)],
    MODELS + "submodels/patchInteractionModels/localInteraction/localInteraction.H":
        [("patchInteraction", "localInteraction")],
    MODELS + "cloudFunctions/momentSampler/momentSampler.H": [("sampling", None)],
    MODELS + "cloudFunctions/sizeDistribution/sizeDistribution.H":
        [("cloudFunctions/<name>", "sizeDistribution"), ("cloudFunctions/<name>/bins", "integer"),
         ("cloudFunctions/<name>/bins", "log")],
    MODELS + "cloudFunctions/cellWork/cellWork.H": [("cloudFunctions/<name>", "cellWork")],
    MODELS + "submodels/growthModels/growthModelList/growthModelList.H": [("growth", None)],
    MODELS + "clouds/runProgress/runProgress.H": [("controlDict", None)],
    MODELS + "submodels/growthModels/constantGrowth/constantGrowth.H":
        [("growth/<name>", "constant")],
    MODELS + "submodels/growthModels/linearGrowth/linearGrowth.H": [("growth/<name>", "linear")],
    MODELS + "submodels/growthModels/surfaceGrowth/surfaceGrowth.H":
        [("growth/<name>", "surface")],
    MODELS + "submodels/growthModels/condensationGrowth/condensationGrowth.H":
        [("growth/<name>", "condensation")],
}


class ParseError(AssertionError):
    """The sources or the reference are not written the way this parser reads them."""


# --------------------------------------------------------------------------- C++ sources

def strip_cpp(text, keep_preprocessor=False):
    """text with comments (and, unless kept, preprocessor lines with their continuations)
    blanked to spaces: positions and line numbers stay; string literals are kept."""
    out = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and not keep_preprocessor:
            j = i
            while j < n and text[j] in " \t":
                j += 1
            if j < n and text[j] == "#":
                while j < n and text[j] != "\n":
                    if text[j] == "\\" and j + 1 < n and text[j + 1] == "\n":
                        j += 1
                    j += 1
                out.append(re.sub(r"[^\n]", " ", text[i:j]))
                i = j
                continue
        line_start = False
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(text[i:j + 1])
            i = j + 1
        else:
            out.append(c)
            if c == "\n":
                line_start = True
            i += 1
    return "".join(out)


def matching(text, i):
    """The index just past the bracket that closes the one at text[i] (strings skipped)."""
    pairs = {"(": ")", "{": "}", "[": "]"}
    stack = [pairs[text[i]]]
    j = i + 1
    while j < len(text):
        c = text[j]
        if c in "\"'":
            k = j + 1
            while k < len(text) and text[k] != c:
                k += 2 if text[k] == "\\" else 1
            j = k + 1
            continue
        if c in pairs:
            stack.append(pairs[c])
        elif c in ")}]":
            if c != stack.pop():
                raise ParseError("unbalanced brackets at offset %d" % j)
            if not stack:
                return j + 1
        j += 1
    raise ParseError("unclosed bracket at offset %d" % i)


def split_args(inner):
    """Top-level comma-separated parts of an argument list's text (template arguments,
    'List<Tuple2<scalar, scalar>>', are not split)."""
    parts, depth, angle, start = [], 0, 0, 0
    i = 0
    while i < len(inner):
        c = inner[i]
        if c in "\"'":
            k = i + 1
            while k < len(inner) and inner[k] != c:
                k += 2 if inner[k] == "\\" else 1
            i = k + 1
            continue
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == "<" and i > 0 and re.match(r"\w", inner[i - 1]):
            angle += 1
        elif c == ">" and angle > 0:
            angle -= 1
        elif c == "," and depth == 0 and angle == 0:
            parts.append(inner[start:i].strip())
            start = i + 1
        i += 1
    last = inner[start:].strip()
    if last or parts:
        parts.append(last)
    return parts


class Function:
    """A function definition: its name, parameters, and the text from its name to its end."""

    def __init__(self, path, text, name, name_pos, params_end, body_start, end):
        self.path, self.text, self.name = path, text, name
        self.name_pos, self.body_start, self.end = name_pos, body_start, end
        self.params = parse_params(text[text.index("(", name_pos) + 1:params_end - 1])

    def line(self, pos):
        return self.text.count("\n", 0, pos) + 1


def parse_params(inner):
    """[(name, default or None)] of a parameter list's text."""
    params = []
    for p in split_args(inner):
        if not p or p == "void":
            continue
        decl, _, default = p.partition("=")
        names = re.findall(r"[A-Za-z_]\w*", decl)
        params.append((names[-1] if names else "", default.strip() or None))
    return params


def functions_of(path, text):
    """The function definitions of a stripped source text (at namespace or class level)."""
    found = []
    i, n = 0, len(text)
    head_start = 0
    paren = 0
    while i < n:
        c = text[i]
        if c in "\"'":
            k = i + 1
            while k < n and text[k] != c:
                k += 2 if text[k] == "\\" else 1
            i = k + 1
            continue
        if c == "(":
            paren += 1
        elif c == ")":
            paren -= 1
        elif c == ";" and paren == 0:
            head_start = i + 1
        elif c == "}" and paren == 0:
            head_start = i + 1      # the end of a container (namespace, class)
        elif c == "{" and paren == 0:
            head = text[head_start:i]
            if re.search(r"\bnamespace\b[\s\w]*$|\bextern\s+\"C\"\s*$", head):
                head_start = i + 1
            elif re.search(r"\b(class|struct|union)\b", head) and "(" not in head.split(":")[0]:
                head_start = i + 1  # a class body: its member functions are found inside
            elif re.search(r"\benum\b", head) or re.search(r"=\s*$", head) or "(" not in head:
                i = matching(text, i)   # an enum, an aggregate, a brace initialiser
                head_start = i
                continue
            elif re.search(r"[\w>]\s*$", head) and not re.search(
                    r"\)\s*(const|override|final|noexcept|mutable|volatile|\s)*$", head):
                i = matching(text, i)   # a member's brace initialiser in an initialiser list
                continue
            else:
                m = re.search(r"\b((?:[A-Za-z_]\w*\s*::\s*)*(?:operator\s*(?:\(\)|[^\s(]+)"
                              r"|~?[A-Za-z_]\w*))\s*\(", head)
                if not m:
                    raise ParseError("%s:%d: a block whose head names no function" % (
                        path, text.count("\n", 0, i) + 1))
                name_pos = head_start + m.start()
                params_open = head_start + m.end() - 1
                params_end = matching(text, params_open)
                end = matching(text, i)
                name = re.sub(r"\s", "", m.group(1)).split("::")[-1]
                found.append(Function(path, text, name, name_pos, params_end, i, end))
                i = end
                head_start = end
                continue
        i += 1
    return found


class Sources:
    """The parsed C++ sources of src/coagulationModels and applications."""

    def __init__(self, root):
        self.root = root
        self.files = {}             # rel path -> stripped text
        self.raw = {}               # rel path -> text with the preprocessor lines kept
        for d in SOURCE_DIRS:
            for dirpath, dirnames, names in os.walk(os.path.join(root, d)):
                # not the build's links (lnInclude) and objects
                dirnames[:] = sorted(n for n in dirnames
                                     if n not in ("lnInclude", "platforms")
                                     and not n.startswith("linux64"))
                for name in sorted(names):
                    if name.endswith(SOURCE_EXTENSIONS):
                        full = os.path.join(dirpath, name)
                        rel = os.path.relpath(full, root).replace(os.sep, "/")
                        with open(full, encoding="utf-8") as f:
                            text = f.read()
                        self.files[rel] = strip_cpp(text)
                        self.raw[rel] = strip_cpp(text, keep_preprocessor=True)
        if not self.files:
            raise ParseError("no C++ source under %s" % ", ".join(SOURCE_DIRS))
        self.functions = {rel: functions_of(rel, text) for rel, text in self.files.items()}

    def enclosing(self, rel, pos):
        for f in self.functions[rel]:
            if f.name_pos <= pos < f.end:
                return f
        return None

    def calls(self, name, qualifiers=None):
        """(rel, Function, pos, args text) of every call of name inside a function (its own
        definition and member calls of other objects excluded); qualifiers: the namespaces
        or classes a qualified call's prefix must be a suffix of (unqualified calls all)."""
        pattern = re.compile(r"\b((?:[A-Za-z_]\w*\s*::\s*)*)" + re.escape(name) + r"\s*\(")
        for rel, text in self.files.items():
            for m in pattern.finditer(text):
                if m.group(1) == "" and m.start() > 0 and re.match(r"\w", text[m.start() - 1]):
                    continue
                f = self.enclosing(rel, m.start())
                open_paren = m.end() - 1
                if f is None or open_paren == text.index("(", f.name_pos):
                    continue                    # not in a function, or its definition
                if re.search(r"(\.|->)\s*$", text[max(0, m.start() - 20):m.start()]):
                    continue                    # a member function of another object
                qual = re.sub(r"\s", "", m.group(1))
                if qual and qualifiers is not None and not any(
                        (q + "::").endswith(qual) for q in qualifiers):
                    continue
                close = matching(text, open_paren)
                yield rel, f, m.start(), text[open_paren + 1:close - 1]


def literals(text, where):
    """The string literals of a braced list's text; ParseError for anything else in it."""
    inner = text.strip()
    if not (inner.startswith("{") and inner.endswith("}")):
        raise ParseError("%s: not a braced list: %s" % (where, inner))
    items = split_args(inner[1:-1])
    words = []
    for item in items:
        m = re.fullmatch(r'"(\w+)"', item)
        if not m:
            raise ParseError("%s: a keyword list item that is no string literal: %s" % (
                where, item))
        words.append(m.group(1))
    return words


def list_expression(expr, where):
    """The keywords of a list expression given as an argument, or None if it is no literal
    list ({...}, wordList({...}), wordList{...}, wordList())."""
    e = expr.strip()
    if e.startswith("{"):
        return literals(e, where)
    m = re.fullmatch(r"(?:Foam::)?wordList\s*(\(\s*(\{.*\})\s*\)|(\{.*\}))", e, re.S)
    if m:
        return literals(m.group(2) or m.group(3), where)
    if re.fullmatch(r"(?:Foam::)?wordList\s*\(\s*\)", e):
        return []
    return None


class Template:
    """A keyword list built in function f from its parameters: fixed words, words appended
    when a bool parameter holds, and lists passed as parameters."""

    def __init__(self, fixed, conditional, list_params, f):
        self.fixed, self.conditional, self.list_params, self.f = fixed, conditional, list_params, f


def resolve_list(sources, rel, f, pos, arg):
    """The list a checker is given at pos in function f: a list of words, or a Template."""
    where = "%s:%d" % (rel, f.line(pos))
    words = list_expression(arg, where)
    if words is not None:
        return words
    var = arg.strip()
    if not re.fullmatch(r"[A-Za-z_]\w*", var):
        raise ParseError("%s: the keyword list '%s' is neither a literal list nor a variable" % (
            where, arg.strip()))
    text = sources.files[rel]
    body = text[f.body_start:pos]
    decl = re.search(r"\bwordList\s+" + var + r"\s*(\(\s*\{.*?\}\s*\)|\{.*?\})\s*;", body, re.S)
    if not decl:
        raise ParseError("%s: no declaration 'wordList %s{...}' before the check" % (where, var))
    init = decl.group(1).strip()
    fixed = literals(init[1:-1].strip() if init.startswith("(") else init, where)
    params = [p for p, _ in f.params]
    conditional, list_params = [], []
    for m in re.finditer(r"\b" + var + r"\s*\.\s*append\s*\(", body[decl.end():]):
        start = decl.end() + m.end() - 1
        item = body[start + 1:matching(body, start) - 1].strip()
        guard = re.search(r"\bif\s*\(\s*(\w+)\s*\)\s*\{?\s*$", body[:decl.end() + m.start()])
        cond = guard.group(1) if guard else None
        if cond is not None and cond not in params:
            raise ParseError("%s: '%s' appended under the condition '%s', which is no "
                             "parameter of %s" % (where, item, cond, f.name))
        if re.fullmatch(r'"\w+"', item):
            if cond:
                conditional.append((cond, item.strip('"')))
            else:
                fixed.append(item.strip('"'))
        elif item in params and cond is None:
            list_params.append(item)
        else:
            raise ParseError("%s: %s.append(%s) is neither a string literal nor a parameter "
                             "of %s" % (where, var, item, f.name))
    if not conditional and not list_params:
        return fixed
    return Template(fixed, conditional, list_params, f)


def declared_defaults(sources, f):
    """{parameter: default} of f's declaration (the defaults live in the header)."""
    defaults = {p: d for p, d in f.params if d is not None}
    names = [p for p, _ in f.params]
    for rel, text in sources.files.items():
        for m in re.finditer(r"\b" + re.escape(f.name) + r"\s*\(", text):
            close = matching(text, m.end() - 1)
            params = parse_params(text[m.end():close - 1])
            if [p for p, _ in params] == names:
                defaults.update({p: d for p, d in params if d is not None})
    return defaults


class Site:
    """Keywords a dictionary accepts, from one check (or one call of a template)."""

    def __init__(self, rel, function, line, pos, keywords):
        self.rel, self.function, self.line, self.pos = rel, function, line, pos
        self.keywords = keywords

    def __repr__(self):
        return "%s:%d (%s) %s" % (self.rel, self.line, self.function, sorted(self.keywords))


def template_sites(sources, template, depth=0):
    """The sites of every call of a template's function."""
    f = template.f
    if depth > 4:
        raise ParseError("keyword templates nested too deeply at %s" % f.name)
    names = [p for p, _ in f.params]
    defaults = declared_defaults(sources, f)
    sites = []
    for rel, caller, pos, args_text in sources.calls(f.name):
        args = split_args(args_text)
        where = "%s:%d" % (rel, caller.line(pos))
        if len(args) > len(names):
            continue                # another overload
        value = {}
        for i, p in enumerate(names):
            value[p] = args[i] if i < len(args) else defaults.get(p)
        words = list(template.fixed)
        for cond, w in template.conditional:
            v = (value.get(cond) or "").strip()
            if v not in ("true", "false"):
                raise ParseError("%s: the call of %s gives '%s' for '%s': not true or false"
                                 % (where, f.name, v, cond))
            if v == "true":
                words.append(w)
        for p in template.list_params:
            if value.get(p) is None:
                raise ParseError("%s: the call of %s gives no '%s' and it has no default"
                                 % (where, f.name, p))
            extra = list_expression(value[p], where)
            if extra is None:
                raise ParseError("%s: the call of %s gives '%s' for '%s': not a literal list"
                                 % (where, f.name, value[p], p))
            words.extend(extra)
        sites.append(Site(rel, caller.name, caller.line(pos), pos, words))
    if not sites:
        raise ParseError("%s builds its keyword list from its parameters, but nothing calls it"
                         % f.name)
    return sites


def checkers(sources):
    """{name: (Function, index of its list parameter)} of the keyword checks."""
    found = {}
    for rel, text in sources.files.items():
        for m in re.finditer(r"\b(\w+)\s*\.\s*found\s*\(\s*\w+\s*(\.|->)\s*keyword\s*\(\s*\)\s*\)",
                             text):
            f = sources.enclosing(rel, m.start())
            if f is None:
                raise ParseError("%s: a keyword check outside a function" % rel)
            params = [p for p, _ in f.params]
            if m.group(1) not in params:
                raise ParseError("%s:%d: %s checks entries against '%s', which is no parameter: "
                                 "a keyword check this parser cannot read"
                                 % (rel, f.line(m.start()), f.name, m.group(1)))
            found[f.name] = (f, params.index(m.group(1)))
    return found


def qualifier_of(f):
    """The qualifiers of f's definition, e.g. ['Foam::caseChecks'] ([] for a plain name)."""
    head = f.text[f.name_pos:f.text.index("(", f.name_pos)]
    qual = re.sub(r"\s", "", head).rsplit("::", 1)
    return [qual[0]] if len(qual) == 2 else []


def keyword_sites(sources):
    """Every site of a keyword check: [Site]."""
    sites = []
    found = checkers(sources)
    if not found:
        raise ParseError("no keyword check found in %s (no function tests "
                         "<list>.found(<entry>.keyword()))" % ", ".join(SOURCE_DIRS))
    for name, (checker, index) in found.items():
        quals = qualifier_of(checker)
        # caseChecks::keywords is called as caseChecks::keywords(...): a suffix of
        # Foam::caseChecks
        calls = list(sources.calls(name, qualifiers=quals or None))
        if not calls:
            raise ParseError("the keyword check %s (%s) is never called" % (name, checker.path))
        for rel, f, pos, args_text in calls:
            args = split_args(args_text)
            if len(args) <= index:
                raise ParseError("%s:%d: %s called without its keyword list" % (
                    rel, f.line(pos), name))
            got = resolve_list(sources, rel, f, pos, args[index])
            if isinstance(got, Template):
                sites.extend(template_sites(sources, got))
            else:
                sites.append(Site(rel, f.name, f.line(pos), pos, got))
    return sites


def read_keys(sources, rel, var):
    """The keys dictionary variable var is read for in file rel."""
    text = sources.files[rel]
    pattern = (r"\b" + re.escape(var) + r"\s*\.\s*(?:get|getOrDefault|lookup|lookupOrDefault|found"
               r"|subDict|isDict|subOrEmptyDict|readEntry|readIfPresent)\s*(?:<[^;()]*?>)?\s*"
               r"\(\s*\"(\w+)\"")
    return [m.group(1) for m in re.finditer(pattern, text)]


def switches(sources):
    """{section: [switch names]} of the switches registered by name."""
    out = defaultdict(list)
    for rel, text in sources.files.items():
        for kind, section in SWITCH_SECTIONS.items():
            for m in re.finditer(r"\b" + kind + r"\s*\(\s*\"(\w+)\"", text):
                out[section].append(m.group(1))
    return out


def core_kernels(sources):
    text = sources.files[MODELS + "submodels/coagulationKernels/coreKernels/coreKernels.C"]
    names = re.findall(r"\bmakeCoreCoagulationKernel\s*\(\s*(\w+)\s*\)", text)
    if not names:
        raise ParseError("no makeCoreCoagulationKernel(...) in coreKernels.C")
    return [("kernel", n) for n in names]


def selectable_types(sources):
    """{(base, table): [type names]} from addToRunTimeSelectionTable, directly or by macros."""
    type_names = {}
    for rel, text in sources.files.items():
        if rel.endswith(".H"):
            for m in re.finditer(r"\bclass\s+(\w+)\s*(?::[^{;]*)?\{", text):
                t = re.search(r"\bTypeName\s*\(\s*\"(\w+)\"\s*\)", text[m.end():])
                if t:
                    type_names.setdefault(m.group(1), t.group(1))
    out = defaultdict(list)
    add = re.compile(r"\baddToRunTimeSelectionTable\s*\(\s*(\w+)\s*,\s*([\w#]+)\s*,\s*(\w+)\s*\)")
    for rel, text in sources.files.items():
        for m in add.finditer(text):
            base, cls, table = m.groups()
            if cls not in type_names:
                raise ParseError("%s: no TypeName found for class %s" % (rel, cls))
            out[(base, table)].append(type_names[cls])
    for rel, raw in sources.raw.items():
        for d in re.finditer(r"#\s*define\s+(\w+)\s*\(\s*(\w+)[^)]*\)((?:[^\n]*\\\n)*[^\n]*)", raw):
            macro, param, body = d.groups()
            m = add.search(body)
            if not m or not re.search(r"TypeName\s*\(\s*#\s*" + param + r"\s*\)", body):
                continue
            base, _, table = m.groups()
            for inv in re.finditer(r"\b" + macro + r"\s*\(\s*(\w+)", sources.files[rel]):
                out[(base, table)].append(inv.group(1))
    return out


# --------------------------------------------------------------------------- the reference

def heading_sections(heading):
    """The sections a heading names: [(path, model)] (empty: no code span)."""
    spans = re.findall(r"`([^`]+)`", heading)
    if not spans:
        return []
    path = spans[0].strip()
    models = []
    for s in spans[1:]:
        m = re.fullmatch(r"type\s+(.+)", s.strip())
        if m:
            models.extend(t.strip() for t in m.group(1).split("|") if t.strip())
    return [(path, t) for t in models] if models else [(path, None)]


def table_keywords(lines, where):
    """[keyword] of the Property tables in lines (a table: header row starting 'Property')."""
    keys = []
    in_table = False
    for k, line in enumerate(lines):
        if not line.startswith("|"):
            in_table = False
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if not in_table:
            if cells[0] == "Property":
                in_table = True
            continue
        if re.fullmatch(r":?-+:?", cells[0]):
            continue
        m = re.fullmatch(r"`([^`]+)`", cells[0])
        if not m:
            raise ParseError("%s: a table row whose first cell is no single `keyword`: %s"
                             % (where, line.strip()))
        keys.append(m.group(1))
    return keys


def parse_reference(path):
    """{(path, model): [keywords]} of the reference's sections."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    sections = {}
    current, start, fence = None, 0, False
    blocks = []
    for i, line in enumerate(lines):
        if line.startswith("```"):
            fence = not fence
        if fence:
            lines[i] = ""           # examples are no tables
            continue
        if re.match(r"#{1,6}\s", line):
            blocks.append((current, start, i))
            current, start = line, i + 1
    blocks.append((current, start, len(lines)))
    for heading, a, b in blocks:
        where = "%s:%d" % (os.path.relpath(path, ROOT), a)
        keys = table_keywords(lines[a:b], where)
        if not keys:
            continue
        ids = heading_sections(heading or "")
        if not ids:
            raise ParseError("%s: a Property table under a heading that names no dictionary "
                             "(%s)" % (where, heading))
        for sid in ids:
            if sid in sections:
                raise ParseError("%s: section %s documented twice" % (where, sid))
            sections[sid] = keys
    return sections


# --------------------------------------------------------------------------- fixtures

@pytest.fixture(scope="module")
def sources():
    return Sources(ROOT)


@pytest.fixture(scope="module")
def sites(sources):
    return keyword_sites(sources)


@pytest.fixture(scope="module")
def mapping(sources, sites):
    """({(path, model): set of keywords} from the sources, [unmapped sites], [stale keys])."""
    out = defaultdict(set)
    ordinals = defaultdict(int)
    unmapped = []
    used = set()
    for s in sorted(sites, key=lambda s: (s.rel, s.pos)):
        key = (s.rel, s.function, ordinals[(s.rel, s.function)])
        ordinals[(s.rel, s.function)] += 1
        if key not in SECTIONS:
            unmapped.append("%r (key %r)" % (s, key))
            continue
        used.add(key)
        ids = SECTIONS[key]
        for sid in (core_kernels(sources) if ids == CORE_KERNELS else ids):
            out[sid].update(s.keywords)
    stale = [k for k in SECTIONS if k not in used]
    for (rel, var), sid in READ_SITES.items():
        keys = read_keys(sources, rel, var)
        assert keys, "no key read from '%s' in %s" % (var, rel)
        out[sid].update(keys)
    for sid, names in switches(sources).items():
        out[sid].update(names)
    return out, unmapped, stale


@pytest.fixture(scope="module")
def accepted(mapping):
    return mapping[0]


@pytest.fixture(scope="module")
def reference():
    assert os.path.isfile(REFERENCE), "missing " + REFERENCE
    return parse_reference(REFERENCE)


# --------------------------------------------------------------------------- tests

def test_every_check_mapped(mapping):
    """Every keyword check of the sources fills known sections; every mapping is current."""
    _, unmapped, stale = mapping
    assert not unmapped, ("keyword checks the reference map does not know (add them to "
                          "SECTIONS in tests/python/test_dictionaryReference.py and document "
                          "them):\n  " + "\n  ".join(unmapped))
    assert not stale, "SECTIONS entries with no keyword check in the sources:\n  " + "\n  ".join(
        map(repr, stale))


def test_sources_give_keywords(sites, accepted):
    """The parser finds the checks, their keywords, and the known sections (not vacuous)."""
    assert len(sites) >= len(SECTIONS) > 0
    n = sum(len(k) for k in accepted.values())
    assert n > 0, "no keyword found in the sources"
    for s in sites:
        assert s.keywords, "a keyword check with an empty list: %r" % s
    assert accepted[("kernel", "constant")] == {"type", "K0"}
    assert "rate" in accepted[("inception", "uniform")]
    assert "rate" not in accepted[("inception", "field")]
    brownian = accepted[("dispersion/Brownian", None)]
    assert brownian and accepted[("dispersion", "Brownian")] == brownian | {"type"}
    assert "coagulationCloudMove" in accepted[("controlDict/OptimisationSwitches", None)]


def test_reference_parsed(reference):
    assert reference, "no section with a Property table in " + REFERENCE
    assert sum(len(k) for k in reference.values()) > 0


def test_every_accepted_keyword_documented(accepted, reference):
    missing = []
    for sid, keys in sorted(accepted.items(), key=str):
        documented = set(reference.get(sid, []))
        for k in sorted(keys - documented):
            missing.append("%s (%s): `%s`" % (sid[0], "type " + sid[1] if sid[1] else "-", k))
    assert not missing, ("keywords the sources accept but doc/dictionaryReference.md does not "
                         "list (a row `keyword` in the section's Property table):\n  "
                         + "\n  ".join(missing))


def test_every_documented_keyword_accepted(accepted, reference):
    wrong = []
    for sid, keys in sorted(reference.items(), key=str):
        if sid in FREE_FORM:
            extra = [k for k in keys if not k.startswith("<")]
            wrong.extend("%s: `%s` in a section of names the user chooses" % (sid, k)
                         for k in extra)
            continue
        if sid not in accepted:
            wrong.append("%s: a section no keyword check or read in the sources fills" % (sid,))
            continue
        for k in keys:
            if k.startswith("<") and sid in MIXED:
                continue
            if k not in accepted[sid]:
                wrong.append("%s: `%s` is not accepted there" % (sid, k))
    assert not wrong, "doc/dictionaryReference.md documents what the code does not take:\n  " \
        + "\n  ".join(wrong)


def test_every_selectable_type_documented(sources, reference):
    types = selectable_types(sources)
    assert types, "no run-time selectable type found"
    missing = []
    for (base, table), path in SELECTION_TABLES.items():
        names = types.get((base, table))
        assert names, "no type registered in %s's %s table" % (base, table)
        for t in names:
            if (path, t) not in reference:
                missing.append("%s: `type %s`" % (path, t))
    assert not missing, "model types with no section in doc/dictionaryReference.md:\n  " \
        + "\n  ".join(missing)


def header_usage_keywords(path):
    """[keyword] of the \\table blocks of a header's Usage section."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    usage = re.search(r"^Usage\s*$(.*?)^(SourceFiles|See also|Note|\\\*-)", text, re.S | re.M)
    if not usage:
        return None
    keys = []
    for table in re.findall(r"\\table\s*\n(.*?)\\endtable", usage.group(1), re.S):
        rows = [r.strip() for r in table.strip().split("\n") if r.strip()]
        for row in rows[1:]:           # the first row is the header
            keys.append(row.split("|")[0].strip())
    return keys


def test_header_usage_tables(sources, accepted):
    problems = []
    for rel, ids in HEADER_SECTIONS.items():
        keys = header_usage_keywords(os.path.join(ROOT, rel))
        if keys is None:
            problems.append("%s: no Usage block" % rel)
            continue
        want = set()
        for sid in (core_kernels(sources) if ids == CORE_KERNELS else ids):
            want |= accepted[sid]
        got = set(k for k in keys if not k.startswith("<"))
        for k in sorted(want - got):
            problems.append("%s: Usage table lacks `%s`" % (rel, k))
        for k in sorted(got - want):
            problems.append("%s: Usage table lists `%s`, which the model does not accept"
                            % (rel, k))
    assert not problems, "\n  ".join(["model headers' Usage tables out of step:"] + problems)
