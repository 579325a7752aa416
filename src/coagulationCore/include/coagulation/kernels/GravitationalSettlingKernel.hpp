// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_GRAVITATIONALSETTLINGKERNEL_HPP
#define COAGULATION_GRAVITATIONALSETTLINGKERNEL_HPP

#include "coagulation/aerosol/AerosolProperties.hpp"
#include "coagulation/kernels/CoagulationKernel.hpp"

#include <string>
#include <vector>

namespace coag {

//- Coagulation by differential sedimentation (gravitational collection) of spheres of one
//  material in a gas (masses in the material's massUnit; K in m3/s):
//      K = E (pi/4) (di + dj)^2 |vi - vj|,   v = rho g d^2 C(Kn) / (18 mu),
//  the larger particle sweeping the smaller one out of the cross-section of the sum of their
//  radii; v is the Stokes terminal velocity with the Cunningham factor C of the gas's mean free
//  path (SlipCorrection; Seinfeld & Pandis, Atmospheric Chemistry and Physics, eq. 9.42 for v
//  and appendix 13.A for the kernel).
//  E is the collision efficiency: 1 is the geometric (purely kinematic) collection; the
//  literature also uses a constant below 1 or forms depending on the size ratio and the
//  Stokes number of the smaller particle (Seinfeld & Pandis appendix 13.A; Pruppacher & Klett
//  chapter 14). Only a constant E is implemented here.
//  Equal particles settle together: K(z, z) = 0.
//
//  Product-sum majorant in x = m^(1/3) (d = a x, a = (6 massUnit/(pi rho))^(1/3)):
//  |vi - vj| <= vi + vj and C <= 1 + Abar/d, Abar = 2 lambda (A1 + A2) (SlipCorrection::bound),
//  so v <= cv (d^2 + Abar d), cv = rho g / (18 mu), and
//      Khat = E (pi/4) cv a^2 (xi + xj)^2 [a^2 (xi^2 + xj^2) + a Abar (xi + xj)]
//           = c2 (xi^4 + 2 xi^3 xj + 2 xi^2 xj^2 + 2 xi xj^3 + xj^4)
//           + c1 (xi^3 + 3 xi^2 xj + 3 xi xj^2 + xj^3),
//  c2 = E (pi/4) cv a^4, c1 = E (pi/4) cv a^3 Abar: nine terms on the basis
//  {1, x, x^2, x^3, x^4}. Khat / K is large for nearly equal particles (K -> 0 there): the
//  price of |vi - vj| <= vi + vj, which the fictitious jumps pay.
class GravitationalSettlingKernel : public CoagulationKernel {
public:
    //- g the magnitude of the gravitational acceleration [m/s2], E the collision efficiency.
    //  Throws std::invalid_argument for a gas, material, E or g that is not positive and
    //  finite.
    GravitationalSettlingKernel(const GasState& gas, const ParticleMaterial& material,
                                double efficiency = 1.0, double g = 9.81);

    std::string name() const override { return "gravitationalSettling"; }
    double operator()(const ParticleType& a, const ParticleType& b) const override;
    int nBasis() const override { return 5; }
    void basis(const ParticleType& z, double* phi) const override;
    const std::vector<MajorantTerm>& majorantTerms() const override { return terms_; }
    bool constantBasis(int b) const override { return b == 0; }

    const GasState& gas() const { return gas_; }
    const ParticleMaterial& material() const { return material_; }
    double efficiency() const { return efficiency_; }
    double g() const { return g_; }

    //- The terminal settling velocity [m/s] of a particle of the given mass
    double settlingVelocity(double mass) const;

private:
    //- The settling velocity of a sphere of diameter d [m]
    double velocityOfDiameter(double d) const;

    GasState gas_;
    ParticleMaterial material_;
    SlipCorrection slip_;
    double efficiency_;
    double g_;
    double lambda_;
    double a_;    //!< d = a m^(1/3)
    double cv_;   //!< v = cv d^2 C
    std::vector<MajorantTerm> terms_;
};

} // namespace coag

#endif
