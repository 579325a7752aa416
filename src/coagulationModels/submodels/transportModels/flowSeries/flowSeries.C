/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "flowSeries.H"
#include "caseChecks.H"
#include "pointFields.H"
#include "Time.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::autoPtr<Foam::volVectorField> Foam::coagulation::flowSeries::read
(
    const label i
) const
{
    const IOobject io
    (
        "U",
        case_/times_[i].name(),
        mesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    autoPtr<volVectorField> U(new volVectorField(io, mesh_));

    // The split step's Courant limit holds for every field of the series
    const scalar deltaT = mesh_.time().deltaTValue();
    const scalar Co = caseChecks::maxCourant(*U, deltaT);
    if (Co > 1 + 1e-9)
    {
        FatalIOErrorInFunction(mesh_.time().controlDict())
            << "Entry 'deltaT' = " << deltaT << " in "
            << mesh_.time().controlDict().name() << " gives the flow series'"
            << " velocity " << io.objectPath() << " a Courant number of " << Co
            << " > 1: particles would cross cells whose cell step they never"
            << " see." << nl << "    Set deltaT <= " << deltaT/Co << nl
            << exit(FatalIOError);
    }
    return U;
}


void Foam::coagulation::flowSeries::checkGaps() const
{
    // The velocity is linear between written times: a gap much longer than
    // the series' spacing elsewhere (writes purged by purgeWrite, a run
    // restarted later) would interpolate straight across changes the flow
    // made in it. The spacing is the lower median of the intervals; a gap
    // more than maxGapRatio of them is refused unless 'maxGap' allows it
    if (dict_.found("maxGap") && !(dict_.get<scalar>("maxGap") > 0))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'maxGap' = " << dict_.get<scalar>("maxGap") << " in "
            << dict_.name() << " must be a time > 0 [s]" << nl
            << exit(FatalIOError);
    }
    const label n = times_.size() - 1;
    if (n < 2)
    {
        return;
    }
    List<scalar> gaps(n);
    forAll(gaps, i)
    {
        gaps[i] = times_[i + 1].value() - times_[i].value();
    }
    List<scalar> sorted(gaps);
    Foam::sort(sorted);
    const scalar spacing = sorted[(n - 1)/2];
    const scalar maxGap =
        dict_.getOrDefault<scalar>("maxGap", maxGapRatio*spacing);
    forAll(gaps, i)
    {
        if (gaps[i] > maxGap*(1 + 1e-9))
        {
            FatalIOErrorInFunction(dict_)
                << "Entry 'flowSeries' in " << dict_.name() << ": the flow"
                << " case " << case_ << " has no written time between "
                << times_[i].name() << " and " << times_[i + 1].name()
                << ", a gap of " << gaps[i] << " s where its times are "
                << spacing << " s apart elsewhere: the velocity would be"
                << " interpolated straight across the gap." << nl
                << "    Write the flow at even intervals (no purgeWrite), or"
                << " accept the gap with 'maxGap " << gaps[i] << ";' in "
                << dict_.name() << nl << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::flowSeries::flowSeries
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    mesh_(mesh),
    dict_(dict),
    case_(dict.get<fileName>("flowSeries")),
    times_()
{
    const Time& runTime = mesh.time();
    case_.expand();
    if (!case_.isAbsolute())
    {
        case_ = runTime.globalPath()/case_;
    }
    case_.clean();
    if (Pstream::parRun())
    {
        // A decomposed run reads the flow case decomposed the same way
        case_ = case_/("processor" + Foam::name(Pstream::myProcNo()));
    }
    if (!isDir(case_))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'flowSeries' in " << dict.name() << " names the flow"
            << " case " << case_ << ", which is not a folder" << nl
            << exit(FatalIOError);
    }

    // The same mesh: the same points
    const pointIOField points
    (
        IOobject
        (
            "points",
            case_/"constant"/"polyMesh",
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    const scalar tol = 1e-9*mag(mesh.bounds().span());
    if
    (
        points.size() != mesh.nPoints()
     || (points.size() && max(mag(points - mesh.points())) > tol)
    )
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'flowSeries' in " << dict.name() << ": the flow case "
            << case_ << " is on another mesh (" << points.size()
            << " points in " << points.objectPath() << ", this case has "
            << mesh.nPoints() << (points.size() == mesh.nPoints()
            ? " at other places" : "") << ")." << nl
            << "    Run the flow on this case's mesh, or map its times with"
            << " mapFields" << nl << exit(FatalIOError);
    }

    // The written times that cover the run, each with a U
    DynamicList<instant> written;
    for (const instant& t : Time::findTimes(case_))
    {
        if (t.name() != "constant")
        {
            written.append(t);
        }
    }
    const instantList all(std::move(written));
    const scalar start = runTime.startTime().value();
    const scalar end = max(runTime.endTime().value(), start);
    const scalar small = 1e-6*runTime.deltaTValue();
    label first = -1, last = -1;
    forAll(all, i)
    {
        if (all[i].value() <= start + small)
        {
            first = i;
        }
        if (last < 0 && all[i].value() >= end - small)
        {
            last = i;
        }
    }
    if (first < 0 || last < 0)
    {
        // A flow run decomposed and never reconstructed holds its times in
        // its processor folders alone
        const bool decomposed =
            !Pstream::parRun() && isDir(case_/"processor0");
        FatalIOErrorInFunction(dict)
            << "Entry 'flowSeries' in " << dict.name() << ": the flow case "
            << case_ << " has written times "
            << (all.size() ? all.first().name() + " to " + all.last().name()
                           : word("none"))
            << ", which do not cover this run's " << start << " to " << end
            << nl;
        if (decomposed)
        {
            FatalIOError
                << "    The flow case was run decomposed: its times are in"
                << " its processor* folders. Run reconstructPar in it, or run"
                << " this case decomposed the same way (decomposePar,"
                << " -parallel)" << nl;
        }
        FatalIOError << exit(FatalIOError);
    }
    times_ = instantList(SubList<instant>(all, last - first + 1, first));

    // Decomposed: every processor's folder holds the same times
    if (Pstream::parRun())
    {
        const scalar t0 = times_.first().value(), t1 = times_.last().value();
        const label n = times_.size();
        if
        (
            returnReduce(n, minOp<label>()) != returnReduce(n, maxOp<label>())
         || returnReduce(t0, minOp<scalar>()) != returnReduce(t0, maxOp<scalar>())
         || returnReduce(t1, minOp<scalar>()) != returnReduce(t1, maxOp<scalar>())
        )
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'flowSeries' in " << dict.name() << ": the flow"
                << " case's processor folders hold different written times"
                << " (this processor's " << case_ << ": " << n << " from "
                << times_.first().name() << " to " << times_.last().name()
                << ")." << nl << "    Decompose every time of the flow case"
                << nl << exit(FatalIOError);
        }
    }
    checkGaps();
    if (!holds("U", "transport"))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'flowSeries' in " << dict.name() << ": the flow case "
            << case_ << " has no U in its written times " << times_.first().name()
            << " to " << times_.last().name() << nl << exit(FatalIOError);
    }
    Info<< "Transport: the velocity of the flow case " << case_ << ", "
        << times_.size() << " written times from " << times_.first().name()
        << " to " << times_.last().name() << ", linear in time between them"
        << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::coagulation::flowSeries::holds
(
    const word& name,
    const word& reader
) const
{
    const dictionary& dict = dict_;
    label n = 0;
    for (const instant& t : times_)
    {
        n += isFile(case_/t.name()/name) || isFile(case_/t.name()/name + ".gz");
    }
    if (n > 0 && n < times_.size())
    {
        for (const instant& t : times_)
        {
            if (!isFile(case_/t.name()/name) && !isFile(case_/t.name()/name + ".gz"))
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'flowSeries' in " << dict.name() << ": the flow"
                    << " case's time " << case_/t.name() << " has no " << name
                    << " (read by the " << reader << "): the series has a gap"
                    << " between "
                    << times_.first().name() << " and "
                    << times_.last().name() << nl << exit(FatalIOError);
            }
        }
    }
    // Decomposed: every processor's folders hold it, or none do (the
    // fields' sources, and what is collective on them, are the same on all)
    if (returnReduce(n, minOp<label>()) != returnReduce(n, maxOp<label>()))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'flowSeries' in " << dict.name() << ": the flow case's"
            << " processor folders do not all hold " << name << " (read by the "
            << reader << "): this processor's " << case_ << " holds it in " << n
            << " of " << times_.size() << " times." << nl
            << "    Decompose every field of the flow case" << nl
            << exit(FatalIOError);
    }
    return n > 0;
}


void Foam::coagulation::flowSeries::bracket
(
    const scalar t,
    label& a,
    label& b,
    scalar& theta
) const
{
    // The written times a <= t <= b around t (a == b at a written time)
    const scalar small = 1e-6*mesh_.time().deltaTValue();
    a = -1;
    for (label i = times_.size() - 1; i >= 0; --i)
    {
        if (times_[i].value() <= t + small)
        {
            a = i;
            break;
        }
    }
    b = a;
    if (a >= 0 && times_[a].value() < t - small)
    {
        b = a + 1;
    }
    if (a < 0 || b >= times_.size())
    {
        FatalErrorInFunction
            << "The flow series of " << case_ << " has no written times"
            << " around t = " << t << " (it covers " << times_.first().name()
            << " to " << times_.last().name() << ")" << nl << exit(FatalError);
    }
    theta =
        b == a
      ? 0
      : (t - times_[a].value())/(times_[b].value() - times_[a].value());
}


void Foam::coagulation::flowSeries::set(volVectorField& U, const scalar t)
{
    label a = -1, b = -1;
    scalar theta = 0;
    bracket(t, a, b, theta);

    hold(a, b, a_, b_, Ua_, Ub_, [this](const label i) { return read(i); });

    const volVectorField& Ua = *Ua_;
    if (b == a)
    {
        U.primitiveFieldRef() = Ua.primitiveField();
        forAll(U.boundaryField(), patchi)
        {
            U.boundaryFieldRef()[patchi] == Ua.boundaryField()[patchi];
        }
    }
    else
    {
        const volVectorField& Ub = *Ub_;
        U.primitiveFieldRef() =
            Ua.primitiveField()
          + theta*(Ub.primitiveField() - Ua.primitiveField());
        forAll(U.boundaryField(), patchi)
        {
            U.boundaryFieldRef()[patchi] ==
                Ua.boundaryField()[patchi]
              + theta*(Ub.boundaryField()[patchi] - Ua.boundaryField()[patchi]);
        }
    }
    ++version_;
}


// ************************************************************************* //
