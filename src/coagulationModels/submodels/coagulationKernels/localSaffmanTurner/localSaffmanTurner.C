/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "localSaffmanTurner.H"
#include "caseChecks.H"
#include "IOdictionary.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
namespace coagulationKernels
{
    defineTypeNameAndDebug(localSaffmanTurner, 0);
    addToRunTimeSelectionTable
    (
        coagulationKernel,
        localSaffmanTurner,
        dictionary
    );
}
}
}


namespace
{
    const char* const modelName = "kernel model 'localSaffmanTurner'";
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar
Foam::coagulation::coagulationKernels::localSaffmanTurner::readCoefficient
(
    const dictionary& dict
)
{
    caseChecks::keywords(dict, {"type", "coefficient", "epsilon", "nu"});
    return caseChecks::positive(dict, "coefficient");
}


Foam::scalar
Foam::coagulation::coagulationKernels::localSaffmanTurner::uniformNu
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    scalar nu = 0;
    string source;
    if (dict.found("nu"))
    {
        nu = caseChecks::withTrapsHeld
        (
            [&]() { return dimensionedScalar("nu", dimViscosity, dict); }
        ).value();
        source = "entry 'nu' in " + dict.name();
    }
    else
    {
        IOobject io
        (
            "transportProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );
        if (!io.typeHeaderOk<IOdictionary>(true))
        {
            FatalIOErrorInFunction(dict)
                << "The " << modelName << " (" << dict.name() << ") has no"
                << " entry 'nu', so it reads the kinematic viscosity 'nu'"
                << " from " << io.objectPath() << ", but there is no such"
                << " file." << nl
                << "    Give 'nu <value>;' (uniform, m2/s) or 'nu <field>;'"
                << " in " << dict.name() << nl << exit(FatalIOError);
        }
        const IOdictionary transport(io);
        if (!transport.found("nu"))
        {
            FatalIOErrorInFunction(dict)
                << "The " << modelName << " (" << dict.name() << ") has no"
                << " entry 'nu', and " << transport.objectPath()
                << " has no entry 'nu' either (the kinematic viscosity)."
                << nl << "    Give 'nu <value>;' (uniform, m2/s) or"
                << " 'nu <field>;' in " << dict.name() << nl
                << exit(FatalIOError);
        }
        nu = caseChecks::withTrapsHeld
        (
            [&]() { return dimensionedScalar("nu", dimViscosity, transport); }
        ).value();
        source = "entry 'nu' in " + transport.objectPath();
    }

    if (!(nu > 0) || !std::isfinite(nu))
    {
        FatalIOErrorInFunction(dict)
            << "The kinematic viscosity nu = " << nu << " (" << source.c_str()
            << ") of the " << modelName << " must be positive and finite"
            << nl << exit(FatalIOError);
    }
    Info<< "    nu " << nu << " (uniform, " << source.c_str() << ")" << endl;
    return nu;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::coagulationKernels::localSaffmanTurner::localSaffmanTurner
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    // The algorithms are built with a saffmanTurner kernel for its majorant
    // layout; every cell step is given the cell's own (cellKernel)
    coagulationKernel
    (
        readCoefficient(dict),
        coag::makeKernel("saffmanTurner", 1)
    ),
    epsilon_
    (
        flowFields::of(mesh).cellField
        (
            dict,
            modelName,
            "epsilon",
            dict.getOrDefault<word>("epsilon", "epsilon"),
            dimensionSet(0, 2, -3, 0, 0),
            true
        )
    ),
    nu_(nullptr),
    nu_uniform_(0),
    dict_(dict),
    epsilonVersion_(-1),
    nuVersion_(-1)
{
    // 'nu': a field's name, or a value (with or without dimensions)
    if (dict.found("nu") && dict.lookup("nu")[0].isWord())
    {
        nu_ = &flowFields::of(mesh).cellField
        (
            dict,
            modelName,
            "nu",
            dict.get<word>("nu"),
            dimViscosity,
            true
        );
        Info<< "    nu from field " << nu_->name() << ": "
            << gMin((*nu_)().primitiveField()) << " to "
            << gMax((*nu_)().primitiveField()) << endl;
    }
    else
    {
        nu_uniform_ = uniformNu(dict, mesh);
    }

    Info<< "    epsilon from field " << epsilon_.name() << ": "
        << gMin(epsilon_().primitiveField()) << " to "
        << gMax(epsilon_().primitiveField()) << endl;
    const Pair<scalar> K0range = makeCellKernels();
    Info<< "    K0 = coefficient sqrt(epsilon/nu) from "
        << returnReduce(K0range.first(), minOp<scalar>()) << " to "
        << returnReduce(K0range.second(), maxOp<scalar>()) << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::Pair<Foam::scalar>
Foam::coagulation::coagulationKernels::localSaffmanTurner::makeCellKernels()
{
    const scalarField& epsilon = epsilon_().primitiveField();
    cellKernels().clear();
    cellKernels().reserve(epsilon.size());
    scalar lowest = GREAT, highest = 0;
    forAll(epsilon, celli)
    {
        const scalar nuc = nu_ ? (*nu_)().primitiveField()[celli] : nu_uniform_;
        const scalar K0c = K0()*std::sqrt(epsilon[celli]/nuc);
        if (!(K0c > 0) || !std::isfinite(K0c))
        {
            FatalIOErrorInFunction(dict_)
                << "The " << modelName << " in " << dict_.name() << " gives "
                << "cell " << celli << " the prefactor coefficient"
                << " sqrt(epsilon/nu) = " << K0c << " (epsilon " << epsilon[celli]
                << ", nu " << nuc << ") at t = " << epsilon_().time().value()
                << ": it must be positive and finite" << nl
                << exit(FatalIOError);
        }
        lowest = min(lowest, K0c);
        highest = max(highest, K0c);
        cellKernels().push_back(coag::makeKernel("saffmanTurner", K0c));
    }
    epsilonVersion_ = epsilon_.version();
    nuVersion_ = nu_ ? nu_->version() : 0;

    return Pair<scalar>(lowest, highest);
}


bool Foam::coagulation::coagulationKernels::localSaffmanTurner::correct()
{
    if
    (
        epsilon_.version() != epsilonVersion_
     || (nu_ && nu_->version() != nuVersion_)
    )
    {
        makeCellKernels();
        return true;
    }
    return false;
}


// ************************************************************************* //
