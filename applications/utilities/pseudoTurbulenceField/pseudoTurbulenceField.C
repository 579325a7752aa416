// coagulationFoam. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
//
// pseudoTurbulenceField: writes one frozen sample of the randomized spectral model of Kolmogorov
// pseudo-turbulence (Kolodko, Sabelfeld and Wagner §5.2, eqs 5.11-5.16; coag::PseudoTurbulence)
// into the field U of a case, so that coagulationFoam advects its particles in it (U is frozen
// there). U must exist (its boundary types are kept): the cell values and the values of every
// patch that fixes its value (fixedValue, ...) are set to meanVelocity + U_E(x) at the cell and
// face centres; other patches (zeroGradient, empty, ...) are left to their type.
//
// system/pseudoTurbulenceDict:
//     epsilon 1e-3; nu 1.5e-5;   // or: u0 0.1; eta 1e-3;  or: epsilon 1; eta 2; (one pair)
//     L 0.1;                     // integral scale: k0 = 2 pi / L, kmax = 2 pi / eta
//     logIntervals 4;            // n0 of the log-scale refinement (5.15)
//     nPerInterval 8;            // harmonics per part
//     seed 1;                    // the sample (a field is a pure function of the seed)
//     meanVelocity (0 0 0);      // optional, added to the fluctuation
//
// Reports u0, eta, L, the harmonics, the mean and rms over the cells and the largest relative
// discrete divergence |sum_f (U_f . S_f)| / (sum_f |U_f| |S_f|) per cell (linear face values).
#include "fvCFD.H"

#include "coagulationReferences/pseudoTurbulence/PseudoTurbulence.hpp"

int main(int argc, char* argv[])
{
    argList::addNote
    (
        "Write a frozen sample of Kolmogorov pseudo-turbulence (Kolodko, Sabelfeld and Wagner"
        " 5.11-5.16) into U, from system/pseudoTurbulenceDict"
    );
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    IOdictionary dict
    (
        IOobject
        (
            "pseudoTurbulenceDict",
            runTime.system(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );
    const label n0 = dict.lookupOrDefault<label>("logIntervals", 4);
    const label n = dict.lookupOrDefault<label>("nPerInterval", 8);
    const label seed = readLabel(dict.lookup("seed"));
    const vector meanU = dict.lookupOrDefault<vector>("meanVelocity", Zero);
    const scalar L = readScalar(dict.lookup("L"));

    coag::PseudoTurbulenceParameters p;
    try
    {
        if (dict.found("u0"))
        {
            p = coag::PseudoTurbulenceParameters::fromScales
            (
                readScalar(dict.lookup("u0")), readScalar(dict.lookup("eta")), L, n0, n
            );
        }
        else if (!dict.found("nu"))
        {
            // epsilon and eta as given: k0 = 2 pi / L, kmax = 2 pi / eta (what the core's
            // studies build, so that a seed gives the same field bit for bit)
            p.epsilon = readScalar(dict.lookup("epsilon"));
            p.k0 = constant::mathematical::twoPi/L;
            p.kmax = constant::mathematical::twoPi/readScalar(dict.lookup("eta"));
            p.logIntervals = n0;
            p.nPerInterval = n;
        }
        else
        {
            p = coag::PseudoTurbulenceParameters::fromDissipation
            (
                readScalar(dict.lookup("epsilon")), readScalar(dict.lookup("nu")), L, n0, n
            );
        }
        p.check();
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(dict) << e.what() << exit(FatalIOError);
    }
    const coag::PseudoTurbulence field(p, std::uint64_t(seed));

    auto eval = [&](const vector& x)
    {
        const double xx[3] = {x.x(), x.y(), x.z()};
        double u[3];
        field.velocity(xx, u);   // (5.14)
        return meanU + vector(u[0], u[1], u[2]);
    };

    volVectorField U
    (
        IOobject("U", runTime.timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE),
        mesh
    );
    vectorField& Ui = U.primitiveFieldRef();
    forAll(Ui, celli)
    {
        Ui[celli] = eval(mesh.C()[celli]);
    }
    label setPatches = 0;
    forAll(U.boundaryField(), patchi)
    {
        fvPatchVectorField& pf = U.boundaryFieldRef()[patchi];
        if (pf.fixesValue())
        {
            const vectorField& Cf = mesh.C().boundaryField()[patchi];
            vectorField v(Cf.size());
            forAll(Cf, i)
            {
                v[i] = eval(Cf[i]);
            }
            pf == v;
            ++setPatches;
        }
    }

    // discrete divergence of the written field, relative to the flux magnitudes
    const surfaceScalarField phi(fvc::interpolate(U) & mesh.Sf());
    const surfaceScalarField absPhi(mag(fvc::interpolate(U))*mesh.magSf());
    const scalarField divU(fvc::surfaceIntegrate(phi)().primitiveField()*mesh.V());
    const scalarField sumAbs(fvc::surfaceSum(absPhi)().primitiveField());
    scalar relDiv = 0;
    forAll(divU, celli)
    {
        relDiv = max(relDiv, mag(divU[celli])/max(sumAbs[celli], VSMALL));
    }
    relDiv = returnReduce(relDiv, maxOp<scalar>());
    const vector meanCell = gAverage(Ui);
    const scalar rms = Foam::sqrt(gAverage(magSqr(Ui - meanCell)));

    Info<< "Kolmogorov pseudo-turbulence (5.11)-(5.16): " << field.harmonics()
        << " harmonics (" << n0 << " x " << n << "), seed " << seed << nl
        << "    u0 = " << p.u0() << ", eta = " << p.eta() << ", L = " << p.L()
        << ", epsilon = " << p.epsilon << nl
        << "    over the cells: mean " << meanCell << ", rms |U - mean| = " << rms
        << " (model sqrt(3) u0 = " << Foam::sqrt(3.0)*p.u0() << ")" << nl
        << "    largest relative discrete divergence " << relDiv
        << " (the continuous field is solenoidal; this is the mesh's resolution of it)" << nl
        << "    patches set: " << setPatches << nl << endl;

    U.write();
    Info<< "Wrote " << U.objectPath() << nl << "End" << nl << endl;
    return 0;
}
