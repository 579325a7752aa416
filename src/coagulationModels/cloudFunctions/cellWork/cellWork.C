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
    eventCost_(dict.getOrDefault<scalar>("eventCost", 1)),
    normal_(Zero),
    rhs_(Zero),
    sumSquares_(0),
    transportSeconds_(0),
    moves_(0),
    fitted_(0),
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

void Foam::cloudFunctions::cellWork::postCellStep()
{
    const cellStepper& step = cloud_.stepper();
    forAll(sum_, celli)
    {
        sum_[celli] += step.work(celli, eventCost_);

        // seconds = a events + b particles + c stepped, least squares
        const vector x
        (
            step.events(celli),
            scalar(step.particles(celli)),
            step.stepped(celli) ? 1 : 0
        );
        const scalar t = step.seconds(celli);
        normal_ += x*x;
        rhs_ += t*x;
        sumSquares_ += t*t;
    }
    fitted_ += sum_.size();
    ++steps_;
    last_ = std::chrono::steady_clock::now();

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
}


void Foam::cloudFunctions::cellWork::postMove(const transportModel::outflow&)
{
    const std::chrono::steady_clock::time_point now =
        std::chrono::steady_clock::now();
    transportSeconds_ += std::chrono::duration<double>(now - last_).count();
    moves_ += cloud_.size();
    last_ = now;
}


void Foam::cloudFunctions::cellWork::postStep()
{
    last_ = std::chrono::steady_clock::now();
}


void Foam::cloudFunctions::cellWork::reportFit()
{
    // Determined only with events, particles and stepped cells that vary
    // independently over the cells (det well away from zero)
    const scalar scale = mag(normal_.xx()*normal_.yy()*normal_.zz());
    const scalar d = det(normal_);
    if (moves_ > 0 && fitted_ > 3 && scale > 0 && mag(d) > 1e-9*scale)
    {
        // Least squares: coefficients inv(N) r, their covariance s^2 inv(N)
        // with s^2 the residuals' variance (sum t^2 - coef . r)/(n - 3)
        const tensor Ninv = inv(normal_);
        const vector abc = Ninv & rhs_;
        const scalar s2 = max(sumSquares_ - (abc & rhs_), scalar(0))/(fitted_ - 3);
        const tensor cov = s2*Ninv;
        const scalar m = transportSeconds_/moves_;
        const scalar p = max(m + abc.y(), VSMALL);
        // eventCost a/p and the visit c/p, p = m + b; first-order errors
        // with m as measured
        const scalar e = abc.x()/p;
        const scalar eErr = Foam::sqrt(max
        (
            cov.xx()/sqr(p) + sqr(e/p)*cov.yy() - 2*e/sqr(p)*cov.xy(),
            scalar(0)
        ));
        const scalar v = abc.z()/p;
        const scalar vErr = Foam::sqrt(max
        (
            cov.zz()/sqr(p) + sqr(v/p)*cov.yy() - 2*v/sqr(p)*cov.yz(),
            scalar(0)
        ));
        Info<< "Cloud function cellWork: cost fit over " << fitted_
            << " cell steps (this processor): an event " << 1e9*abc.x()
            << " +- " << 1e9*Foam::sqrt(cov.xx()) << " ns, a particle in the"
            << " cell step " << 1e9*abc.y() << " +- "
            << 1e9*Foam::sqrt(cov.yy()) << " ns, a cell's visit "
            << 1e6*abc.z() << " +- " << 1e6*Foam::sqrt(cov.zz())
            << " us; a move " << 1e9*m << " ns" << nl
            << "    eventCost = " << e << " +- " << eErr << " (in use "
            << eventCost_ << "), a cell's visit = " << v << " +- " << vErr
            << " particles (in use " << cellStepper::cellCost << ")"
            << endl;
    }
    normal_ = Zero;
    rhs_ = Zero;
    sumSquares_ = 0;
    transportSeconds_ = 0;
    moves_ = 0;
    fitted_ = 0;
}


// ************************************************************************* //
