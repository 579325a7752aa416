# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# The duct as a case of OpenFOAM's transient solvers with the coagulationCloud function object
# (case_functionObject, case_faults, case_liveFields); sourced after caseLib.sh.

# fo case [U]: the function object in the case's controlDict
fo()
{
    foamDictionary -case "$1" "$1/system/controlDict" -entry functions/particles \
        -add "{ type coagulationCloud; libs (coagulationModels); ${2:-} }" > /dev/null
    foamDictionary -case "$1" "$1/system/controlDict" -entry functions/momentAverages \
        -remove > /dev/null
}

# scalarTransport case: the duct as a scalarTransportFoam case (a passive T, U kept as read)
scalarTransport()
{
    local c="$1"
    sed -e 's/volVectorField/volScalarField/' -e 's/object      U;/object      T;/' \
        -e 's/\[0 1 -1 0 0 0 0\]/[0 0 0 1 0 0 0]/' -e 's/uniform (1 0 0)/uniform 1/g' \
        "$c/0/U" > "$c/0/T"
    cat > "$c/constant/transportProperties" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object transportProperties; }
DT 1e-9;
DICT
    scalarTransportSchemes "$c" 1e-12
    setEntry "$c" system/controlDict application scalarTransportFoam
}

# scalarTransportSchemes case tolerance: scalarTransportFoam's scheme and solver for T
scalarTransportSchemes()
{
    foamDictionary -case "$1" "$1/system/fvSchemes" -entry divSchemes/"div(phi,T)" \
        -add "Gauss upwind" > /dev/null
    foamDictionary -case "$1" "$1/system/fvSolution" -entry solvers/T \
        -add "{ solver PBiCGStab; preconditioner DILU; tolerance $2; relTol 0; }" > /dev/null
    foamDictionary -case "$1" "$1/system/fvSolution" -entry SIMPLE \
        -add "{ nNonOrthogonalCorrectors 0; }" > /dev/null
}

# pimpleCase dir: the duct as a laminar pimpleFoam case (p, nu, fvSchemes, fvSolution)
pimpleCase()
{
    local c
    c=$(newCase constantKernelDuct "$1")
    cat > "$c/0/p" <<'DICT'
FoamFile { version 2.0; format ascii; class volScalarField; object p; }
dimensions [0 2 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    inlet { type zeroGradient; }
    outlet { type fixedValue; value uniform 0; }
    sides { type empty; }
}
DICT
    cat > "$c/constant/transportProperties" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object transportProperties; }
transportModel Newtonian;
nu 1e-5;
DICT
    cat > "$c/constant/turbulenceProperties" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object turbulenceProperties; }
simulationType laminar;
DICT
    cat > "$c/system/fvSchemes" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object fvSchemes; }
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default none; div(phi,U) Gauss linear; div((nuEff*dev2(T(grad(U))))) Gauss linear; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
DICT
    cat > "$c/system/fvSolution" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object fvSolution; }
solvers
{
    p { solver PCG; preconditioner DIC; tolerance 1e-10; relTol 0; }
    pFinal { $p; }
    U { solver PBiCGStab; preconditioner DILU; tolerance 1e-10; relTol 0; }
    UFinal { $U; }
}
PIMPLE { nOuterCorrectors 1; nCorrectors 2; nNonOrthogonalCorrectors 0; }
DICT
    setEntry "$c" system/controlDict application pimpleFoam
    setEntry "$c" system/controlDict endTime 1.2
    setEntry "$c" system/controlDict writeInterval 1.2
    fo "$c"
    echo "$c"
}
