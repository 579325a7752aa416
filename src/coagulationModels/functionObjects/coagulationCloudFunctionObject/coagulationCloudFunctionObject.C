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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::coagulationCloudFunctionObject::
coagulationCloudFunctionObject
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    functionObjects::fvMeshFunctionObject(name, runTime, dict),
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

    // Every execution is a split step over the solver's deltaT, and the end
    // checks the balances: the function object runs at every time step to
    // the end of the run
    const word control = dict.getOrDefault<word>("executeControl", "timeStep");
    const label interval = dict.getOrDefault<label>("executeInterval", 1);
    if (control != "timeStep" || interval != 1)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << " (type " << typeName
            << ") in " << dict.name() << " has executeControl " << control
            << " and executeInterval " << interval << ": the population makes"
            << " a split step of every time step of the solver, so both must"
            << " be left at timeStep and 1" << nl << exit(FatalIOError);
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
                "coagulationCloud",
                true
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
    return true;
}


bool Foam::coagulation::coagulationCloudFunctionObject::execute()
{
    coagulationCloud& cloud = *cloud_;
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
