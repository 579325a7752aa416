/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
\*---------------------------------------------------------------------------*/

#include "constantKernel.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(constantKernel, 0);
    addToRunTimeSelectionTable(coagulationKernel, constantKernel, dictionary);
}


// ************************************************************************* //
