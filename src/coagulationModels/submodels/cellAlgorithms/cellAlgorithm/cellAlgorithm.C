/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "cellAlgorithm.H"
#include "coagulationKernel.H"
#include "error.H"

#include <stdexcept>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
    defineTypeNameAndDebug(cellAlgorithm, 0);
    defineRunTimeSelectionTable(cellAlgorithm, components);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::cellAlgorithm::cellAlgorithm
(
    const std::string& coreName,
    const coagulationKernel& kernel,
    const coag::InceptionModel& inception,
    const coag::NumberControl& control
)
:
    kernel_(kernel),
    inception_(inception),
    control_(control),
    core_(coag::makeCellAlgorithm(coreName, kernel.core(), inception, control))
{}


// * * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::coagulation::cellAlgorithm>
Foam::coagulation::cellAlgorithm::New
(
    const word& algorithmType,
    const dictionary& dict,
    const coagulationKernel& kernel,
    const coag::InceptionModel& inception,
    const coag::NumberControl& control
)
{
    auto cstrIter = componentsConstructorTablePtr_->cfind(algorithmType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "algorithm",
            algorithmType,
            *componentsConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    // The core refuses a kernel its pair sampler cannot hold (too many basis
    // functions, majorant terms, groups or stored columns: a large sum of
    // kernels): name the entry, not a C++ exception
    try
    {
        return autoPtr<cellAlgorithm>(cstrIter()(kernel, inception, control));
    }
    catch (const std::invalid_argument& e)
    {
        FatalIOErrorInFunction(dict)
            << "The kernel of entry 'kernel' in " << dict.name()
            << " does not fit algorithm " << algorithmType << ": " << e.what()
            << nl << exit(FatalIOError);
    }
    return autoPtr<cellAlgorithm>();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::autoPtr<Foam::coagulation::cellAlgorithm>
Foam::coagulation::cellAlgorithm::clone() const
{
    // The type is in the table: this object was constructed from it
    return autoPtr<cellAlgorithm>
    (
        componentsConstructorTablePtr_->cfind(this->type())()
        (
            kernel_, inception_, control_
        )
    );
}


// ************************************************************************* //
