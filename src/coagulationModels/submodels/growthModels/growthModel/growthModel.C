/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "growthModel.H"
#include "caseChecks.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
    defineTypeNameAndDebug(growthModel, 0);
    defineRunTimeSelectionTable(growthModel, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::growthModel::cellValue::cellValue
(
    const dictionary& dict,
    const word& model,
    const word& key,
    const dimensionSet& dims,
    const fvMesh& mesh,
    const sign values
)
:
    uniform_(0),
    field_(nullptr)
{
    if (!dict.found(key))
    {
        FatalIOErrorInFunction(dict)
            << "The " << model << " needs entry '" << key << "' (a value or"
            << " a field's name) in " << dict.name() << nl
            << exit(FatalIOError);
    }
    if (dict.lookup(key)[0].isWord())
    {
        field_ = &flowFields::of(mesh).cellField
        (
            dict, model, key, dict.get<word>(key), dims,
            values == sign::positive
        );
        return;
    }
    uniform_ =
        values == sign::any ? growthModel::finite(dict, key)
      : values == sign::positive ? caseChecks::positive(dict, key)
      : caseChecks::nonNegative(dict, key);
}


Foam::coagulation::growthModel::growthModel
(
    const word& name,
    const dictionary& dict,
    const wordList& keywords
)
:
    name_(name)
{
    wordList valid({"type"});
    valid.append(keywords);
    caseChecks::keywords(dict, valid);
}


// * * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::coagulation::growthModel>
Foam::coagulation::growthModel::New
(
    const word& name,
    const dictionary& dict,
    const fvMesh& mesh
)
{
    const word modelType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "growthModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<growthModel>(cstrIter()(name, dict, mesh));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::coagulation::growthModel::finite
(
    const dictionary& dict,
    const word& key
)
{
    const scalar value = dict.get<scalar>(key);
    if (!std::isfinite(value))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' in " << dict.name()
            << " must be finite, got " << value << nl
            << exit(FatalIOError);
    }
    return value;
}


Foam::string Foam::coagulation::growthModel::cellValue::range() const
{
    if (!field_)
    {
        return Foam::name(uniform_);
    }
    const scalarField& v = (*field_)().primitiveField();
    return
        "field " + field_->name() + ": " + Foam::name(gMin(v)) + " to "
      + Foam::name(gMax(v));
}


// ************************************************************************* //
