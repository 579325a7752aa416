/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "flowFields.H"
#include "caseChecks.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
    defineTypeNameAndDebug(flowFields, 0);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::flowFields::flowField::flowField
(
    const word& name,
    const dimensionSet& dims,
    const bool positive,
    const word& model,
    const dictionary& dict,
    const source src
)
:
    name_(name),
    dims_(dims),
    positive_(positive),
    model_(model),
    dict_(&dict),
    source_(src)
{}


Foam::coagulation::flowFields::flowFields
(
    const fvMesh& mesh,
    const dictionary& transportDict,
    const bool live
)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            mesh.time().constant(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        )
    ),
    mesh_(mesh),
    source_(live ? source::live : source::frozen),
    series_(),
    fields_()
{
    if (transportDict.found("flowSeries"))
    {
        if (live)
        {
            FatalIOErrorInFunction(transportDict)
                << "Entry 'flowSeries' in " << transportDict.name() << " is"
                << " for coagulationFoam: inside a flow solver (the"
                << " coagulationCloud function object) the particles move"
                << " with the solver's velocity." << nl
                << "    Remove the entry" << nl << exit(FatalIOError);
        }
        series_.reset(new flowSeries(transportDict, mesh));
        source_ = source::series;
    }
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::coagulation::flowFields& Foam::coagulation::flowFields::of
(
    const fvMesh& mesh
)
{
    return mesh.lookupObjectRef<flowFields>(typeName);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::coagulation::flowFields::checkValues
(
    const flowField& f,
    const Foam::scalarField& values,
    const string& from
) const
{
    forAll(values, celli)
    {
        const scalar v = values[celli];
        if (!std::isfinite(v) || !(v >= 0) || (f.positive_ && !(v > 0)))
        {
            FatalIOErrorInFunction(*f.dict_)
                << "Field '" << f.name_ << "' (" << from.c_str() << "), read"
                << " by the " << f.model_ << " of " << f.dict_->name()
                << ", has the "
                << (std::isfinite(v) ? (v < 0 ? "negative " : "") : "non-finite ")
                << "value " << v << " in cell " << celli << " at t = "
                << mesh_.time().value() << "; it must be "
                << (f.positive_ ? "positive" : "finite and not negative")
                << " in every cell" << nl << exit(FatalIOError);
        }
    }
}


void Foam::coagulation::flowFields::checkDimensions
(
    const flowField& f,
    const volScalarField& values
) const
{
    if (values.dimensions() != f.dims_)
    {
        FatalIOErrorInFunction(*f.dict_)
            << "Field '" << f.name_ << "' (" << values.objectPath() << "),"
            << " read by the " << f.model_ << " of " << f.dict_->name()
            << ", has dimensions " << values.dimensions() << "; it must have "
            << f.dims_ << nl << exit(FatalIOError);
    }
}


Foam::autoPtr<Foam::volScalarField> Foam::coagulation::flowFields::readSeries
(
    const flowField& f,
    const label i
) const
{
    autoPtr<volScalarField> values
    (
        caseChecks::withTrapsHeld
        (
            [&]()
            {
                return autoPtr<volScalarField>::New
                (
                    IOobject
                    (
                        f.name_,
                        series_->timePath(i),
                        mesh_,
                        IOobject::MUST_READ,
                        IOobject::NO_WRITE,
                        false
                    ),
                    mesh_
                );
            }
        )
    );
    checkDimensions(f, *values);
    checkValues(f, values->primitiveField(), values->objectPath());
    return values;
}


bool Foam::coagulation::flowFields::set
(
    flowField& f,
    const scalar t,
    const scalar stepStart
)
{
    volScalarField& values = *f.values_;
    Foam::scalarField next;
    string from;

    if (f.source_ == source::frozen)
    {
        return false;
    }
    else if (f.source_ == source::series)
    {
        label a = -1, b = -1;
        scalar theta = 0;
        series_->bracket(t, a, b, theta);
        flowSeries::hold
        (
            a, b, f.a_, f.b_, f.fa_, f.fb_,
            [&](const label i) { return readSeries(f, i); }
        );
        const Foam::scalarField& fa = f.fa_->primitiveField();
        if (b == a)
        {
            next = fa;
        }
        else
        {
            next = fa + theta*(f.fb_->primitiveField() - fa);
        }
    }
    else
    {
        // The solver's field now (the end of the split step) and at the
        // split step's start: linear in time between them
        const volScalarField& now =
            mesh_.lookupObject<volScalarField>(f.name_);
        const Time& runTime = mesh_.time();
        const scalar tNow = runTime.value();
        const scalar small = 1e-6*runTime.deltaTValue();
        if (runTime.timeIndex() != f.indexLast_)
        {
            // A new split step: the values the last one ended with are
            // this one's start
            f.prev_.transfer(f.last_);
            f.tPrev_ = f.tLast_;
            f.last_ = now.primitiveField();
            f.tLast_ = tNow;
            f.indexLast_ = runTime.timeIndex();
        }
        const Foam::scalarField* start = nullptr;
        if (f.prev_.size() == now.size() && mag(f.tPrev_ - stepStart) < small)
        {
            start = &f.prev_;
        }
        else if
        (
            now.nOldTimes() > 0
         && mag(tNow - runTime.deltaTValue() - stepStart) < small
        )
        {
            // (the first split step after a gap: the solver's old time)
            start = &now.oldTime().primitiveField();
        }
        if (start && tNow - stepStart > small)
        {
            const scalar theta =
                min(max((t - stepStart)/(tNow - stepStart), scalar(0)), scalar(1));
            next = *start + theta*(now.primitiveField() - *start);
        }
        else
        {
            next = now.primitiveField();
        }
        from = "the flow solver's, " + now.objectPath();
    }

    // Changed on any processor: the versions, and so the submodels' remaking
    // of their cell data (some of it collective: volPointInterpolation), go
    // in step on every processor
    if (!returnReduce(next != values.primitiveField(), orOp<bool>()))
    {
        return false;
    }
    if (f.source_ == source::live)
    {
        checkValues(f, next, from);
    }
    values.primitiveFieldRef() = next;
    ++f.version_;
    return true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::coagulation::flowFields::unwrittenLiveFields() const
{
    DynamicList<word> names;
    for (const flowField& f : fields_)
    {
        const volScalarField* now =
            f.source_ == source::live
          ? mesh_.findObject<volScalarField>(f.name_)
          : nullptr;
        if (now && now->writeOpt() == IOobject::NO_WRITE)
        {
            names.append(f.name_);
        }
    }
    return wordList(std::move(names));
}


const Foam::coagulation::flowFields::flowField&
Foam::coagulation::flowFields::cellField
(
    const dictionary& dict,
    const word& model,
    const word& entry,
    const word& fieldName,
    const dimensionSet& dims,
    const bool positive
)
{
    for (flowField& f : fields_)
    {
        if (f.name_ == fieldName)
        {
            if (f.dims_ != dims)
            {
                FatalIOErrorInFunction(dict)
                    << "The " << model << " (" << dict.name() << ") reads the"
                    << " field '" << fieldName << "' (entry '" << entry
                    << "') with dimensions " << dims << ", the " << f.model_
                    << " with " << f.dims_ << nl << exit(FatalIOError);
            }
            f.positive_ = f.positive_ || positive;
            checkValues(f, f().primitiveField(), f().objectPath());
            // (a series' written times read so far, under the new sign)
            for (const autoPtr<volScalarField>* written : {&f.fa_, &f.fb_})
            {
                if (*written)
                {
                    checkValues
                    (
                        f,
                        (*written)->primitiveField(),
                        (*written)->objectPath()
                    );
                }
            }
            return f;
        }
    }

    // A series field that no written time of the flow case holds is frozen
    source src = source_;
    if (src == source::series && !series_->holds(fieldName, model))
    {
        src = source::frozen;
        Info<< "    field " << fieldName << ": not in the flow series, read"
            << " from the start time and held" << endl;
    }

    flowField* f = new flowField(fieldName, dims, positive, model, dict, src);
    fields_.append(f);

    if (src == source::frozen)
    {
        f->values_ = caseChecks::cellField
        (
            dict, model, entry, fieldName, mesh_, dims, positive
        );
        return *f;
    }

    if (src == source::live)
    {
        const volScalarField* now =
            mesh_.findObject<volScalarField>(fieldName);
        if (!now)
        {
            // A readFields function object registers a field only where
            // the start time holds its file: say which is missing
            const fileName file(mesh_.time().timePath()/fieldName);
            const bool inTime = isFile(file) || isFile(file + ".gz");
            FatalIOErrorInFunction(dict)
                << "The " << model << " (" << dict.name() << ") reads the"
                << " field '" << fieldName << "' (entry '" << entry << "'),"
                << " which the flow solver does not register: inside a flow"
                << " solver the cloud takes its fields from the solver at"
                << " every step." << nl << "    The solver's fields: "
                << mesh_.sortedNames<volScalarField>() << nl;
            if (inTime)
            {
                FatalIOError
                    << "    Name one of them, or read the field from the time"
                    << " folders with a readFields function object listed"
                    << " before the cloud" << nl;
            }
            else
            {
                FatalIOError
                    << "    The start time " << mesh_.time().timeName()
                    << " has no file " << fieldName << " (" << file << "),"
                    << " so a readFields function object cannot read it"
                    << " either: copy the field into the start time, or"
                    << " restart from a time that holds it (the cloud writes"
                    << " the fields it reads through readFields with its"
                    << " times)" << nl;
            }
            FatalIOError << exit(FatalIOError);
        }
        checkDimensions(*f, *now);
        checkValues
        (
            *f, now->primitiveField(), "the flow solver's, " + now->objectPath()
        );
        f->values_.reset
        (
            new volScalarField
            (
                IOobject
                (
                    fieldName + ":coagulation",
                    mesh_.time().timeName(),
                    mesh_,
                    IOobject::NO_READ,
                    IOobject::NO_WRITE,
                    false
                ),
                *now
            )
        );
    }
    else
    {
        label a = -1, b = -1;
        scalar theta = 0;
        series_->bracket(mesh_.time().value(), a, b, theta);
        f->values_ = readSeries(*f, a);
        f->values_->rename(fieldName + ":coagulation");
    }
    if (src == source::live)
    {
        // The values at the start, the first split step's start values
        f->last_ = (*f)().primitiveField();
        f->tLast_ = mesh_.time().value();
        f->indexLast_ = mesh_.time().timeIndex();
    }
    // Set at the time now (the submodels are made before the first step)
    set(*f, mesh_.time().value(), mesh_.time().value());
    return *f;
}


void Foam::coagulation::flowFields::update
(
    const scalar t,
    const scalar stepStart
)
{
    for (flowField& f : fields_)
    {
        set(f, t, stepStart);
    }
}


// ************************************************************************* //
