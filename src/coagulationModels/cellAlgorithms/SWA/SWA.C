/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
\*---------------------------------------------------------------------------*/

#include "SWA.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(SWA, 0);
    addToRunTimeSelectionTable(cellAlgorithm, SWA, kernel);
}


// ************************************************************************* //
