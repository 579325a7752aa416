/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "growthModelList.H"
#include "particleMaterial.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- FatalIOError for an entry of dict that is neither a dictionary (a growth
//  model's) nor one of valid
void checkEntries(const Foam::dictionary& dict, const Foam::wordList& valid)
{
    for (const Foam::entry& e : dict)
    {
        if (!e.isDict() && !valid.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << e.keyword() << "' of " << dict.name()
                << " is neither one of " << valid << " nor a growth model's"
                << " dictionary (name { type <type>; ... })" << Foam::nl
                << Foam::exit(Foam::FatalIOError);
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::growthModelList::growthModelList
(
    const dictionary& properties,
    const fvMesh& mesh
)
:
    PtrList<growthModel>(),
    minimumMass_(0)
{
    if (!properties.found("growth"))
    {
        return;
    }
    if (!properties.isDict("growth"))
    {
        FatalIOErrorInFunction(properties)
            << "Entry 'growth' in " << properties.name() << " must be a"
            << " dictionary of growth models: growth { <name> { type <type>;"
            << " ... } }" << nl << exit(FatalIOError);
    }
    const dictionary& dict = properties.subDict("growth");
    checkEntries(dict, {"minimumMass", "minimumDiameter"});
    for (const entry& e : dict)
    {
        if (e.isDict())
        {
            append(growthModel::New(e.keyword(), e.dict(), mesh));
        }
    }
    if (dict.found("minimumMass") && dict.found("minimumDiameter"))
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << " takes one of 'minimumMass'"
            << " and 'minimumDiameter', not both" << nl << exit(FatalIOError);
    }
    if (dict.found("minimumMass"))
    {
        minimumMass_ = caseChecks::nonNegative(dict, "minimumMass");
    }
    else if (dict.found("minimumDiameter"))
    {
        minimumMass_ =
            readParticleMaterial(properties, "growth's 'minimumDiameter'")
           .mass(caseChecks::nonNegative(dict, "minimumDiameter"));
    }
    if (empty())
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << " lists no growth model:"
            << " growth { <name> { type constant | linear | surface |"
            << " condensation; ... } }" << nl << exit(FatalIOError);
    }
    Info<< "Growth: " << size() << " model(s), particles at or below mass "
        << minimumMass_ << " are gone" << nl << endl;
}


// ************************************************************************* //
