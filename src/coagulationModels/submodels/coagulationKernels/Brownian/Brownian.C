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
    cellGas::checkGasKeywords(dict, {"type", "regime"});
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
            // the top-level 'particles' entry, also for a part of a sum
            readParticleMaterial(dict.topDict(), modelName)
        )
    ),
    gas_(dict, modelName, mesh)
{
    // The regime and material read for the base's kernel
    const coag::BrownianKernel& layout =
        static_cast<const coag::BrownianKernel&>(core());
    const coag::BrownianRegime regime = layout.regime();
    const coag::ParticleMaterial& material = layout.material();

    makeCellKernels();

    const Pair<scalar> lambda = gas_.meanFreePathRange();
    Info<< "    regime " << coag::brownianRegimeName(regime).c_str()
        << ", particle density " << material.density << " kg/m3, mass unit "
        << material.massUnit << " kg, mean free path from "
        << lambda.first() << " to " << lambda.second() << " m" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::coagulationKernels::Brownian::makeCellKernels()
{
    const coag::BrownianKernel& layout =
        static_cast<const coag::BrownianKernel&>(core());
    cellKernels().clear();
    cellKernels().reserve(gas_.size());
    for (label celli = 0; celli < gas_.size(); ++celli)
    {
        cellKernels().push_back
        (
            std::make_unique<coag::BrownianKernel>
            (
                layout.regime(), gas_[celli], layout.material()
            )
        );
    }
}


bool Foam::coagulation::coagulationKernels::Brownian::correct()
{
    if (gas_.update())
    {
        makeCellKernels();
        return true;
    }
    return false;
}


// ************************************************************************* //
