/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "cloudFunction.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
    defineTypeNameAndDebug(cloudFunction, 0);
    defineRunTimeSelectionTable(cloudFunction, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::cloudFunction::cloudFunction(coagulationCloud& cloud)
:
    cloud_(cloud)
{}


// * * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::coagulation::cloudFunction>
Foam::coagulation::cloudFunction::New
(
    const word& name,
    const dictionary& dict,
    coagulationCloud& cloud
)
{
    const word functionType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(functionType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "cloudFunction",
            functionType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    Info<< "Cloud function " << name << " (" << functionType << ")" << endl;
    return autoPtr<cloudFunction>(cstrIter()(name, dict, cloud));
}


// ************************************************************************* //
