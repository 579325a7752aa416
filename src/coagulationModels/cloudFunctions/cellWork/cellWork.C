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
namespace coagulation
{
namespace cloudFunctions
{
    defineTypeNameAndDebug(cellWork, 0);
    addToRunTimeSelectionTable(cloudFunction, cellWork, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::cloudFunctions::cellWork::cellWork
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
    eventCost_(dict.getOrDefault<scalar>("eventCost", 1)),
    fit_(),
    transportSeconds_(0),
    moves_(0),
    last_(std::chrono::steady_clock::now())
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
    cloud.stepper().timeCells(true);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::cloudFunctions::cellWork::postCellStep()
{
    const cellStepper& step = cloud_.stepper();
    forAll(sum_, celli)
    {
        sum_[celli] += step.work(celli, eventCost_);

        // seconds = a events + b particles + c stepped, least squares
        fit_.add
        (
            step.events(celli),
            scalar(step.particles(celli)),
            step.stepped(celli) ? 1 : 0,
            step.seconds(celli)
        );
    }
    last_ = std::chrono::steady_clock::now();
}


void Foam::coagulation::cloudFunctions::cellWork::postMove
(
    const transportModel::outflow&
)
{
    const std::chrono::steady_clock::time_point now =
        std::chrono::steady_clock::now();
    transportSeconds_ += std::chrono::duration<double>(now - last_).count();
    moves_ += cloud_.size();
    last_ = now;
}


void Foam::coagulation::cloudFunctions::cellWork::postStep()
{
    // A split step may hold two cell steps (StrangSAS): the work of both
    ++steps_;

    // The field is an AUTO_WRITE object: set before the time writes it,
    // from the steps since the last write
    if (cloud_.mesh().time().writeTime())
    {
        work_.primitiveFieldRef() = sum_/scalar(steps_);
        work_.correctBoundaryConditions();
        sum_ = Zero;
        steps_ = 0;
        reportFit();
    }
    last_ = std::chrono::steady_clock::now();
}


void Foam::coagulation::cloudFunctions::cellWork::reportFit()
{
    const coag::CostFit::Result r = fit_.solve();
    const scalar m = moves_ > 0 ? transportSeconds_/moves_ : 0;
    const coag::CostFit::Relative q = coag::CostFit::relative(r, m);
    if (r.determined)
    {
        Info<< "Cloud function cellWork: cost fit over " << label(fit_.count())
            << " cell steps (this processor): an event " << 1e9*r.coef[0]
            << " +- " << 1e9*r.stdErr[0] << " ns, a particle in the cell step "
            << 1e9*r.coef[1] << " +- " << 1e9*r.stdErr[1] << " ns, a cell's"
            << " visit " << 1e6*r.coef[2] << " +- " << 1e6*r.stdErr[2]
            << " us; a move " << 1e9*m << " ns" << nl;
        if (q.determined)
        {
            Info<< "    eventCost = " << q.eventCost << " +- " << q.eventCostErr
                << " (in use " << eventCost_ << "), a cell's visit = " << q.visit
                << " +- " << q.visitErr << " particles (in use "
                << cellStepper::cellCost << ")" << endl;
        }
        else
        {
            Info<< "    no eventCost from it: nothing moved, or a particle's"
                << " share of the cell step is fitted near minus a move"
                << " (in use " << eventCost_ << ")" << endl;
        }
    }
    else
    {
        Info<< "Cloud function cellWork: no cost fit over "
            << label(fit_.count()) << " cell steps (this processor): the"
            << " cells' events, particles and visits do not vary"
            << " independently enough" << endl;
    }
    fit_.clear();
    transportSeconds_ = 0;
    moves_ = 0;
}


// ************************************************************************* //
