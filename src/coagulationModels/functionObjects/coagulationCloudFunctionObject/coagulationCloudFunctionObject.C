/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "coagulationCloudFunctionObject.H"
#include "caseChecks.H"
#include "restartPrecision.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
    defineTypeNameAndDebug(coagulationCloudFunctionObject, 0);

    addToRunTimeSelectionTable
    (
        functionObject,
        coagulationCloudFunctionObject,
        dictionary
    );
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::dictionary&
Foam::coagulation::coagulationCloudFunctionObject::checkRegion
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
{
    // OpenFOAM's base class looks the region up with a FatalError, which
    // functionObjectList turns into a warning and runs on without the
    // function object: an IOerror here stops the run instead
    const word region =
        dict.getOrDefault<word>("region", polyMesh::defaultRegion);
    if (!runTime.foundObject<fvMesh>(region))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'region' = " << region << " of function object "
            << name << " (type " << typeName << ") in " << dict.name()
            << ": the case has no mesh region of that name; it has "
            << runTime.sortedNames<fvMesh>() << nl
            << "    Name one of them, or remove the entry for the default"
            << " region " << polyMesh::defaultRegion << nl
            << exit(FatalIOError);
    }
    return dict;
}


void Foam::coagulation::coagulationCloudFunctionObject::checkTransient
(
    const dictionary& dict
) const
{
    const dictionary& ddt = mesh_.schemesDict().subDict("ddtSchemes");
    const word UName = dict.getOrDefault<word>("U", "U");
    for (const word& key : {word("ddt(" + UName + ")"), word("default")})
    {
        if (ddt.found(key))
        {
            const word scheme(ddt.lookup(key));
            if (scheme == "steadyState")
            {
                FatalIOErrorInFunction(dict)
                    << "Function object " << name() << " (type "
                    << typeName << ") in " << dict.name() << " needs a"
                    << " transient flow solver, but ddtSchemes/" << key
                    << " is steadyState in " << mesh_.schemesDict().name()
                    << ": a steady solver's iterations are not time steps."
                    << nl << "    Run coagulationFoam on the converged flow"
                    << " instead" << nl << exit(FatalIOError);
            }
            return;
        }
    }
}


void Foam::coagulation::coagulationCloudFunctionObject::checkStepInterval
(
    const dictionary& dict,
    const label interval
) const
{
    if (interval == 1)
    {
        return;
    }

    // The split steps end at the time indices that are multiples of the
    // interval (OpenFOAM's timeStep control): the start, every write and
    // the end must be among them, so that every written time holds the
    // particles of that time and a restart continues the same steps
    const dictionary& controlDict = time_.controlDict();
    const scalar deltaT = time_.deltaTValue();
    const word writeControl =
        controlDict.getOrDefault<word>("writeControl", "timeStep");
    const scalar writeInterval = controlDict.get<scalar>("writeInterval");
    label writeSteps = -1;
    if (writeControl == "timeStep")
    {
        writeSteps = label(std::round(writeInterval));
    }
    else if (writeControl == "runTime" || writeControl == "adjustableRunTime")
    {
        const scalar steps = std::round(writeInterval/deltaT);
        if (mag(steps*deltaT - writeInterval) < 1e-6*writeInterval)
        {
            writeSteps = label(steps);
        }
    }
    // (stopAt nextWrite, writeNow: endTime GREAT, the run ends at a write)
    const scalar endSteps =
        time_.endTime().value() > 0.5*GREAT
      ? 0
      : std::round((time_.endTime().value() - time_.startTime().value())/deltaT);
    const label startIndex = time_.timeIndex();
    // The first split step starts at the later of the start and timeStart
    scalar startSteps = 0;
    if (dict.found("timeStart"))
    {
        startSteps = std::round
        (
            max(dict.get<scalar>("timeStart") - time_.value(), scalar(0))/deltaT
        );
    }

    string why;
    if (writeSteps < 0 || writeSteps % interval != 0)
    {
        why =
            "writeControl " + writeControl + " and writeInterval "
          + Foam::name(writeInterval) + " in " + controlDict.name()
          + " do not write every multiple of " + Foam::name(interval)
          + " time steps of " + Foam::name(deltaT);
    }
    else if (endSteps > labelMax || label(endSteps) % interval != 0)
    {
        why =
            "the run from " + time_.timeName() + " to endTime "
          + Foam::name(time_.endTime().value()) + " is not a multiple of "
          + Foam::name(interval) + " time steps of " + Foam::name(deltaT);
    }
    else if (startIndex % interval != 0)
    {
        why =
            "the start time " + time_.timeName() + " has the time index "
          + Foam::name(startIndex) + ", not a multiple of "
          + Foam::name(interval);
    }
    else if (label(startSteps) % interval != 0)
    {
        why =
            "timeStart " + Foam::name(dict.get<scalar>("timeStart"))
          + " is " + Foam::name(label(startSteps)) + " time steps after the"
            " start time " + time_.timeName() + ", not a multiple of "
          + Foam::name(interval);
    }
    if (!why.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'executeInterval' = " << interval << " of function"
            << " object " << name() << " in " << dict.name() << ": "
            << why.c_str() << ". The population's split steps end every "
            << interval << " time steps, and every written time must hold"
            << " the particles of that time." << nl
            << "    Start, write and end the run at multiples of " << interval
            << " time steps, or set executeInterval 1" << nl
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::coagulationCloudFunctionObject::
coagulationCloudFunctionObject
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    functionObjects::fvMeshFunctionObject
    (
        name,
        runTime,
        checkRegion(name, runTime, dict)
    ),
    cloud_(),
    cloudObjects_()
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::coagulation::coagulationCloudFunctionObject::read
(
    const dictionary& dict
)
{
    fvMeshFunctionObject::read(dict);
    caseChecks::keywords
    (
        dict,
        {
            "type", "libs", "U", "region", "enabled", "log", "timeStart",
            "timeEnd", "executeControl", "executeInterval", "writeControl",
            "writeInterval"
        }
    );
    if (cloud_)
    {
        return true;
    }
    checkTransient(dict);

    // Every execution is a split step over the time since the last one
    // (executeInterval time steps), and the end checks the balances: the
    // function object runs every executeInterval time steps to the end of
    // the run
    const word control = dict.getOrDefault<word>("executeControl", "timeStep");
    const label interval = dict.getOrDefault<label>("executeInterval", 1);
    if (control != "timeStep" || interval < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << " (type " << typeName
            << ") in " << dict.name() << " has executeControl " << control
            << " and executeInterval " << interval << ": the population makes"
            << " a split step every executeInterval time steps of the solver,"
            << " so executeControl must be timeStep and executeInterval at"
            << " least 1" << nl << exit(FatalIOError);
    }
    checkStepInterval(dict, interval);
    if
    (
        dict.found("timeStart")
     && dict.get<scalar>("timeStart")
      > time_.endTime().value() - 0.5*time_.deltaTValue()
    )
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'timeStart' = " << dict.get<scalar>("timeStart")
            << " of function object " << name() << " in " << dict.name()
            << " is not before the run's endTime "
            << time_.endTime().value() << ": the population would never"
            << " make a step." << nl << "    Set timeStart before endTime,"
            << " or a later endTime" << nl << exit(FatalIOError);
    }
    if
    (
        dict.found("timeEnd")
     && dict.get<scalar>("timeEnd") < time_.endTime().value()
    )
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'timeEnd' = " << dict.get<scalar>("timeEnd") << " of"
            << " function object " << name() << " in " << dict.name()
            << " is before the run's endTime " << time_.endTime().value()
            << ": the population's balances are checked at the end of the"
            << " run." << nl << "    Remove the entry" << nl
            << exit(FatalIOError);
    }

    // One population a mesh: a second would write the same particle
    // files, samples and balances
    const word cloudName("coagulationCloud");
    if (mesh_.foundObject<coagulationCloud>(cloudName))
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << " (type " << typeName
            << ") in " << dict.name() << ": the mesh "
            << mesh_.name() << " already has a coagulation cloud, made by"
            << " another function object of this type. Both would write the"
            << " same lagrangian/" << cloudName << " files, samples and"
            << " balances." << nl << "    Keep one coagulationCloud function"
            << " object per mesh region" << nl << exit(FatalIOError);
    }

    const word UName = dict.getOrDefault<word>("U", "U");
    if (!mesh_.foundObject<volVectorField>(UName))
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << " (type " << typeName
            << ") in " << dict.name() << " moves particles with the"
            << " velocity '" << UName << "' (entry 'U'), but the solver has"
            << " no volVectorField of that name; it has "
            << mesh_.sortedNames<volVectorField>() << nl
            << exit(FatalIOError);
    }

    // A population that starts later than the solver (timeStart) checks
    // the velocity as the flow is then, at its first split step: the
    // solver's initial field (a fluid at rest) says nothing of it
    const bool startsLater =
        dict.found("timeStart")
     && dict.get<scalar>("timeStart") > time_.value() + 0.5*time_.deltaTValue();

    // The objects the cloud registers with the mesh: those written with
    // the time are written again once the step is made
    const wordList before(mesh_.objectRegistry::sortedToc());
    try
    {
        cloud_.reset
        (
            new coagulationCloud
            (
                mesh_.lookupObjectRef<volVectorField>(UName),
                cloudName,
                true,
                interval,
                !startsLater
            )
        );
    }
    catch (const Foam::IOerror& err)
    {
        // functionObjectList prints it on the master and stops the run: a
        // processor's own error printed here first
        if (Pstream::parRun() && !Pstream::master())
        {
            Perr<< err << endl;
        }
        throw;
    }
    catch (const Foam::error& err)
    {
        // functionObjectList would make any other error a warning and run
        // on without the particles: stop the run
        FatalError.dontThrowExceptions();
        FatalErrorInFunction
            << err.message().c_str() << nl
            << "    (function object " << name() << ", type " << typeName
            << ")" << nl << exit(FatalError);
    }
    // The solver's writes would write them before the step (and before the
    // function object's timeStart): the function object writes them itself
    const wordHashSet old(before);
    for (const word& objName : mesh_.objectRegistry::sortedToc())
    {
        regIOobject* obj =
            mesh_.objectRegistry::getObjectPtr<regIOobject>(objName);
        if
        (
            !old.found(objName) && obj
         && obj->writeOpt() == IOobject::AUTO_WRITE
        )
        {
            obj->writeOpt() = IOobject::NO_WRITE;
            cloudObjects_.append(objName);
        }
    }
    // The solver's fields the cloud reads that nothing writes (a readFields
    // function object's): written with the cloud's times, so that a restart
    // from any of them finds them
    for (const word& fieldName : flowFields::of(mesh_).unwrittenLiveFields())
    {
        Info<< "    field " << fieldName << ": written with the cloud's"
            << " times for restarts" << endl;
        cloudObjects_.append(fieldName);
    }
    return true;
}


bool Foam::coagulation::coagulationCloudFunctionObject::execute()
{
    coagulationCloud& cloud = *cloud_;

    // A split step ends at every multiple of the interval (OpenFOAM applies
    // executeInterval only with an executeControl entry)
    if (time_.timeIndex() % cloud.stepInterval() != 0)
    {
        return true;
    }

    cloud.completeWrite();
    cloud.evolve();
    Log << type() << " " << name() << ": time " << time_.timeName()
        << ", particles = " << returnReduce(cloud.size(), sumOp<label>())
        << endl;

    if (time_.writeTime())
    {
        for (const word& objName : cloudObjects_)
        {
            const regIOobject* obj = mesh_.cfindObject<regIOobject>(objName);
            if (obj && obj->readOpt() == IOobject::MUST_READ)
            {
                // a field the cloud read: all digits, for a restart
                const restartPrecision allDigits;
                obj->write();
            }
            else if (obj)
            {
                obj->write();
            }
        }
        cloud.onWrite();
        cloud.reportTimes();
    }
    return true;
}


bool Foam::coagulation::coagulationCloudFunctionObject::write()
{
    return true;
}


bool Foam::coagulation::coagulationCloudFunctionObject::end()
{
    if (cloud_)
    {
        cloud_->endRun();
    }
    return true;
}


// ************************************************************************* //
