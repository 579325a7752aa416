/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
\*---------------------------------------------------------------------------*/

#include "saffmanTurnerKernel.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(saffmanTurnerKernel, 0);
    addToRunTimeSelectionTable(coagulationKernel, saffmanTurnerKernel, dictionary);
}


// ************************************************************************* //
