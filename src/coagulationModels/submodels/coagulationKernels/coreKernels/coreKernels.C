/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
-------------------------------------------------------------------------------
Description
    The core library's kernels as run-time selectable coagulationKernel
    types, one macro line each (x, y the particle masses):
      constant        K = K0                           (paper §3.1)
      additive        K = K0 (x + y)                   (paper §3.2)
      multiplicative  K = K0 x y                       (gels at finite time)
      saffmanTurner   K = K0 (x^(1/3) + y^(1/3))^3     (KSW eq. 1.2)
    The formulas and their majorants are coag::CoagulationKernel's. The
    Saffman-Turner kernel of each cell's dissipation rate is
    localSaffmanTurner (its own folder).

\*---------------------------------------------------------------------------*/

#include "coagulationKernel.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * * * * Macros  * * * * * * * * * * * * * * * * //

//- A coagulationKernel type 'Name' for the core kernel of that name
#define makeCoreCoagulationKernel(Name)                                        \
    class Name##Kernel                                                         \
    :                                                                          \
        public coagulationKernel                                               \
    {                                                                          \
    public:                                                                    \
        TypeName(#Name);                                                       \
        Name##Kernel(const dictionary& dict, const fvMesh&)                    \
        :                                                                      \
            coagulationKernel(dict, #Name)                                     \
        {}                                                                     \
    };                                                                         \
    defineTypeNameAndDebug(Name##Kernel, 0);                                   \
    addToRunTimeSelectionTable(coagulationKernel, Name##Kernel, dictionary);


// * * * * * * * * * * * * * * * * * Kernels * * * * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
namespace coagulationKernels
{
    makeCoreCoagulationKernel(constant)
    makeCoreCoagulationKernel(additive)
    makeCoreCoagulationKernel(multiplicative)
    makeCoreCoagulationKernel(saffmanTurner)
}
}
}


// ************************************************************************* //
