/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "cellGas.H"
#include "caseChecks.H"
#include "Pair.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalarField Foam::coagulation::cellGas::cellValues
(
    const dictionary& dict,
    const word& model,
    const word& key,
    const dimensionSet& dims,
    const fvMesh& mesh,
    autoPtr<volScalarField>& field
)
{
    if (dict.found(key) && !dict.lookup(key)[0].isWord())
    {
        return scalarField(mesh.nCells(), caseChecks::positive(dict, key));
    }
    field = caseChecks::cellField
    (
        dict, model, key, dict.getOrDefault<word>(key, key), mesh, dims,
        true
    );
    Info<< "    " << key << " from field " << field->name() << ": "
        << gMin(field->primitiveField()) << " to "
        << gMax(field->primitiveField()) << endl;
    return field->primitiveField();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::cellGas::cellGas
(
    const dictionary& dict,
    const word& model,
    const fvMesh& mesh
)
:
    T_(),
    p_(),
    gas_()
{
    const scalarField T
    (
        cellValues(dict, model, "T", dimTemperature, mesh, T_)
    );
    const scalarField p(cellValues(dict, model, "p", dimPressure, mesh, p_));

    // mu: a value, or Sutherland's law on each cell's T
    const bool sutherland =
        !dict.found("mu") || dict.lookup("mu")[0].isWord();
    if (sutherland && dict.found("mu") && dict.get<word>("mu") != "sutherland")
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'mu' = " << dict.get<word>("mu") << " in " << dict.name()
            << " is neither a value [Pa s] nor sutherland" << nl
            << exit(FatalIOError);
    }
    const scalar mu = sutherland ? 0 : caseChecks::positive(dict, "mu");
    const scalar As =
        dict.found("As") ? caseChecks::positive(dict, "As") : 1.458e-6;
    const scalar Ts =
        dict.found("Ts") ? caseChecks::positive(dict, "Ts") : 110.4;
    coag::GasState gas;
    if (dict.found("molarMass"))
    {
        gas.molarMass = caseChecks::positive(dict, "molarMass");
    }

    gas_.reserve(T.size());
    forAll(T, celli)
    {
        gas.T = T[celli];
        gas.p = p[celli];
        gas.mu = sutherland ? coag::sutherlandViscosity(gas.T, As, Ts) : mu;
        gas_.push_back(gas);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::cellGas::checkGasKeywords
(
    const dictionary& dict,
    const wordList& own
)
{
    wordList valid{"T", "p", "mu", "As", "Ts", "molarMass"};
    valid.append(own);
    caseChecks::keywords(dict, valid);
}


Foam::Pair<Foam::scalar>
Foam::coagulation::cellGas::meanFreePathRange() const
{
    scalar lowest = GREAT, highest = 0;
    for (const coag::GasState& gas : gas_)
    {
        lowest = min(lowest, gas.meanFreePath());
        highest = max(highest, gas.meanFreePath());
    }
    return Pair<scalar>
    (
        returnReduce(lowest, minOp<scalar>()),
        returnReduce(highest, maxOp<scalar>())
    );
}


// ************************************************************************* //
