// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/kernels/GravitationalSettlingKernel.hpp"
#include "coagulation/kernels/CubeRoot.hpp"

#include <cmath>

namespace coag {

namespace {

// The basis phi_b(m) of the majorant: powers of x = m^(1/3)
enum Basis { one, x1, x2, x3, x4 };

constexpr const char* who = "coag::GravitationalSettlingKernel";

} // namespace

GravitationalSettlingKernel::GravitationalSettlingKernel(const GasState& gas,
                                                         const ParticleMaterial& material,
                                                         double efficiency, double g)
    : gas_(gas), material_(material), efficiency_(efficiency), g_(g)
{
    gas_.check();
    material_.check();
    requirePositive(who, "the collision efficiency E", efficiency_);
    requirePositive(who, "the gravitational acceleration g [m/s2]", g_);
    using constants::pi;
    lambda_ = gas_.meanFreePath();
    a_ = material_.diameter(1.0);
    cv_ = material_.density * g_ / (18.0 * gas_.mu);

    // C <= slip.bound(Kn) = 1 + Abar/d
    const double Abar = 2.0 * lambda_ * (slip_.A1 + slip_.A2);
    const double e = efficiency_ * 0.25 * pi * cv_;
    const double c2 = e * a_ * a_ * a_ * a_;
    const double c1 = e * a_ * a_ * a_ * Abar;
    terms_ = {{c2, x4, one},      {c2, one, x4},      {2.0 * c2, x3, x1},
              {2.0 * c2, x1, x3}, {2.0 * c2, x2, x2}, {c1, x3, one},
              {c1, one, x3},      {3.0 * c1, x2, x1}, {3.0 * c1, x1, x2}};
}

double GravitationalSettlingKernel::settlingVelocity(double mass) const
{
    return velocityOfDiameter(a_ * cubeRoot(mass));
}

double GravitationalSettlingKernel::velocityOfDiameter(double d) const
{
    return cv_ * d * d * slip_(2.0 * lambda_ / d);
}

double GravitationalSettlingKernel::operator()(const ParticleType& a,
                                               const ParticleType& b) const
{
    // one cube root a particle
    const double da = a_ * cubeRoot(a.mass), db = a_ * cubeRoot(b.mass);
    const double d = da + db;
    return efficiency_ * 0.25 * constants::pi * d * d
           * std::fabs(velocityOfDiameter(da) - velocityOfDiameter(db));
}

void GravitationalSettlingKernel::basis(const ParticleType& z, double* phi) const
{
    const double x = cubeRoot(z.mass);
    phi[one] = 1.0;
    phi[x1] = x;
    phi[x2] = x * x;
    phi[x3] = z.mass;
    phi[x4] = x * x * x * x;
}

} // namespace coag
