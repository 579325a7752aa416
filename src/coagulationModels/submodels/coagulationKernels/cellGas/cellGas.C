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

const Foam::coagulation::flowFields::flowField*
Foam::coagulation::cellGas::cellValues
(
    const dictionary& dict,
    const word& model,
    const word& key,
    const dimensionSet& dims,
    const fvMesh& mesh,
    scalar& uniform
)
{
    if (dict.found(key) && !dict.lookup(key)[0].isWord())
    {
        uniform = caseChecks::positive(dict, key);
        return nullptr;
    }
    const flowFields::flowField& f = flowFields::of(mesh).cellField
    (
        dict, model, key, dict.getOrDefault<word>(key, key), dims, true
    );
    Info<< "    " << key << " from field " << f.name() << ": "
        << gMin(f().primitiveField()) << " to "
        << gMax(f().primitiveField()) << endl;
    return &f;
}


void Foam::coagulation::cellGas::makeGas()
{
    coag::GasState gas;
    gas.molarMass = molarMass_;
    const label n = label(gas_.size());
    for (label celli = 0; celli < n; ++celli)
    {
        gas.T = T_ ? (*T_)().primitiveField()[celli] : uniformT_;
        gas.p = p_ ? (*p_)().primitiveField()[celli] : uniformP_;
        gas.mu = sutherland_ ? coag::sutherlandViscosity(gas.T, As_, Ts_) : mu_;
        gas_[celli] = gas;
    }
    TVersion_ = T_ ? T_->version() : 0;
    pVersion_ = p_ ? p_->version() : 0;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::cellGas::cellGas
(
    const dictionary& dict,
    const word& model,
    const fvMesh& mesh
)
:
    uniformT_(0),
    uniformP_(0),
    T_(cellValues(dict, model, "T", dimTemperature, mesh, uniformT_)),
    p_(cellValues(dict, model, "p", dimPressure, mesh, uniformP_)),
    sutherland_(!dict.found("mu") || dict.lookup("mu")[0].isWord()),
    mu_(0),
    As_(dict.found("As") ? caseChecks::positive(dict, "As") : 1.458e-6),
    Ts_(dict.found("Ts") ? caseChecks::positive(dict, "Ts") : 110.4),
    molarMass_(coag::GasState().molarMass),
    TVersion_(0),
    pVersion_(0),
    gas_(mesh.nCells())
{
    // mu: a value, or Sutherland's law on each cell's T
    if (sutherland_ && dict.found("mu") && dict.get<word>("mu") != "sutherland")
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'mu' = " << dict.get<word>("mu") << " in " << dict.name()
            << " is neither a value [Pa s] nor sutherland" << nl
            << exit(FatalIOError);
    }
    if (!sutherland_)
    {
        mu_ = caseChecks::positive(dict, "mu");
    }
    if (dict.found("molarMass"))
    {
        molarMass_ = caseChecks::positive(dict, "molarMass");
    }
    makeGas();
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


bool Foam::coagulation::cellGas::update()
{
    if
    (
        (T_ && T_->version() != TVersion_)
     || (p_ && p_->version() != pVersion_)
    )
    {
        makeGas();
        return true;
    }
    return false;
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
