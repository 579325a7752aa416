// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_BROWNIANKERNEL_HPP
#define COAGULATION_BROWNIANKERNEL_HPP

#include "coagulation/aerosol/AerosolProperties.hpp"
#include "coagulation/kernels/CoagulationKernel.hpp"

#include <string>
#include <vector>

namespace coag {

//- The regimes of Brownian coagulation, by the particles' Knudsen number Kn = 2 lambda / d.
enum class BrownianRegime { freeMolecular, continuum, transition };

//- "freeMolecular", "continuum", "transition"; parseBrownianRegime throws
//  std::invalid_argument for another name.
std::string brownianRegimeName(BrownianRegime regime);
BrownianRegime parseBrownianRegime(const std::string& name);

//- Brownian coagulation of spheres of one material in a gas (masses in the material's
//  massUnit, kg by default; K in m3/s).
//  With d the diameter, c = sqrt(8kT/(pi m)) the mean thermal speed, C the Cunningham
//  factor and D = kTC/(3 pi mu d) the diffusivity of each particle (i, j):
//    freeMolecular  K = (pi/4) (di + dj)^2 sqrt(ci^2 + cj^2)        (kinetic theory)
//    continuum      K = 2 pi (Di + Dj)(di + dj)                    (Smoluchowski, slip-corrected)
//    transition     Fuchs' interpolation, K = 2 pi (Di + Dj)(di + dj) / F with
//                   F = (di + dj)/(di + dj + 2 sqrt(gi^2 + gj^2))
//                     + 8 (Di + Dj) / (sqrt(ci^2 + cj^2)(di + dj)),
//                   gi = ((di + li)^3 - (di^2 + li^2)^(3/2)) / (3 di li) - di,
//                   li = 8 Di / (pi ci)
//  (Fuchs 1964; the form of Seinfeld & Pandis table 13.1 and Jacobson, Fundamentals of
//  Atmospheric Modeling, 2nd ed., eq. 15.33). The transition kernel tends to the
//  free-molecular one as Kn -> infinity and to the slip-corrected continuum one as Kn -> 0.
//
//  Product-sum majorants in the mass m (d = a m^(1/3), a = (6 massUnit/(pi rho))^(1/3)),
//  four terms each (seven sampler columns under SWA):
//    freeMolecular  (xi + xj)^2 sqrt(1/mi + 1/mj) <= f (xi^2 + xj^2)(mi^(-1/2) + mj^(-1/2))
//                   with x = m^(1/3) and f = freeMolecularFactor: the ratio of the two
//                   depends on t = xj/xi alone, and f is above the largest
//                   (1 + t)^2 sqrt(1 + t^-3) / ((1 + t^2)(1 + t^(-3/2))) = 1.41779 (at
//                   t = 1.52), so Khat / K lies between 1.0016 and f = 1.42.
//    continuum      C <= s = 1 + Abar/d with Abar = 2 lambda (A1 + A2) (SlipCorrection), so
//                   Khat = (2kT/3mu)(si/di + sj/dj)(di + dj); Khat / K <= (A1 + A2)/A1 = 1.32.
//    transition     two majorants, as two groups: the free-molecular one (K is below the
//                   free-molecular K, F exceeding its second term) and the continuum one
//                   times transitionContinuumMargin; the sampler proposes from the one
//                   whose sum over the population is the lesser at each build of the
//                   sampler's tree.
class BrownianKernel : public CoagulationKernel {
public:
    //- The continuum majorant's factor in the transition regime: Fuchs' kernel exceeds the
    //  continuum majorant by up to 1.4 % (a particle of Kn ~ 0.03 meeting one 50 times
    //  larger; the largest ratio over diameters 0.1 nm to 1 mm, T 250 to 2500 K, p 0.01 to
    //  100 bar and densities 500 to 20000 kg/m3 is 1.0138), which the factor covers
    static constexpr double transitionContinuumMargin = 1.02;

    //- The free-molecular majorant's factor f (above): 1.42 >= 1.41779, the largest ratio
    static constexpr double freeMolecularFactor = 1.42;

    //- Throws std::invalid_argument for a gas or material that is not positive and finite.
    BrownianKernel(BrownianRegime regime, const GasState& gas, const ParticleMaterial& material);

    std::string name() const override { return "Brownian"; }
    double operator()(const ParticleType& a, const ParticleType& b) const override;
    int nBasis() const override { return 7; }
    void basis(const ParticleType& z, double* phi) const override;
    const std::vector<MajorantTerm>& majorantTerms() const override { return terms_; }
    bool constantBasis(int b) const override { return b == 0; }

    BrownianRegime regime() const { return regime_; }
    const GasState& gas() const { return gas_; }
    const ParticleMaterial& material() const { return material_; }

    //- The three kernels at (a, b), whatever the regime of this one
    double freeMolecular(const ParticleType& a, const ParticleType& b) const;
    double continuum(const ParticleType& a, const ParticleType& b) const;
    double transition(const ParticleType& a, const ParticleType& b) const;

    //- The single-particle quantities: diameter [m], mean thermal speed [m/s], Cunningham
    //  factor, diffusivity [m2/s]
    struct Single {
        double d, c, C, D;
    };
    Single single(double mass) const;

private:
    BrownianRegime regime_;
    GasState gas_;
    ParticleMaterial material_;
    SlipCorrection slip_;
    double kT_;
    double lambda_;
    double a_;       //!< d = a m^(1/3)
    // The single-particle quantities at unit mass: c = speed1 m^(-1/2), Kn = knudsen1 m^(-1/3),
    // D = diffusivity1 C m^(-1/3); the kernels' factors (pi/4) a^2 speed1 and 2kT/(3 mu)
    double speed1_, knudsen1_, diffusivity1_, freeMolecular1_, continuum1_;
    double slipBound1_;  //!< the slip bound s = 1 + slipBound1 m^(-1/3)
    std::vector<MajorantTerm> terms_;
};

} // namespace coag

#endif
