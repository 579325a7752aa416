/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "coagulationParticle.H"
#include "IOstreams.H"
#include "IOField.H"
#include "Cloud.H"
#include "restartPrecision.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const std::size_t Foam::coagulation::coagulationParticle::sizeofFields
(
    sizeof(coagulationParticle) - sizeof(particle)
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::coagulationParticle::coagulationParticle
(
    const polyMesh& mesh,
    Istream& is,
    bool readFields,
    bool newFormat
)
:
    particle(mesh, is, readFields, newFormat),
    mass_(0),
    weight_(0),
    dispersal_(Zero)
{
    if (readFields)
    {
        if (is.format() == IOstream::ASCII)
        {
            is >> mass_ >> weight_ >> dispersal_;
        }
        else if (!is.checkLabelSize<>() || !is.checkScalarSize<>())
        {
            is.beginRawRead();
            readRawScalar(is, &mass_);
            readRawScalar(is, &weight_);
            readRawScalar(is, dispersal_.data(), vector::nComponents);
            is.endRawRead();
        }
        else
        {
            is.read(reinterpret_cast<char*>(&mass_), sizeofFields);
        }
    }

    is.check(FUNCTION_NAME);
}


void Foam::coagulation::coagulationParticle::readFields
(
    Cloud<coagulationParticle>& c
)
{
    const bool valid = c.size();

    particle::readFields(c);

    IOField<scalar> mass(c.fieldIOobject("mass", IOobject::MUST_READ), valid);
    c.checkFieldIOobject(c, mass);

    IOField<scalar> weight(c.fieldIOobject("weight", IOobject::MUST_READ), valid);
    c.checkFieldIOobject(c, weight);

    label i = 0;
    for (coagulationParticle& p : c)
    {
        p.mass_ = mass[i];
        p.weight_ = weight[i];
        ++i;
    }
}


void Foam::coagulation::coagulationParticle::writeFields
(
    const Cloud<coagulationParticle>& c
)
{
    // All digits: a restart goes on from exactly the state written
    const restartPrecision allDigits;

    particle::writeFields(c);

    const label np = c.size();

    IOField<scalar> mass(c.fieldIOobject("mass", IOobject::NO_READ), np);
    IOField<scalar> weight(c.fieldIOobject("weight", IOobject::NO_READ), np);

    label i = 0;
    for (const coagulationParticle& p : c)
    {
        mass[i] = p.mass_;
        weight[i] = p.weight_;
        ++i;
    }

    mass.write(np > 0);
    weight.write(np > 0);
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

Foam::Ostream& Foam::coagulation::operator<<
(
    Ostream& os,
    const coagulationParticle& p
)
{
    if (os.format() == IOstream::ASCII)
    {
        os  << static_cast<const particle&>(p)
            << token::SPACE << p.mass_
            << token::SPACE << p.weight_
            << token::SPACE << p.dispersal_;
    }
    else
    {
        os  << static_cast<const particle&>(p);
        os.write
        (
            reinterpret_cast<const char*>(&p.mass_),
            coagulationParticle::sizeofFields
        );
    }

    os.check(FUNCTION_NAME);
    return os;
}


// ************************************************************************* //
