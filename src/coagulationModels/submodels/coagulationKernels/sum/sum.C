/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "sum.H"
#include "caseChecks.H"
#include "HashTable.H"
#include "addToRunTimeSelectionTable.H"

#include "coagulation/kernels/SumKernel.hpp"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
namespace coagulationKernels
{
    defineTypeNameAndDebug(sum, 0);
    addToRunTimeSelectionTable(coagulationKernel, sum, dictionary);
}
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::PtrList<Foam::coagulation::coagulationKernel>
Foam::coagulation::coagulationKernels::sum::readParts
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    caseChecks::keywords(dict, {"type", "kernels"});
    if (!dict.isDict("kernels"))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'kernels' in " << dict.name() << " is missing or not a"
            << " dictionary of kernels (named kernel dictionaries)" << nl
            << exit(FatalIOError);
    }
    const dictionary& kernels = dict.subDict("kernels");
    if (kernels.empty())
    {
        FatalIOErrorInFunction(kernels)
            << "Entry 'kernels' in " << dict.name() << " has no kernel: a sum"
            << " needs at least one (for no coagulation: 'type none;')" << nl
            << exit(FatalIOError);
    }

    PtrList<coagulationKernel> parts(kernels.size());
    HashTable<word> partOfType;   // type -> the part of that type
    label parti = 0;
    for (const entry& e : kernels)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(kernels)
                << "Entry '" << e.keyword() << "' in " << kernels.name()
                << " is not a kernel dictionary" << nl << exit(FatalIOError);
        }
        const dictionary& part = e.dict();
        const word type(part.get<word>("type"));
        if (type == typeName)
        {
            // The check of two parts of one type sees only this level: a
            // nested sum could hold a mechanism the outer sum holds too
            FatalIOErrorInFunction(part)
                << "Entry '" << e.keyword() << "' in " << kernels.name()
                << " is itself a sum: a sum inside a sum could count a"
                << " mechanism twice." << nl << "    List its kernels in "
                << kernels.name() << " instead" << nl << exit(FatalIOError);
        }
        if (partOfType.found(type))
        {
            FatalIOErrorInFunction(kernels)
                << "Entries '" << partOfType[type] << "' and '" << e.keyword()
                << "' in " << kernels.name() << " are both of type " << type
                << ": the sum would count that mechanism twice" << nl
                << exit(FatalIOError);
        }
        partOfType.insert(type, e.keyword());
        parts.set(parti++, coagulationKernel::New(part, mesh));
    }
    return parts;
}


std::unique_ptr<coag::CoagulationKernel>
Foam::coagulation::coagulationKernels::sum::sumOf
(
    const PtrList<coagulationKernel>& parts,
    const label celli
)
{
    std::vector<coag::SumKernel::Part> kernels;
    for (const coagulationKernel& part : parts)
    {
        kernels.push_back
        (
            celli < 0 ? part.sharedCore() : part.sharedCellKernel(celli)
        );
    }
    return std::make_unique<coag::SumKernel>(std::move(kernels));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::coagulationKernels::sum::sum
(
    PtrList<coagulationKernel>&& parts
)
:
    // The algorithms are built with the sum of the parts' layout kernels
    // (the majorant layout of every cell's sum)
    coagulationKernel(0, sumOf(parts, -1)),
    parts_(std::move(parts))
{}


Foam::coagulation::coagulationKernels::sum::sum
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    sum(readParts(dict, mesh))
{
    bool perCellParts = false;
    for (const coagulationKernel& part : parts_)
    {
        perCellParts = perCellParts || part.perCell();
    }
    if (perCellParts)
    {
        cellKernels().reserve(mesh.nCells());
        for (label celli = 0; celli < mesh.nCells(); ++celli)
        {
            cellKernels().push_back(sumOf(parts_, celli));
        }
    }

    const coag::CoagulationKernel& layout = core();
    Info<< "    sum of " << parts_.size() << " kernels: "
        << layout.nBasis() << " basis functions, "
        << layout.majorantTerms().size() << " majorant terms in "
        << layout.nMajorantGroups() << " groups" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::coagulation::coagulationKernels::sum::correct()
{
    bool changed = false;
    for (coagulationKernel& part : parts_)
    {
        changed = part.correct() || changed;
    }
    if (changed)
    {
        const label nCells = label(cellKernels().size());
        cellKernels().clear();
        for (label celli = 0; celli < nCells; ++celli)
        {
            cellKernels().push_back(sumOf(parts_, celli));
        }
    }
    return changed;
}


// ************************************************************************* //
