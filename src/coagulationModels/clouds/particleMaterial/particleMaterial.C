/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "particleMaterial.H"
#include "caseChecks.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * //

coag::ParticleMaterial Foam::coagulation::readParticleMaterial
(
    const dictionary& properties,
    const string& model
)
{
    if (!properties.isDict("particles"))
    {
        FatalIOErrorInFunction(properties)
            << "The " << model.c_str() << " needs the particles' material:"
            << " entry 'particles { density <kg/m3>; }' in "
            << properties.name() << nl << exit(FatalIOError);
    }
    const dictionary& dict = properties.subDict("particles");
    caseChecks::keywords(dict, {"density", "massUnit"});
    coag::ParticleMaterial material;
    material.density = caseChecks::positive(dict, "density");
    if (dict.found("massUnit"))
    {
        material.massUnit = caseChecks::positive(dict, "massUnit");
    }
    return material;
}


Foam::scalar Foam::coagulation::readParticleMass
(
    const dictionary& dict,
    const string& model
)
{
    if (dict.found("mass") == dict.found("diameter"))
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << " needs exactly one of 'mass'"
            << " (in the particles' massUnit) and 'diameter' (m, a sphere of"
            << " the particles' material)" << nl << exit(FatalIOError);
    }
    if (dict.found("mass"))
    {
        return caseChecks::positive(dict, "mass");
    }
    const coag::ParticleMaterial material =
        readParticleMaterial(dict.topDict(), model + " (its 'diameter')");
    const scalar d = caseChecks::positive(dict, "diameter");
    const scalar mass = material.mass(d);
    if (!(mass > 0) || !std::isfinite(mass))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'diameter' = " << d << " in " << dict.name()
            << " makes a particle of mass " << mass << " (in the massUnit "
            << material.massUnit << " kg), outside the range of numbers"
            << nl << exit(FatalIOError);
    }
    return mass;
}


// ************************************************************************* //
