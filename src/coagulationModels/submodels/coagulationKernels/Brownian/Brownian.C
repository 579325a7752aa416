/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "Brownian.H"
#include "caseChecks.H"
#include "particleMaterial.H"
#include "addToRunTimeSelectionTable.H"

#include <stdexcept>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
namespace coagulationKernels
{
    defineTypeNameAndDebug(Brownian, 0);
    addToRunTimeSelectionTable(coagulationKernel, Brownian, dictionary);
}
}
}


namespace
{
    const char* const modelName = "kernel model 'Brownian'";
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

coag::BrownianRegime
Foam::coagulation::coagulationKernels::Brownian::readRegime
(
    const dictionary& dict
)
{
    caseChecks::keywords
    (
        dict, {"type", "regime", "T", "p", "mu", "As", "Ts", "molarMass"}
    );
    const word regime(dict.getOrDefault<word>("regime", "transition"));
    try
    {
        return coag::parseBrownianRegime(regime);
    }
    catch (const std::invalid_argument&)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'regime' = " << regime << " in " << dict.name()
            << " is not a regime; valid regimes are freeMolecular, continuum"
            << " and transition" << nl << exit(FatalIOError);
    }
    return coag::BrownianRegime::transition;
}


Foam::scalarField
Foam::coagulation::coagulationKernels::Brownian::cellValues
(
    const dictionary& dict,
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
        dict, modelName, key, dict.getOrDefault<word>(key, key), mesh, dims,
        true
    );
    Info<< "    " << key << " from field " << field->name() << ": "
        << gMin(field->primitiveField()) << " to "
        << gMax(field->primitiveField()) << endl;
    return field->primitiveField();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::coagulationKernels::Brownian::Brownian
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    // The algorithms are built with a kernel of the regime for its majorant
    // layout (the same in every gas); every cell step is given the cell's
    // own (cellKernel)
    coagulationKernel
    (
        0,
        std::make_unique<coag::BrownianKernel>
        (
            readRegime(dict),
            coag::GasState(),
            readParticleMaterial(dict.parent(), modelName)
        )
    ),
    T_(),
    p_()
{
    // The regime and material read for the base's kernel
    const coag::BrownianKernel& layout =
        static_cast<const coag::BrownianKernel&>(core());
    const coag::BrownianRegime regime = layout.regime();
    const coag::ParticleMaterial& material = layout.material();

    const scalarField T(cellValues(dict, "T", dimTemperature, mesh, T_));
    const scalarField p(cellValues(dict, "p", dimPressure, mesh, p_));

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

    cellKernels().reserve(T.size());
    scalar lowest = GREAT, highest = 0;
    forAll(T, celli)
    {
        gas.T = T[celli];
        gas.p = p[celli];
        gas.mu = sutherland ? coag::sutherlandViscosity(gas.T, As, Ts) : mu;
        cellKernels().push_back
        (
            std::make_unique<coag::BrownianKernel>(regime, gas, material)
        );
        lowest = min(lowest, gas.meanFreePath());
        highest = max(highest, gas.meanFreePath());
    }

    Info<< "    regime " << coag::brownianRegimeName(regime).c_str()
        << ", particle density " << material.density << " kg/m3, mass unit "
        << material.massUnit << " kg, mean free path from "
        << returnReduce(lowest, minOp<scalar>()) << " to "
        << returnReduce(highest, maxOp<scalar>()) << " m" << endl;
}


// ************************************************************************* //
