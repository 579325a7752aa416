/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
\*---------------------------------------------------------------------------*/

#include "multiplicativeKernel.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(multiplicativeKernel, 0);
    addToRunTimeSelectionTable(coagulationKernel, multiplicativeKernel, dictionary);
}


// ************************************************************************* //
