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

      S. inception + coagulation in every cell (exact stochastic jump process)
      A. every particle moves with the frozen carrier flow U over the step
         (continuous positions, outflow removed, inflow injected)

    in the order S(dt) A(dt) (Lie, the paper's scheme, first order) or
    A(dt/2) S(dt) A(dt/2) (Strang, second order): entry 'splitting'.

    Writes the moments M0..M3 as volScalarFields, the particles under
    lagrangian/coagulationCloud, and the sampled moment series to HDF5.

    Reads constant/coagulationProperties and the velocity U of the start time.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "coagulationCloud.H"
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
        const scalar dt = runTime.deltaTValue();

        Info<< "Time = " << runTime.timeName()
            << "  particles = " << returnReduce(cloud.size(), sumOp<label>())
            << nl;

        // Operator splitting over dt (Patterson & Wagner 2011, §2) of
        //   S: the source terms, each cell on its own: inception (eqs 10,
        //      20) and coagulation (SWA jumps 21-22, DSA jumps 11-15)
        //   A: transport, every particle with the frozen flow U, then its
        //      random walk dX = grad(D) dt + sqrt(2D) dW (coagulation-
        //      diffusion paper, eq. 8); outflow leaves, walls rebound or
        //      take the particle (deposition); then inflow enters
        timer.start();
        if (cloud.splitting() == coagulationCloud::splittingScheme::Lie)
        {
            // Lie, the paper's scheme: S(dt) then A(dt); first order in dt
            cloud.cellStep(dt);
            timer.coagulationDone();
            cloud.transport(U, dt);
            timer.transportDone(cloud.size());
        }
        else
        {
            // Strang: A(dt/2), S(dt), A(dt/2); second order in dt
            cloud.transport(U, 0.5*dt, streamSeeds::inflowFirstHalf);
            timer.transportDone(cloud.size());
            cloud.cellStep(dt);
            timer.coagulationDone();
            cloud.transport(U, 0.5*dt);
            timer.transportDone(cloud.size());
        }

        // The cloud functions on the new state: M0..M3 (eq. 37), samples
        cloud.postStep();

        if (runTime.write())
        {
            cloud.onWrite();
            timer.report
            (
                cloud.events(), cloud.transportStep().transfers(),
                cloud.stepper().workSinceStart()
            );
        }
    }

    // Samples to disk, the last write marked complete, balances checked
    cloud.endRun();

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
