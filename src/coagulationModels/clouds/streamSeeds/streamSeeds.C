/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "streamSeeds.H"
#include "Pstream.H"
#include "coagulation/random/SplitMix64.hpp"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::streamSeeds::streamSeeds
(
    const dictionary& dict,
    const Time& time,
    const label stepInterval
)
:
    time_(time),
    stepInterval_(stepInterval),
    seed_(0)
{
    const label seed = dict.get<label>("seed");
    if (seed < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'seed' = " << seed << " in " << dict.name()
            << " must not be negative" << nl << exit(FatalIOError);
    }
    seed_ = uint64_t(seed);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

uint64_t Foam::coagulation::streamSeeds::operator()
(
    const label index,
    const purpose p
) const
{
    uint64_t s = coag::mix64(seed_);
    s = coag::mix64(s ^ uint64_t(Pstream::myProcNo()));
    s = coag::mix64(s ^ uint64_t(index));
    s = coag::mix64(s ^ uint64_t(time_.timeIndex()/stepInterval_));
    s = coag::mix64(s ^ uint64_t(p));
    return s;
}


// ************************************************************************* //
