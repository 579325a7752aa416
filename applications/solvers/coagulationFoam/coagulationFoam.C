/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
-------------------------------------------------------------------------------
Application
    coagulationFoam

Group
    grpLagrangianSolvers

Description
    Inception, coagulation and advection of a particle population resolved
    in particle size, by the stochastic particle methods of Patterson &
    Wagner (2011): every mesh cell holds a weighted stochastic particle
    population (SWA; DSA1/DSA2 as options), stepped by operator splitting

      1. inception + coagulation in every cell (exact stochastic jump process)
      2. every particle moves with the frozen carrier flow U over the step
         (continuous positions, outflow removed, inflow injected)

    Writes the moments M0..M3 as volScalarFields, the particles under
    lagrangian/coagulationCloud, and the sampled moment series to HDF5.

    Reads constant/coagulationProperties and the velocity U of the start time.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "coagulationCloud.H"
#include "coagulationSampler.H"
#include "splitStepTimer.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Inception-coagulation-advection of a weighted stochastic particle"
        " population (SWA / DSA1 / DSA2) by operator splitting"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "createFields.H"

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        // The last write is complete once run() has had the function
        // objects write too: mark it so for restarts
        cloud.completeWrite();

        ++runTime;
        const scalar splitTimeStep = runTime.deltaTValue();

        Info<< "Time = " << runTime.timeName()
            << "  particles = " << returnReduce(cloud.size(), sumOp<label>())
            << nl;

        // 1. Source terms: inception + coagulation, each cell on its own
        timer.start();
        cloud.coagulate(splitTimeStep);
        timer.stopCoagulation();

        // 2. Transport: every particle moves with the flow over the step
        cloud.advect(U, splitTimeStep);
        timer.stopTransport(cloud.size());

        // Moments M0..M3 of the new state, sampled when due
        cloud.updateMoments();
        sampler.sample();

        if (runTime.write())
        {
            cloud.report();
            timer.report(cloud.events().coagulations);
        }
    }

    sampler.flush();
    cloud.completeWrite();
    cloud.checkBalance();

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
