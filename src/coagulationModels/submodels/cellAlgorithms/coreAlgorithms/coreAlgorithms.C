/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
-------------------------------------------------------------------------------
Description
    The core library's cell algorithms as run-time selectable cellAlgorithm
    types, one macro line each (Patterson & Wagner 2011):
      SWA   jumps 19-22, weighted particles         equalWeights no
      DSA1  jumps 9-12 with p = 1/2 (eq. 14)          equalWeights yes
      DSA2  jumps 9-12 with p = m1/(m1+m2) (eq. 15)   equalWeights yes

\*---------------------------------------------------------------------------*/

#include "cellAlgorithm.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * * * * Macros  * * * * * * * * * * * * * * * * //

//- A cellAlgorithm type 'Name' for the core algorithm of that name
#define makeCoreCellAlgorithm(Name, EqualWeights)                              \
    class Name                                                                 \
    :                                                                          \
        public cellAlgorithm                                                   \
    {                                                                          \
    public:                                                                    \
        TypeName(#Name);                                                       \
        Name                                                                   \
        (                                                                      \
            const coagulationKernel& kernel,                                   \
            const coag::InceptionModel& inception,                             \
            const coag::NumberControl& control                                 \
        )                                                                      \
        :                                                                      \
            cellAlgorithm(#Name, kernel, inception, control)                   \
        {}                                                                     \
        virtual bool equalWeights() const { return EqualWeights; }             \
    };                                                                         \
    defineTypeNameAndDebug(Name, 0);                                           \
    addToRunTimeSelectionTable(cellAlgorithm, Name, components);


// * * * * * * * * * * * * * * * * Algorithms  * * * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
namespace cellAlgorithms
{
    makeCoreCellAlgorithm(SWA, false)
    makeCoreCellAlgorithm(DSA1, true)
    makeCoreCellAlgorithm(DSA2, true)
}
}
}


// ************************************************************************* //
