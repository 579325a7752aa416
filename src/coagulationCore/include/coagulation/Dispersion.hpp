// coagulationCore: the random-walk half of particle transport. Copyright (C) 2025-2026 the
// coagulationFoam authors. SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_DISPERSION_HPP
#define COAGULATION_DISPERSION_HPP

#include <cstdint>

namespace coag {

//- A counter-based stream: the k-th draw is a pure function of (key, k), the SplitMix64
//  sequence started at key (Steele, Lea & Flood, "Fast splittable pseudorandom number
//  generators", 2014). Every particle of every transport step gets its own key, so that a
//  random walk step does not depend on which thread moves the particle or on anything drawn
//  before it; seeding costs nothing, unlike a Mersenne twister per particle.
class CounterStream {
public:
    explicit CounterStream(std::uint64_t key) : state_(key) {}

    std::uint64_t next()
    {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }

    //- Uniform on the open interval (0,1) (53 bits, centred in their bin, as Rng::uniform).
    double uniform()
    {
        const double u =
            (static_cast<double>(next() >> 11) + 0.5) * (1.0 / 9007199254740992.0);
        return u < 1.0 ? u : 1.0 - 1.0 / 9007199254740992.0;
    }

    //- Three independent standard normals (Box-Muller on two uniform pairs; the fourth
    //  normal is dropped so that every particle uses exactly four draws).
    void normal3(double xi[3]);

private:
    std::uint64_t state_;
};

//- The gas and material that set a particle's Brownian diffusivity.
struct BrownianGas {
    double temperature = 293.15;   //- T [K]
    double viscosity = 1.81e-5;    //- dynamic viscosity mu [Pa s]
    double meanFreePath = 6.65e-8; //- lambda [m]
    double density = 1000;         //- material density of the (spherical) particles [kg/m^3]
    double massUnit = 1;           //- kg per unit of particle mass (1: masses in kg)
    //- Cunningham slip correction Cc = 1 + Kn (A1 + A2 exp(-A3/Kn)), Kn = 2 lambda/d
    //  (Davies 1945 constants, as in Hinds, Aerosol Technology, eq. 3.20)
    double A1 = 1.257, A2 = 0.400, A3 = 1.10;
};

//- Boltzmann's constant [J/K].
constexpr double boltzmann = 1.380649e-23;

//- Diameter [m] of a sphere of the given mass (in BrownianGas::massUnit units).
double sphereDiameter(double mass, const BrownianGas& gas);

//- Cunningham slip correction for a sphere of diameter d [m].
double slipCorrection(double diameter, const BrownianGas& gas);

//- Stokes-Einstein diffusivity with slip, D = k T Cc / (3 pi mu d) [m^2/s], of a sphere of
//  the given mass; the mass must be positive.
double brownianDiffusivity(double mass, const BrownianGas& gas);

} // namespace coag

#endif
