/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "coagulationKernel.H"
#include "error.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
    defineTypeNameAndDebug(coagulationKernel, 0);
    defineRunTimeSelectionTable(coagulationKernel, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::coagulationKernel::coagulationKernel
(
    const dictionary& dict,
    const std::string& coreName
)
:
    K0_(0),
    core_(),
    cellKernels_()
{
    caseChecks::keywords(dict, {"type", "K0"});
    K0_ = dict.get<scalar>("K0");
    if (!(K0_ > 0) || !std::isfinite(K0_))
    {
        FatalIOErrorInFunction(dict)
            << "Kernel coefficient K0 = " << K0_ << " in " << dict.name()
            << " must be positive and finite (for no coagulation:"
            << " 'type none;')" << nl
            << exit(FatalIOError);
    }

    core_ = coag::makeKernel(coreName, K0_);
}


Foam::coagulation::coagulationKernel::coagulationKernel
(
    const scalar K0,
    std::unique_ptr<coag::CoagulationKernel> core
)
:
    K0_(K0),
    core_(std::move(core)),
    cellKernels_()
{}


// * * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::coagulation::coagulationKernel>
Foam::coagulation::coagulationKernel::New
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    const word kernelType(dict.get<word>("type"));

    Info<< "Selecting coagulation kernel " << kernelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(kernelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "coagulationKernel",
            kernelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<coagulationKernel>(cstrIter()(dict, mesh));
}


// ************************************************************************* //
