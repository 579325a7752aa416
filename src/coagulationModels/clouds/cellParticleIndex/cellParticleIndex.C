/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "cellParticleIndex.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::cellParticleIndex::cellParticleIndex()
:
    particles_(),
    cells_(),
    listValid_(false),
    cellStart_(),
    cellNext_(),
    cellParticles_(),
    cellListIndex_(),
    sorted_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::cellParticleIndex::list
(
    Cloud<coagulationParticle>& cloud
)
{
    if (listValid_)
    {
        return;
    }

    const label nParticles = cloud.size();
    particles_.setSize(nParticles);
    cells_.setSize(nParticles);
    label i = 0;
    for (coagulationParticle& p : cloud)
    {
        particles_[i] = &p;
        cells_[i] = p.cell();
        ++i;
    }
    listValid_ = true;
}


void Foam::coagulation::cellParticleIndex::sort
(
    Cloud<coagulationParticle>& cloud,
    const label nCells
)
{
    if (sorted_)
    {
        return;
    }

    // The cloud in list order (kept by the steps, or one pass over the
    // linked list), then a stable counting sort on the arrays: within a
    // cell, list order
    list(cloud);
    const label nParticles = particles_.size();

    cellStart_.setSize(nCells + 1);
    cellStart_ = 0;
    for (label k = 0; k < nParticles; ++k)
    {
        ++cellStart_[cells_[k] + 1];
    }
    for (label celli = 0; celli < nCells; ++celli)
    {
        cellStart_[celli + 1] += cellStart_[celli];
    }

    cellParticles_.setSize(nParticles);
    cellListIndex_.setSize(nParticles);
    cellNext_ = SubList<label>(cellStart_, nCells);
    for (label k = 0; k < nParticles; ++k)
    {
        const label pos = cellNext_[cells_[k]]++;
        cellParticles_[pos] = particles_[k];
        cellListIndex_[pos] = k;
    }

    sorted_ = true;
}


void Foam::coagulation::cellParticleIndex::compact
(
    const std::vector<char>& removed
)
{
    const label n = particles_.size();
    label kept = 0;
    for (label k = 0; k < n; ++k)
    {
        if (!removed[k])
        {
            particles_[kept] = particles_[k];
            cells_[kept] = cells_[k];
            ++kept;
        }
    }
    particles_.setSize(kept);
    cells_.setSize(kept);
}


// ************************************************************************* //
