// coagulationFoam. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
//
// workDecomposition: a decomposition for the `manual` method that balances the work per cell
// (the field coagulationWork that the cellWork cloud function writes) with the smallest
// largest share, where OpenFOAM's weighted simple/hierarchical split the cumulative weight
// and leave a heavy cell that straddles a share with the rank it starts in (the measured
// shares of both on the additive duct are in doc/performance.md).
//
// Like hierarchical, the cells are cut into n.x slabs along x, each slab into n.y along y,
// each of those into n.z along z (cells ordered by their centre, ties by cell index); every
// cut is the exact linear partition of its cells' work (coag::partitionContiguous).
// With runsPerPart m > 1, each of those cuts may instead deal its cells as up to m n.d
// contiguous runs to its n.d parts (coag::partitionRuns: largest run first to the least
// loaded part), when that leaves a smaller largest share: a part is then a union of up to
// about m slabs. It balances work that sits in a few heavy cells (the additive duct: a
// largest share of 50.3 % of 2 ranks where any cut leaves 55 %), at the price of up to
// m n.d - 1 processor boundaries along d instead of n.d - 1.
//
// system/decomposeParDict:
//     numberOfSubdomains  2;
//     method              manual;
//     coeffs              { dataFile "cellDecomposition"; }   // written by this utility
//     workDecompositionCoeffs
//     {
//         n       (2 1 1);             // slabs along x, y, z: product numberOfSubdomains
//         field   coagulationWork;     // optional, the default
//         runsPerPart 1;               // optional, the default: contiguous slabs
//     }
//
// workDecomposition [-time T | -latestTime]  reads the field at that time (default: the
// latest), writes constant/<dataFile> (the mesh's faces instance), prints the work per
// processor and the balance (max/mean), beside that of OpenFOAM's weighted hierarchical
// decomposition of the same field (its cumulative split) for comparison.
// Then: decomposePar [-latestTime].
#include "fvCFD.H"
#include "decompositionMethod.H"
#include "labelIOList.H"
#include "timeSelector.H"

#include "coagulation/decomposition/WorkPartition.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

using namespace Foam;

namespace
{

//- Reject keywords of dict outside valid (FatalIOError naming the file and entry)
void checkKeywords(const dictionary& dict, const wordList& valid)
{
    for (const entry& e : dict)
    {
        if (!valid.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown keyword '" << e.keyword() << "' in " << dict.name()
                << "; valid: " << valid << exit(FatalIOError);
        }
    }
}

//- Cut cells (in place, ordered) into parts along component dir, each part then along the
//  later directions; assigns processors from firstProc on
void cut
(
    labelList& cells,
    const volVectorField::Internal& C,
    const scalarField& w,
    const Vector<label>& n,
    const label runsPerPart,
    const direction dir,
    const label firstProc,
    labelList& proc
)
{
    if (dir == 3)
    {
        for (const label c : cells)
        {
            proc[c] = firstProc;
        }
        return;
    }
    std::stable_sort
    (
        cells.begin(),
        cells.end(),
        [&](const label a, const label b) { return C[a][dir] < C[b][dir]; }
    );
    std::vector<double> cw(cells.size());
    forAll(cells, i)
    {
        cw[i] = w[cells[i]];
    }
    const label parts = n[dir];
    std::vector<std::size_t> part;
    try
    {
        part = coag::partitionRuns(cw, std::size_t(parts), std::size_t(runsPerPart));
    }
    catch (const std::invalid_argument& e)
    {
        FatalErrorInFunction
            << e.what() << " (" << cells.size() << " cells cut into " << parts
            << " along direction " << label(dir) << ")" << exit(FatalError);
    }
    label procsPerPart = 1;
    for (direction d = dir + 1; d < 3; ++d)
    {
        procsPerPart *= n[d];
    }
    for (label p = 0; p < parts; ++p)
    {
        DynamicList<label> sub;
        forAll(cells, i)
        {
            if (label(part[i]) == p)
            {
                sub.append(cells[i]);
            }
        }
        labelList subCells(std::move(sub));
        cut(subCells, C, w, n, runsPerPart, dir + 1, firstProc + p*procsPerPart, proc);
    }
}

void report
(
    const word& what,
    const labelList& proc,
    const scalarField& w,
    const label nProcs,
    const fvMesh& mesh
)
{
    scalarField work(nProcs, Zero);
    labelList cells(nProcs, Zero);
    forAll(proc, c)
    {
        work[proc[c]] += w[c];
        ++cells[proc[c]];
    }
    label boundaryFaces = 0;
    for (label f = 0; f < mesh.nInternalFaces(); ++f)
    {
        if (proc[mesh.faceOwner()[f]] != proc[mesh.faceNeighbour()[f]])
        {
            ++boundaryFaces;
        }
    }
    Info<< what << ":" << nl;
    forAll(work, p)
    {
        Info<< "    processor" << p << ": cells " << cells[p] << ", work " << work[p] << nl;
    }
    Info<< "    processor boundary faces = " << boundaryFaces << nl
        << "    work balance (max/mean) = " << max(work)/(sum(work)/nProcs + VSMALL) << nl;
}

} // namespace


int main(int argc, char* argv[])
{
    argList::addNote
    (
        "Write constant/<dataFile> for decomposePar's manual method: the cells cut into"
        " n.x * n.y * n.z parts with the smallest largest share of the coagulationWork"
        " field (system/decomposeParDict, workDecompositionCoeffs)"
    );
    argList::noParallel();
    timeSelector::addOptions(true, false);
    #include "setRootCase.H"
    #include "createTime.H"
    instantList times = timeSelector::selectIfPresent(runTime, args);
    if (!args.found("time") && !args.found("latestTime"))
    {
        times = instantList(1, runTime.times().last());
    }
    runTime.setTime(times.last(), 0);
    #include "createMesh.H"

    IOdictionary decompDict
    (
        IOobject
        (
            "decomposeParDict",
            runTime.system(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );
    const label nProcs = decompDict.get<label>("numberOfSubdomains");
    const word method = decompDict.get<word>("method");
    if (method != "manual")
    {
        FatalIOErrorInFunction(decompDict)
            << "Entry 'method' in " << decompDict.name() << " is " << method
            << "; workDecomposition writes the data of method manual" << exit(FatalIOError);
    }
    const dictionary& manualCoeffs =
        decompDict.found("manualCoeffs")
      ? decompDict.subDict("manualCoeffs")
      : decompDict.subDict("coeffs");
    const fileName dataFile = manualCoeffs.get<fileName>("dataFile");

    const dictionary& coeffs = decompDict.subDict("workDecompositionCoeffs");
    checkKeywords(coeffs, wordList({"n", "field", "runsPerPart"}));
    const Vector<label> n = coeffs.get<Vector<label>>("n");
    const word fieldName = coeffs.getOrDefault<word>("field", "coagulationWork");
    const label runsPerPart = coeffs.getOrDefault<label>("runsPerPart", 1);
    if (runsPerPart < 1)
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry 'runsPerPart' " << runsPerPart << " in " << coeffs.name()
            << ": must be >= 1" << exit(FatalIOError);
    }
    if (cmptMin(n) < 1 || n.x()*n.y()*n.z() != nProcs)
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry 'n' " << n << " in " << coeffs.name()
            << ": every component >= 1, product numberOfSubdomains = " << nProcs
            << exit(FatalIOError);
    }

    volScalarField work
    (
        IOobject
        (
            fieldName,
            runTime.timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        ),
        mesh
    );
    forAll(work, c)
    {
        if (!(work[c] >= 0) || !std::isfinite(work[c]))
        {
            FatalErrorInFunction
                << "Field " << fieldName << " at time " << runTime.timeName()
                << ": cell " << c << " has work " << work[c]
                << " (must be finite and >= 0)" << exit(FatalError);
        }
    }
    if (mesh.nCells() < nProcs)
    {
        FatalErrorInFunction
            << mesh.nCells() << " cells for " << nProcs << " processors" << exit(FatalError);
    }

    labelList cells(identity(mesh.nCells()));
    labelList proc(mesh.nCells(), -1);
    cut(cells, mesh.C(), work.primitiveField(), n, runsPerPart, 0, 0, proc);

    // For comparison: OpenFOAM's own weighted hierarchical decomposition of the same weights
    {
        dictionary hierarchical;
        hierarchical.add("numberOfSubdomains", nProcs);
        hierarchical.add("method", word("hierarchical"));
        dictionary hierarchicalCoeffs;
        hierarchicalCoeffs.add("n", n);
        hierarchicalCoeffs.add("order", word("xyz"));
        hierarchical.add("coeffs", hierarchicalCoeffs);
        const labelList cumulative =
            decompositionMethod::New(hierarchical)->decompose
            (
                mesh.cellCentres(),
                work.primitiveField()
            );
        report("hierarchical, weightField " + fieldName, cumulative, work, nProcs, mesh);
    }
    report("this decomposition", proc, work, nProcs, mesh);

    labelIOList out
    (
        IOobject
        (
            dataFile,
            mesh.facesInstance(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        proc
    );
    out.write();
    Info<< "Wrote " << out.objectPath() << nl << "End" << nl;
    return 0;
}
