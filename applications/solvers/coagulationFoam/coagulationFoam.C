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
#include "caseChecks.H"
#include "runProgress.H"

#include <csignal>
#include <new>

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

    // A write past a file size limit (ulimit -f) then fails with EFBIG and
    // stops the run with a message, as on a full disk, instead of SIGXFSZ;
    // memory exhausted throws std::bad_alloc (OpenFOAM's handler would
    // abort without naming the cause), answered below
    std::signal(SIGXFSZ, SIG_IGN);
    std::set_new_handler(nullptr);

    // A line every step for short runs, else progress lines (runProgress)
    coagulation::runProgress progress(runTime);

    Info<< "\nStarting time loop\n" << endl;

    try
    {
        while (runTime.run())
        {
            // The last write is complete once run() has had the function
            // objects write too: mark it so for restarts
            cloud.completeWrite();

            ++runTime;
            progress.step(cloud.size());

            // The split step over deltaT (Patterson & Wagner 2011,
            // section 2): Strang A(dt/2) S(dt) A(dt/2) or Lie S(dt) A(dt),
            // S inception + coagulation in every cell, A transport; then
            // the cloud functions on the new state (M0..M3, samples)
            cloud.evolve();

            const bool written = runTime.write();
            progress.afterStep(cloud.size(), written);
            if (written)
            {
                // The cloud functions' output (the balances checked), then
                // the split step's wall times
                cloud.onWrite();
                cloud.reportTimes();
            }
        }

        // Samples to disk, the last write marked complete, balances checked
        cloud.endRun();
        progress.end();
    }
    catch (const std::bad_alloc&)
    {
        FatalErrorInFunction
            << "Out of memory at time " << runTime.timeName() << " with "
            << cloud.size() << " particles on this processor." << nl
            << "    Lower statisticalWeight/n or set numberControl/"
            << "maxParticlesPerCell in " << cloud.properties().objectPath()
            << nl << exit(FatalError);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
