/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "streamSeeds.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- SplitMix64 finaliser: decorrelates the seeds of neighbouring streams
inline uint64_t mix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30))*0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27))*0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::streamSeeds::streamSeeds
(
    const dictionary& dict,
    const Time& time
)
:
    time_(time),
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
    uint64_t s = mix64(seed_);
    s = mix64(s ^ uint64_t(Pstream::myProcNo()));
    s = mix64(s ^ uint64_t(index));
    s = mix64(s ^ uint64_t(time_.timeIndex()));
    s = mix64(s ^ uint64_t(p));
    return s;
}


// ************************************************************************* //
