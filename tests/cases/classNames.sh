#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# No class of the project's OpenFOAM library has the name of a class of the OpenFOAM
# libraries it is loaded beside.
#
#   classNames.sh [LIB...]     (default: $FOAM_USER_LIBBIN/libcoagulationModels.so)
#
# Two classes of one name in one process break the one-definition rule: the dynamic linker
# binds every symbol of that name (typeName, the run-time selection tables, the vtable) to
# the first library loaded, so a solver that loads both gets one class's selection table or
# type name under the other's. OpenFOAM's own incompressible Foam::transportModel
# (libincompressibleTransportModels, linked by every incompressible solver and by the
# turbulence models) is such a name.
#
# The symbols: `nm -C --defined-only` of each library, its dynamic symbol table (nm -D) where
# the library is stripped (Debian's OpenFOAM libraries are), the table the dynamic linker binds.
# A class of the project: the type scope (Foam::X of Foam::X::f(), Foam::A::B of
# Foam::A::B::typeName) of a symbol the library defines out of line, type T, D, B or R; the library's weak symbols (W, V, u: the inline functions and template
# instances of OpenFOAM's headers) are OpenFOAM's, not the project's. Every class with a .C
# file, a typeName or a selection table has such a symbol. A class of OpenFOAM: the type
# scope of any symbol defined in the libraries below (all types), or the class of a vtable or
# typeinfo there. The test fails when the two sets share a name, listing each with a symbol of
# either side.
testsDir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# shellcheck source=/dev/null
. "$testsDir/caseLib.sh"

libs=("$@")
[ ${#libs[@]} -gt 0 ] || libs=("$FOAM_USER_LIBBIN/libcoagulationModels.so")
for lib in "${libs[@]}"; do
    [ -f "$lib" ] || fail "no library $lib (run ./Allwmake)"
done

# OpenFOAM's libraries: where the project's library finds libfiniteVolume (Debian: /usr/lib;
# a development tree: its platforms/*/lib), the libraries it links and those a case or a
# solver loads beside it (function objects, the incompressible and turbulence models, the
# lagrangian libraries)
ofLib=$(ldd "${libs[0]}" | awk '$1 == "libfiniteVolume.so" { print $3 }')
[ -n "$ofLib" ] && [ -f "$ofLib" ] || fail "ldd ${libs[0]} finds no libfiniteVolume.so"
ofDir=$(dirname "$(readlink -f "$ofLib")")
ofLibs=()
for name in OpenFOAM finiteVolume meshTools fileFormats surfMesh dynamicMesh \
    lagrangian lagrangianIntermediate lagrangianTurbulence lagrangianFunctionObjects \
    incompressibleTransportModels compressibleTransportModels turbulenceModels \
    incompressibleTurbulenceModels compressibleTurbulenceModels fieldFunctionObjects \
    sampling decompositionMethods specie fluidThermophysicalModels
do
    [ -f "$ofDir/lib$name.so" ] || fail "no lib$name.so in $ofDir"
    ofLibs+=("$ofDir/lib$name.so")
done
# and every other OpenFOAM library the project's links (the same folder)
while read -r dep; do
    case " ${ofLibs[*]} " in *" $dep "*) ;; *) ofLibs+=("$dep") ;; esac
done < <(ldd "${libs[@]}" | awk -v d="$ofDir/" 'index($3, d) == 1 { print $3 }' | sort -u)
echo "project: ${libs[*]}"
echo "OpenFOAM (${#ofLibs[@]} libraries in $ofDir): $(basename -a "${ofLibs[@]}" | tr '\n' ' ')"

"${COAGULATIONFOAM_PYTHON:-python3}" - "${#libs[@]}" "${libs[@]}" "${ofLibs[@]}" <<'EOF'
import os, re, subprocess, sys

n = int(sys.argv[1])
projectLibs, ofLibs = sys.argv[2:2 + n], sys.argv[2 + n:]

# Prefixes of special symbols: those that name a class (the class is the rest), and those
# that name a function or variable (the class is the rest's scope)
CLASS_OF = ("vtable for ", "typeinfo for ", "typeinfo name for ", "VTT for ")
ENTITY_OF = ("guard variable for ", "non-virtual thunk to ", "virtual thunk to ",
             "covariant return thunk to ", "TLS init function for ",
             "TLS wrapper function for ", "transaction clone for ")
OPEN, CLOSE = "<({[", ">)}]"


def qualifiedName(s):
    """The qualified name of a demangled function or variable, without its parameters and
    return type, split at the top-level '::'; None for a name that is no entity."""
    s = s.replace("(anonymous namespace)", "{anonymous}")
    parts, depth, start, i = [], 0, 0, 0
    while i < len(s):
        c = s[i]
        if depth == 0 and s.startswith("operator", i) and (i == start):
            parts.append(s[start:])   # operator<<, operator(), a conversion: the last part
            return parts
        if c in OPEN:
            if c == "(" and depth == 0:
                break                 # the parameters
            depth += 1
        elif c in CLOSE:
            depth -= 1
        elif depth == 0 and c == " ":
            parts, start = [], i + 1  # what came before was the return type
        elif depth == 0 and s.startswith("::", i):
            parts.append(s[start:i])
            i += 2
            start = i
            continue
        i += 1
    parts.append(s[start:i])
    return parts


def typeScope(name):
    """The class a demangled symbol belongs to ('Foam::X'), or None."""
    for p in CLASS_OF:
        if name.startswith(p):
            scope = qualifiedName(name[len(p):])
            break
    else:
        for p in ENTITY_OF:
            if name.startswith(p):
                name = name[len(p):]
                break
        scope = qualifiedName(name)[:-1]
    if len(scope) < 2 or scope[0] != "Foam":
        return None
    return "::".join(scope)


def symbols(lib):
    """(type, demangled name) of the symbols lib defines: its symbol table, or where it is
    stripped (Debian's OpenFOAM) its dynamic symbol table, which is what the dynamic linker
    binds by"""
    out = ""
    for dynamic in ([], ["-D"]):
        out = subprocess.run(["nm", "-C", "--defined-only"] + dynamic + [lib],
                             check=True, capture_output=True, text=True).stdout
        if out:
            break
    if not out:
        sys.exit(f"FAIL: nm finds no symbols in {lib}")
    for line in out.splitlines():
        f = line.split(" ", 2)
        if len(f) == 3:
            yield f[1], f[2]


project = {}
for lib in projectLibs:
    for kind, name in symbols(lib):
        if kind in "TDBR":
            scope = typeScope(name)
            if scope:
                project.setdefault(scope, name)
print(f"{len(project)} classes of the project (out-of-line symbols under Foam::)")

clashes = {}
for lib in ofLibs:
    for kind, name in symbols(lib):
        scope = typeScope(name)
        if scope in project and scope not in clashes:
            clashes[scope] = (os.path.basename(lib), name)

for scope in sorted(clashes):
    lib, name = clashes[scope]
    print(f"CLASH {scope}: project {project[scope]!r}; {lib} {name!r}")
if clashes:
    print(f"FAIL: {len(clashes)} class name(s) of the project also defined by OpenFOAM")
    sys.exit(1)
print("no class name of the project is defined by the OpenFOAM libraries")
EOF
