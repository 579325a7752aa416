// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/kernels/BrownianKernel.hpp"
#include "coagulation/kernels/CubeRoot.hpp"

#include <cmath>
#include <stdexcept>

namespace coag {

namespace {

// The basis phi_b(m) of the majorants (BrownianKernel.hpp), x = m^(1/3): 1, x, x^2, x^(1/2),
// x^(-3/2), the slip bound s = 1 + b/x and s/x
enum Basis { one, third, twoThirds, sixth, minusHalf, slip, slipOverX };

} // namespace

std::string brownianRegimeName(BrownianRegime regime)
{
    switch (regime) {
    case BrownianRegime::freeMolecular: return "freeMolecular";
    case BrownianRegime::continuum: return "continuum";
    case BrownianRegime::transition: return "transition";
    }
    return "transition";
}

BrownianRegime parseBrownianRegime(const std::string& name)
{
    for (BrownianRegime r :
         {BrownianRegime::freeMolecular, BrownianRegime::continuum, BrownianRegime::transition}) {
        if (brownianRegimeName(r) == name) return r;
    }
    throw std::invalid_argument("coag::parseBrownianRegime: unknown regime '" + name
                                + "'; valid regimes are freeMolecular continuum transition");
}

BrownianKernel::BrownianKernel(BrownianRegime regime, const GasState& gas,
                               const ParticleMaterial& material)
    : regime_(regime), gas_(gas), material_(material)
{
    gas_.check();
    material_.check();
    using namespace constants;
    kT_ = boltzmann * gas_.T;
    lambda_ = gas_.meanFreePath();
    a_ = material_.diameter(1.0);
    speed1_ = std::sqrt(8.0 * kT_ / (pi * material_.massUnit));
    knudsen1_ = 2.0 * lambda_ / a_;
    diffusivity1_ = kT_ / (3.0 * pi * gas_.mu * a_);
    freeMolecular1_ = 0.25 * pi * a_ * a_ * speed1_;
    continuum1_ = 2.0 * kT_ / (3.0 * gas_.mu);

    // (2kT/3mu)(si/xi + sj/xj)(xi + xj), d = a x, x = m^(1/3), s = 1 + b/x >= C
    const double cc = continuum1_;
    slipBound1_ = 2.0 * lambda_ * (slip_.A1 + slip_.A2) / a_;
    const std::vector<MajorantTerm> continuumTerms{
        {cc, slip, one},  {cc, one, slip},  {cc, slipOverX, third},  {cc, third, slipOverX}};
    // freeMolecularFactor (xi^2 + xj^2)(mi^(-1/2) + mj^(-1/2)) (pi/4) a^2 sqrt(8kT/pi)
    const double cf = freeMolecularFactor * freeMolecular1_;
    const std::vector<MajorantTerm> freeMolecularTerms{
        {cf, sixth, one},  {cf, one, sixth},  {cf, twoThirds, minusHalf},  {cf, minusHalf, twoThirds}};

    switch (regime_) {
    case BrownianRegime::freeMolecular: terms_ = freeMolecularTerms; break;
    case BrownianRegime::continuum: terms_ = continuumTerms; break;
    case BrownianRegime::transition:
        // Both, as two groups: the sampler takes the one of the lesser sum
        terms_ = freeMolecularTerms;
        for (MajorantTerm t : continuumTerms) {
            t.coeff *= transitionContinuumMargin;
            t.group = 1;
            terms_.push_back(t);
        }
        break;
    }
}

BrownianKernel::Single BrownianKernel::single(double mass) const
{
    Single s;
    const double x = cubeRoot(mass);
    s.d = a_ * x;
    s.c = speed1_ / std::sqrt(mass);
    s.C = slip_(knudsen1_ / x);
    s.D = diffusivity1_ * s.C / x;
    return s;
}

// Each regime computes only what its formula needs: the free-molecular kernel has no slip
// correction, the continuum one no thermal speed

double BrownianKernel::freeMolecular(const ParticleType& a, const ParticleType& b) const
{
    // (pi/4)(di + dj)^2 sqrt(ci^2 + cj^2) with c^2 = speed1^2 / m
    const double x = cubeRoot(a.mass) + cubeRoot(b.mass);
    return freeMolecular1_ * x * x * std::sqrt(1.0 / a.mass + 1.0 / b.mass);
}

double BrownianKernel::continuum(const ParticleType& a, const ParticleType& b) const
{
    // 2 pi (Di + Dj)(di + dj) = (2kT/3mu)(Ci/xi + Cj/xj)(xi + xj)
    const double xi = cubeRoot(a.mass), xj = cubeRoot(b.mass);
    return continuum1_ * (slip_(knudsen1_ / xi) / xi + slip_(knudsen1_ / xj) / xj) * (xi + xj);
}

double BrownianKernel::transition(const ParticleType& a, const ParticleType& b) const
{
    using constants::pi;
    const Single i = single(a.mass), j = single(b.mass);
    auto g = [](const Single& s) {
        const double l = 8.0 * s.D / (pi * s.c);
        const double dl = s.d + l;
        const double q = s.d * s.d + l * l;
        return (dl * dl * dl - q * std::sqrt(q)) / (3.0 * s.d * l) - s.d;
    };
    const double gi = g(i), gj = g(j);
    const double d = i.d + j.d, D = i.D + j.D;
    const double F = d / (d + 2.0 * std::sqrt(gi * gi + gj * gj))
                     + 8.0 * D / (std::sqrt(i.c * i.c + j.c * j.c) * d);
    return 2.0 * pi * D * d / F;
}

double BrownianKernel::operator()(const ParticleType& a, const ParticleType& b) const
{
    switch (regime_) {
    case BrownianRegime::freeMolecular: return freeMolecular(a, b);
    case BrownianRegime::continuum: return continuum(a, b);
    case BrownianRegime::transition: return transition(a, b);
    }
    return transition(a, b);
}

void BrownianKernel::basis(const ParticleType& z, double* phi) const
{
    const double x = cubeRoot(z.mass);
    const double r = std::sqrt(x);
    const double s = 1.0 + slipBound1_ / x;
    phi[one] = 1.0;
    phi[third] = x;
    phi[twoThirds] = x * x;
    phi[sixth] = r;
    phi[minusHalf] = 1.0 / (r * x);
    phi[slip] = s;
    phi[slipOverX] = s / x;
}

} // namespace coag
