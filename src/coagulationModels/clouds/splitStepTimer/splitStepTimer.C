/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "splitStepTimer.H"
#include "FixedList.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::splitStepTimer::report
(
    const coag::StepStatistics& events,
    const transportModel::transferCounts& transfers,
    const scalar work
) const
{
    const double n = max(steps_, label(1));
    Info<< "Split step wall time (this processor, since start):" << nl
        << "    steps                      = " << steps_ << nl
        << "    per step: coagulation      = "
        << 1e3*coagulationSeconds_/n << " ms, transport = "
        << 1e3*transportSeconds_/n << " ms" << nl
        << "    particle moves per second  = "
        << moves_/max(transportSeconds_, 1e-12) << nl
        << "    coagulation events per second = "
        << double(events.coagulations)/max(coagulationSeconds_, 1e-12)
        << nl << endl;

    if (!Pstream::parRun())
    {
        return;
    }

    // Every processor's share: the work (the cell step's particles,
    // events and cell visits, cellStepper::work, which the cellWork
    // function writes per cell), the times and the particles handed
    // over
    const double allEvents =
        double(events.coagulations) + double(events.fictitious)
      + double(events.inceptions);
    List<FixedList<scalar, 9>> rows(Pstream::nProcs());
    FixedList<scalar, 9>& mine = rows[Pstream::myProcNo()];
    mine[0] = work/n;
    mine[1] = allEvents/n;
    mine[2] = 1e3*coagulationSeconds_/n;
    mine[3] = 1e3*transportSeconds_/n;
    mine[4] = moves_/n;
    mine[5] = transfers.particles/n;
    mine[6] = transfers.bytes/n/1024;
    mine[7] = transfers.rounds/n;
    mine[8] = 1e3*transfers.waitSeconds/n;
    Pstream::gatherList(rows);

    if (Pstream::master())
    {
        scalar maxWork = 0, sumWork = 0, maxWall = 0, sumWall = 0;
        Info<< "Per processor, per step: work (particles + events +"
            << " cell visits), events, coagulation ms, transport ms,"
            << " moves/s, particles sent, kB received, exchange rounds,"
            << " exchange wait ms, moves/s without the wait" << nl;
        forAll(rows, proci)
        {
            const FixedList<scalar, 9>& r = rows[proci];
            maxWork = max(maxWork, r[0]);
            sumWork += r[0];
            maxWall = max(maxWall, r[2] + r[3]);
            sumWall += r[2] + r[3];
            Info<< "    processor" << proci << ": " << r[0] << ' '
                << r[1] << ' ' << r[2] << ' ' << r[3] << ' '
                << 1e3*r[4]/max(r[3], 1e-12) << ' ' << r[5] << ' '
                << r[6] << ' ' << r[7] << ' ' << r[8] << ' '
                << 1e3*r[4]/max(r[3] - r[8], 1e-12) << nl;
        }
        const scalar nProcs = rows.size();
        Info<< "    work balance (max/mean)    = "
            << maxWork/max(sumWork/nProcs, 1e-12) << nl
            << "    wall balance (max/mean)    = "
            << maxWall/max(sumWall/nProcs, 1e-12) << nl << endl;
    }
}


// ************************************************************************* //
