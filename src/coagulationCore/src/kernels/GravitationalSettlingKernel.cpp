// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/kernels/GravitationalSettlingKernel.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace coag {

namespace {

// The basis phi_b(m) of the majorant: powers of x = m^(1/3)
enum Basis { one, x1, x2, x3, x4 };

void requirePositive(const char* what, double v)
{
    if (!(v > 0.0) || !std::isfinite(v)) {
        std::ostringstream os;
        os << "coag::GravitationalSettlingKernel: " << what
           << " must be positive and finite, got " << v;
        throw std::invalid_argument(os.str());
    }
}

} // namespace

GravitationalSettlingKernel::GravitationalSettlingKernel(const GasState& gas,
                                                         const ParticleMaterial& material,
                                                         double efficiency, double g)
    : gas_(gas), material_(material), efficiency_(efficiency), g_(g)
{
    gas_.check();
    material_.check();
    requirePositive("the collision efficiency E", efficiency_);
    requirePositive("the gravitational acceleration g [m/s2]", g_);
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
    const double d = a_ * std::cbrt(mass);
    return cv_ * d * d * slip_(2.0 * lambda_ / d);
}

double GravitationalSettlingKernel::operator()(const ParticleType& a,
                                               const ParticleType& b) const
{
    const double d = a_ * (std::cbrt(a.mass) + std::cbrt(b.mass));
    return efficiency_ * 0.25 * constants::pi * d * d
           * std::fabs(settlingVelocity(a.mass) - settlingVelocity(b.mass));
}

void GravitationalSettlingKernel::basis(const ParticleType& z, double* phi) const
{
    const double x = std::cbrt(z.mass);
    phi[one] = 1.0;
    phi[x1] = x;
    phi[x2] = x * x;
    phi[x3] = z.mass;
    phi[x4] = x * x * x * x;
}

} // namespace coag
