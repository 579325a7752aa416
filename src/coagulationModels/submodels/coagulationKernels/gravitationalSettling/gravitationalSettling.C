/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "gravitationalSettling.H"
#include "caseChecks.H"
#include "particleMaterial.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
namespace coagulationKernels
{
    defineTypeNameAndDebug(gravitationalSettling, 0);
    addToRunTimeSelectionTable
    (
        coagulationKernel,
        gravitationalSettling,
        dictionary
    );
}
}
}


namespace
{
    const char* const modelName = "kernel model 'gravitationalSettling'";
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::unique_ptr<coag::GravitationalSettlingKernel>
Foam::coagulation::coagulationKernels::gravitationalSettling::readLayout
(
    const dictionary& dict
)
{
    cellGas::checkGasKeywords(dict, {"type", "collisionEfficiency", "g"});
    const scalar E =
        dict.found("collisionEfficiency")
      ? caseChecks::positive(dict, "collisionEfficiency")
      : 1.0;
    const scalar g = dict.found("g") ? caseChecks::positive(dict, "g") : 9.81;

    // The layout's gas is any valid one: the majorant's basis and groups do
    // not depend on it. The material: the top-level 'particles' entry, also
    // for a part of a sum
    return std::make_unique<coag::GravitationalSettlingKernel>
    (
        coag::GasState(),
        readParticleMaterial(dict.topDict(), modelName),
        E,
        g
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::coagulationKernels::gravitationalSettling::
gravitationalSettling
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    coagulationKernel(0, readLayout(dict)),
    gas_(dict, modelName, mesh)
{
    const coag::GravitationalSettlingKernel& layout =
        static_cast<const coag::GravitationalSettlingKernel&>(core());

    makeCellKernels();

    const Pair<scalar> lambda = gas_.meanFreePathRange();
    Info<< "    collision efficiency " << layout.efficiency() << ", g "
        << layout.g() << " m/s2, particle density "
        << layout.material().density << " kg/m3, mass unit "
        << layout.material().massUnit << " kg, mean free path from "
        << lambda.first() << " to " << lambda.second() << " m" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::coagulationKernels::gravitationalSettling::
makeCellKernels()
{
    const coag::GravitationalSettlingKernel& layout =
        static_cast<const coag::GravitationalSettlingKernel&>(core());
    cellKernels().clear();
    cellKernels().reserve(gas_.size());
    for (label celli = 0; celli < gas_.size(); ++celli)
    {
        cellKernels().push_back
        (
            std::make_unique<coag::GravitationalSettlingKernel>
            (
                gas_[celli], layout.material(), layout.efficiency(),
                layout.g()
            )
        );
    }
}


bool Foam::coagulation::coagulationKernels::gravitationalSettling::correct()
{
    if (gas_.update())
    {
        makeCellKernels();
        return true;
    }
    return false;
}


// ************************************************************************* //
