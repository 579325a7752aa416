/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "cellWork.H"
#include "coagulationCloud.H"
#include "caseChecks.H"
#include "zeroGradientFvPatchFields.H"
#include "addToRunTimeSelectionTable.H"
#include <cmath>

namespace Foam
{
namespace cloudFunctions
{
    defineTypeNameAndDebug(cellWork, 0);
    addToRunTimeSelectionTable(cloudFunction, cellWork, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cloudFunctions::cellWork::cellWork
(
    const word& name,
    const dictionary& dict,
    coagulationCloud& cloud
)
:
    cloudFunction(cloud),
    work_
    (
        IOobject
        (
            "coagulationWork",
            cloud.mesh().time().timeName(),
            cloud.mesh(),
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        cloud.mesh(),
        dimensionedScalar(dimless, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    sum_(cloud.mesh().nCells(), Zero),
    steps_(0),
    eventCost_(dict.getOrDefault<scalar>("eventCost", 1))
{
    caseChecks::keywords(dict, {"type", "eventCost"});
    if (!(eventCost_ >= 0) || !std::isfinite(eventCost_))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'eventCost' " << eventCost_ << " in " << dict.name()
            << ": must be finite and >= 0" << exit(FatalIOError);
    }
    Info<< "Cloud function " << name << ": the work per cell and step"
        << " (an event at " << eventCost_ << " of a particle),"
        << " written as " << work_.name() << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cloudFunctions::cellWork::postCellStep()
{
    const cellStepper& step = cloud_.stepper();
    forAll(sum_, celli)
    {
        sum_[celli] += step.work(celli, eventCost_);
    }
    ++steps_;

    // The field is an AUTO_WRITE object: set before the time writes it,
    // from the steps since the last write
    if (cloud_.mesh().time().writeTime())
    {
        work_.primitiveFieldRef() = sum_/scalar(steps_);
        work_.correctBoundaryConditions();
        sum_ = Zero;
        steps_ = 0;
    }
}


// ************************************************************************* //
