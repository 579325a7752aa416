/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "caseChecks.H"
#include "IFstream.H"
#include "fvMesh.H"
#include "fvc.H"
#include "emptyPolyPatch.H"
#include "surfaceFields.H"

#include <cctype>
#include <fstream>
#include <iterator>
#include <string>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- Whether the file dict was read from refers to key as a variable, $key or
//  ${key}: an entry the file uses so is there to be expanded, not a setting
bool isVariable(const Foam::dictionary& dict, const Foam::word& key)
{
    std::ifstream is(dict.topDict().name());
    const std::string text
    (
        (std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>()
    );
    for (const std::string& ref : {"$" + key, "${" + key})
    {
        for
        (
            std::size_t pos = text.find(ref);
            pos != std::string::npos;
            pos = text.find(ref, pos + 1)
        )
        {
            const std::size_t end = pos + ref.size();
            if
            (
                end == text.size()
             || !(std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_')
            )
            {
                return true;
            }
        }
    }
    return false;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * //

void Foam::coagulation::caseChecks::keywords
(
    const dictionary& dict,
    const wordList& valid
)
{
    for (const entry& e : dict)
    {
        if (!valid.found(e.keyword()) && !isVariable(dict, e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown entry '" << e.keyword() << "' in "
                << dict.name() << nl
                << "    Valid entries are " << valid << " (and variables:"
                << " an entry the file uses as $name)" << nl
                << exit(FatalIOError);
        }
    }
}


void Foam::coagulation::caseChecks::movedEntries
(
    const dictionary& dict,
    std::initializer_list<std::pair<const char*, const char*>> moved
)
{
    for (const auto& m : moved)
    {
        if (dict.found(m.first, keyType::LITERAL))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << m.first << "' in " << dict.name()
                << " is no longer read here: give it as " << m.second
                << " in " << dict.topDict().name() << nl
                << exit(FatalIOError);
        }
    }
}


Foam::scalar Foam::coagulation::caseChecks::positive
(
    const dictionary& dict,
    const word& key
)
{
    const scalar value = dict.get<scalar>(key);
    if (!(value > 0) || !std::isfinite(value))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << value << " in " << dict.name()
            << " must be positive and finite" << nl << exit(FatalIOError);
    }
    return value;
}


Foam::label Foam::coagulation::caseChecks::stepsPer
(
    const dictionary& dict,
    const word& key,
    const scalar interval,
    const scalar deltaT
)
{
    // Rounded in scalars first: a huge interval must not overflow a label
    const scalar steps = std::round(interval/deltaT);
    if
    (
        !(steps >= 1) || !(steps < scalar(labelMax))
     || mag(steps*deltaT - interval) > 1e-6*interval
    )
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << interval << " in " << dict.name()
            << " must be a positive multiple of the split step " << deltaT
            << " (at most " << labelMax << " steps)" << nl
            << exit(FatalIOError);
    }
    return label(steps);
}


Foam::scalar Foam::coagulation::caseChecks::nonNegative
(
    const dictionary& dict,
    const word& key
)
{
    const scalar value = dict.get<scalar>(key);
    if (!(value >= 0) || !std::isfinite(value))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << value << " in " << dict.name()
            << " must be finite and not negative" << nl << exit(FatalIOError);
    }
    return value;
}


Foam::autoPtr<Foam::volScalarField> Foam::coagulation::caseChecks::cellField
(
    const dictionary& dict,
    const word& model,
    const word& entry,
    const word& fieldName,
    const fvMesh& mesh,
    const dimensionSet& dims,
    const bool positive
)
{
    IOobject io
    (
        fieldName,
        mesh.time().timeName(),
        mesh,
        IOobject::MUST_READ,
        IOobject::AUTO_WRITE
    );
    if (!io.typeHeaderOk<volScalarField>(true))
    {
        FatalIOErrorInFunction(dict)
            << "The " << model << " (" << dict.name() << ") reads the field '"
            << fieldName << "' (entry '" << entry << "'), but there is no file "
            << io.objectPath() << nl
            << "    Put the field in the start time, or name another one"
            << nl << exit(FatalIOError);
    }

    autoPtr<volScalarField> fieldPtr
    (
        withTrapsHeld
        (
            [&]() { return autoPtr<volScalarField>::New(io, mesh); }
        )
    );
    const volScalarField& f = *fieldPtr;

    if (f.dimensions() != dims)
    {
        FatalIOErrorInFunction(dict)
            << "Field '" << fieldName << "' in " << f.objectPath()
            << " (the " << model << " of " << dict.name() << ") has dimensions "
            << f.dimensions() << "; it must have " << dims << nl
            << exit(FatalIOError);
    }

    forAll(f, celli)
    {
        const scalar v = f[celli];
        if (!std::isfinite(v) || !(v >= 0) || (positive && !(v > 0)))
        {
            FatalIOErrorInFunction(dict)
                << "Field '" << fieldName << "' in " << f.objectPath()
                << " (the " << model << " of " << dict.name() << ") has the "
                << (std::isfinite(v) ? (v < 0 ? "negative " : "") : "non-finite ")
                << "value " << v << " in cell " << celli << "; it must be "
                << (positive ? "positive" : "finite and not negative")
                << " in every cell" << nl << exit(FatalIOError);
        }
    }

    return fieldPtr;
}


void Foam::coagulation::caseChecks::noDuplicates(const IOdictionary& dict)
{
    // The top-level read (IOdictionary, operator>>) resets the input mode to
    // merge; dictionary::read does not, so the scan below reads the file as
    // "#inputMode error" does: a second entry of a key in one dictionary is a
    // FatalIOError naming it, the file and the line
    IFstream is(dict.objectPath());
    if (!is.good())
    {
        return;   // read from elsewhere (a stream, the master): checked there
    }
    const entry::inputMode saved = entry::globalInputMode;
    entry::globalInputMode = entry::inputMode::ERROR;
    dictionary scan;
    scan.read(is, false);
    entry::globalInputMode = saved;
}


void Foam::coagulation::caseChecks::cellVolumes(const fvMesh& mesh)
{
    // Far below the mean: a collapsed or inverted cell (its computed volume
    // is round-off, or negative), whose events per unit volume would be
    // without bound and in which no particle could be tracked
    const scalarField& V = mesh.V().field();
    const scalar mean =
        gSum(V)/max(returnReduce(V.size(), sumOp<label>()), label(1));
    forAll(V, celli)
    {
        if (!(V[celli] > 1e-12*mean))
        {
            FatalErrorInFunction
                << "Cell " << celli << " (centre " << mesh.C()[celli]
                << ") of the mesh in "
                << mesh.time().path()/mesh.pointsInstance()/polyMesh::meshSubDir
                << " has volume " << V[celli] << ", the mean is " << mean
                << ": a zero-volume or inverted cell." << nl
                << "    Run checkMesh on the case and repair the mesh" << nl
                << exit(FatalError);
        }
    }
}


void Foam::coagulation::caseChecks::velocity(const volVectorField& U)
{
    if (U.dimensions() != dimVelocity)
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__, U.objectPath(), -1, -1
        )   << "Field U in " << U.objectPath() << " has dimensions "
            << U.dimensions() << "; a velocity has " << dimVelocity
            << " (m/s)." << nl
            << "    Correct the 'dimensions' entry of the file" << nl
            << exit(FatalIOError);
    }

    auto check = [&U](const vectorField& values, const word& where)
    {
        forAll(values, i)
        {
            const vector& u = values[i];
            if
            (
                !std::isfinite(u.x()) || !std::isfinite(u.y())
             || !std::isfinite(u.z())
            )
            {
                FatalErrorInFunction
                    << "Field " << U.objectPath() << " holds " << u
                    << " in " << where << " (index " << i << "): the carrier"
                    << " velocity must be finite everywhere" << nl
                    << exit(FatalError);
            }
        }
    };

    check(U.primitiveField(), "the internalField");
    forAll(U.boundaryField(), patchi)
    {
        check
        (
            U.boundaryField()[patchi],
            "boundaryField " + U.mesh().boundaryMesh()[patchi].name()
        );
    }
}


void Foam::coagulation::caseChecks::emptyPatches(const fvMesh& mesh)
{
    // In a 1-D/2-D mesh every cell has two empty faces normal to each empty
    // direction. An empty patch with any other count is not a reduced-D
    // direction but a lost boundary (faces that should be an outlet or wall)
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    const vectorField& Sf = mesh.faceAreas();

    Vector<label> nFaces(Zero);
    wordList names(3);
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        if (!isA<emptyPolyPatch>(pp))
        {
            continue;
        }
        forAll(pp, i)
        {
            const vector& s = Sf[pp.start() + i];
            const direction d =
                mag(s.x()) >= mag(s.y()) && mag(s.x()) >= mag(s.z()) ? 0
              : mag(s.y()) >= mag(s.z()) ? 1 : 2;
            ++nFaces[d];
            names[d] = pp.name();
        }
    }
    reduce(nFaces, sumOp<Vector<label>>());
    const label nCells = returnReduce(mesh.nCells(), sumOp<label>());

    for (direction d = 0; d < 3; ++d)
    {
        if (nFaces[d] != 0 && nFaces[d] != 2*nCells)
        {
            FatalErrorInFunction
                << "The empty patch '" << names[d] << "' of "
                << mesh.boundaryMesh().objectPath() << " holds " << nFaces[d]
                << " faces normal to the " << vector::componentNames[d]
                << " direction, but a 1-D/2-D mesh of " << nCells
                << " cells has 2 per cell (" << 2*nCells << ")." << nl
                << "    Faces that belong to an outlet or a wall have lost"
                << " their patch (blockMesh puts faces missing from 'boundary'"
                << " into the empty 'defaultFaces'): particles would vanish"
                << " through them. Give them a patch of type patch or wall."
                << nl << exit(FatalError);
        }
    }
}


Foam::scalar Foam::coagulation::caseChecks::maxCourant
(
    const volVectorField& U,
    const scalar deltaT
)
{
    const fvMesh& mesh = U.mesh();
    const surfaceScalarField phi(fvc::interpolate(U) & mesh.Sf());
    const scalarField sumPhi
    (
        fvc::surfaceSum(mag(phi))().primitiveField()
    );
    return 0.5*gMax(sumPhi/mesh.V().field())*deltaT;
}


void Foam::coagulation::caseChecks::courant
(
    const volVectorField& U,
    const label stepInterval
)
{
    const Time& runTime = U.time();
    const scalar deltaT = runTime.deltaTValue();
    const scalar Co = maxCourant(U, stepInterval*deltaT);

    Info<< "Courant number of the split step: max " << Co << nl << endl;

    if (Co > 1 + 1e-9)
    {
        const string steps =
            stepInterval > 1
          ? " (" + Foam::name(stepInterval) + " time steps a split step)"
          : "";
        // The function object's split step is executeInterval time steps
        // of the flow solver's deltaT: fewer time steps a split step first
        const label maxInterval =
            label(std::floor(stepInterval*(1 + 1e-9)/Co));
        const string advice =
            stepInterval > 1 && maxInterval >= 1
          ? "Set the function object's executeInterval <= "
          + Foam::name(maxInterval)
          : "Set deltaT <= " + Foam::name(deltaT*stepInterval/Co)
          + (stepInterval > 1 ? " and executeInterval 1" : "");
        FatalIOErrorInFunction(runTime.controlDict())
            << "Entry 'deltaT' = " << deltaT << " in "
            << runTime.controlDict().name() << steps.c_str()
            << " gives a Courant number of "
            << Co << " > 1: particles would cross cells whose cell step they"
            << " never see, and inflow would skip the first cells." << nl
            << "    " << advice.c_str() << nl
            << exit(FatalIOError);
    }
}


void Foam::coagulation::caseChecks::timeControls(const Time& runTime)
{
    // The split step is of the fixed deltaT (the statistics' sample times,
    // the restarts and the Courant check assume it): a Courant-limited step
    // that a transient solver's user sets by habit is refused, not ignored
    if (runTime.controlDict().getOrDefault<bool>("adjustTimeStep", false))
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "Entry 'adjustTimeStep' is on in "
            << runTime.controlDict().name() << ": coagulationFoam takes"
            << " fixed steps of deltaT." << nl
            << "    Remove the entry (or set it to no) and choose deltaT so"
            << " that the Courant number stays below 1 (the solver checks it)"
            << nl << exit(FatalIOError);
    }

    const scalar deltaT = runTime.deltaTValue();
    const scalar start = runTime.startTime().value();
    const scalar end = runTime.endTime().value();

    // Time::run() steps while t < endTime - deltaT/2: a run with
    // endTime - startTime in (0, deltaT/2] would end at once
    if (end > start && end - start <= 0.5*deltaT)
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "Entry 'endTime' = " << end << " in "
            << runTime.controlDict().name() << " is less than half a step"
            << " (deltaT = " << deltaT << ") after the start time " << start
            << ": the run would take no step." << nl
            << "    Set endTime >= " << start + deltaT << " or a smaller deltaT"
            << nl << exit(FatalIOError);
    }
}


// ************************************************************************* //
