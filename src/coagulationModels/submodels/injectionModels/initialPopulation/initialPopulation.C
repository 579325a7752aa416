/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "initialPopulation.H"
#include "particleMaterial.H"
#include "coagulationCloud.H"
#include "caseChecks.H"
#include "cellTetSampler.H"
#include "Tuple2.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::initialPopulation::initialPopulation
(
    const dictionary& dict,
    const coagulationCloud& cloud
)
:
    dict_(dict),
    density_(cloud.mesh().nCells(), Zero),
    masses_(),
    cumulative_()
{
    const fvMesh& mesh = cloud.mesh();
    caseChecks::keywords
    (
        dict,
        {
            "numberDensity", "numberDensityField", "cellZone", "mass",
            "diameter",
            "sizeDistribution"
        }
    );

    // The number density: uniform, or a field of the start time
    if (dict.found("numberDensity") == dict.found("numberDensityField"))
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << " needs exactly one of"
            << " 'numberDensity' (a value) and 'numberDensityField' (the name"
            << " of a volScalarField of the start time)" << nl
            << exit(FatalIOError);
    }
    if (dict.found("numberDensity"))
    {
        density_ = caseChecks::nonNegative(dict, "numberDensity");
    }
    else
    {
        const autoPtr<volScalarField> n
        (
            caseChecks::cellField
            (
                dict,
                "initial population",
                "numberDensityField",
                dict.get<word>("numberDensityField"),
                mesh,
                dimless/dimVolume,
                false
            )
        );
        density_ = n->primitiveField();
    }

    // Only the cells of a zone
    if (dict.found("cellZone"))
    {
        const word zoneName(dict.get<word>("cellZone"));
        const label zonei = mesh.cellZones().findZoneID(zoneName);
        if (zonei < 0)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'cellZone' of " << dict.name() << " names the zone '"
                << zoneName << "', which the mesh does not have; its zones: "
                << mesh.cellZones().names() << nl << exit(FatalIOError);
        }
        scalarField inZone(density_.size(), Zero);
        for (const label celli : mesh.cellZones()[zonei])
        {
            inZone[celli] = density_[celli];
        }
        density_ = inZone;
    }

    // The particle masses: one, or a table of (mass, number fraction)
    const bool oneSize = dict.found("mass") || dict.found("diameter");
    if (oneSize == dict.found("sizeDistribution"))
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << " needs exactly one of 'mass'"
            << " or 'diameter' (monodisperse) and 'sizeDistribution'"
            << " ((mass fraction) pairs)" << nl << exit(FatalIOError);
    }
    if (oneSize)
    {
        masses_ = scalarField(1, readParticleMass(dict, "initial population"));
        cumulative_ = scalarField(1, scalar(1));
    }
    else
    {
        const List<Tuple2<scalar, scalar>> table
        (
            dict.get<List<Tuple2<scalar, scalar>>>("sizeDistribution")
        );
        scalar total = 0;
        for (const auto& row : table)
        {
            if
            (
                !(row.first() > 0) || !(row.second() >= 0)
             || !std::isfinite(row.first()) || !std::isfinite(row.second())
            )
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'sizeDistribution' of " << dict.name()
                    << " has the row (" << row.first() << ' ' << row.second()
                    << "): masses must be positive and fractions not"
                    << " negative" << nl << exit(FatalIOError);
            }
            masses_.append(row.first());
            total += row.second();
            cumulative_.append(total);
        }
        if (!(total > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'sizeDistribution' of " << dict.name()
                << " has no positive number fraction" << nl
                << exit(FatalIOError);
        }
        cumulative_ /= total;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::coagulation::initialPopulation::create
(
    coagulationCloud& cloud
) const
{
    const fvMesh& mesh = cloud.mesh();
    const scalar W = cloud.scaling().particleWeight();
    const bool equalWeights = cloud.algorithmEqualWeights();
    const cellTetSampler& tets = cloud.cellTets();

    // A density that would not fit in memory stops here, not in the step
    scalar expected = 0;
    forAll(density_, celli)
    {
        expected += density_[celli]*mesh.cellVolumes()[celli]/W;
    }
    if
    (
        returnReduce(expected, sumOp<scalar>())
      > 0.5*coagulationCloud::availableMemory()
       /coagulationCloud::bytesPerParticle()
    )
    {
        FatalIOErrorInFunction(dict_)
            << "The initial population of " << dict_.name() << " would be "
            << returnReduce(expected, sumOp<scalar>()) << " computational"
            << " particles (number density x cell volume / weight "
            << W << "), more than half the free memory holds" << nl
            << exit(FatalIOError);
    }

    label created = 0;
    forAll(density_, celli)
    {
        const scalar N = density_[celli]*mesh.cellVolumes()[celli];
        if (!(N > 0))
        {
            continue;
        }
        coag::Rng rng(cloud.seeds()(celli, streamSeeds::initialPopulation));

        label count = 0;
        scalar weight = W;
        if (equalWeights)
        {
            const scalar whole = std::floor(N/W);
            count = label(whole) + (rng.uniform() < N/W - whole ? 1 : 0);
        }
        else
        {
            count = max(label(1), label(std::llround(N/W)));
            weight = N/count;
        }

        for (label i = 0; i < count; ++i)
        {
            // The mass by its number fraction (the last one takes round-off)
            const scalar u = rng.uniform();
            label k = 0;
            while (k < masses_.size() - 1 && u > cumulative_[k])
            {
                ++k;
            }
            const cellTetSampler::point place = tets.sample(celli, rng);
            cloud.addParticle
            (
                new coagulationParticle
                (
                    mesh,
                    place.coordinates,
                    celli,
                    place.tetFace,
                    place.tetPt,
                    masses_[k],
                    weight
                )
            );
        }
        created += count;
    }

    return created;
}


// ************************************************************************* //
